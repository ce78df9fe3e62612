#include "view/status_text.hpp"

#include <fmt/format.h>

#include "render/adaptive_render.hpp"
#include "view/camera_text.hpp"

namespace lancer::view {
namespace {

double mrays_per_s(double rays, double ms) { return ms > 0.0 ? rays / ms / 1e3 : 0.0; }

std::string adaptive_summary(const ShownFrame& f) {
    return camera_rays_summary(f.samples, static_cast<long long>(f.width) * f.height, f.refined_pixels, f.camera_rays);
}

}  // namespace

std::string window_title(const std::string& scene_name, const ShownFrame& f) {
    const dvec3& e = f.camera.eye;
    std::string where = fmt::format("lancer view | {} | eye ({:.2f}, {:.2f}, {:.2f})", scene_name, e.x, e.y, e.z);
    const unsigned total = unsigned(f.samples * f.samples);
    if (f.refined_pixels >= 0 && (f.kind == ShownFrame::Kind::Pass || f.kind == ShownFrame::Kind::Final))
        return fmt::format("{} | adaptive{} {}/{}: {} | {:.0f} ms | {:.1f} Mrays/s", where,
                           f.kind == ShownFrame::Kind::Final ? ", done at step" : " step", f.pass, f.passes,
                           adaptive_summary(f), f.view_ms, mrays_per_s(f.view_rays, f.view_ms));
    switch (f.kind) {
        case ShownFrame::Kind::Preview:
            return fmt::format("{} | preview 1/{} size: {:.0f} ms | {:.1f} Mrays/s", where, f.preview_divisor,
                               f.render_ms, mrays_per_s(f.rays, f.render_ms));
        case ShownFrame::Kind::Pass:
            return fmt::format("{} | refining {}/{} samples: {:.0f} ms | {:.1f} Mrays/s", where, f.samples_done, total,
                               f.view_ms, mrays_per_s(f.view_rays, f.view_ms));
        case ShownFrame::Kind::Final:
            return fmt::format("{} | {}/{} samples in {:.0f} ms | {:.1f} Mrays/s", where, f.samples_done, total,
                               f.view_ms, mrays_per_s(f.view_rays, f.view_ms));
        case ShownFrame::Kind::Recording:
            return fmt::format("lancer view | {} | {} ({:.0f} ms/frame, {:.1f} Mrays/s; f or l stops)", scene_name, f.status,
                               f.render_ms, mrays_per_s(f.rays, f.render_ms));
    }
    return where;
}

std::string refined_line(const ShownFrame& f) {
    if (f.refined_pixels >= 0)
        return fmt::format("view: refined {}x{}, {} in {:.3f} s ({} steps, {:.2f} Mrays/s); camera: {}", f.width, f.height,
                           adaptive_summary(f), f.view_ms / 1000.0, f.passes, mrays_per_s(f.view_rays, f.view_ms),
                           camera_toml(f.camera));
    return fmt::format("view: refined {}x{}, {} rays/pixel in {:.3f} s ({} passes, {:.2f} Mrays/s); camera: {}", f.width,
                       f.height, f.samples * f.samples, f.view_ms / 1000.0, f.passes,
                       mrays_per_s(f.view_rays, f.view_ms), camera_toml(f.camera));
}

}  // namespace lancer::view
