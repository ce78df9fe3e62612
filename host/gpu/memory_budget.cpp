#include "gpu/memory_budget.hpp"

#include <set>

#include <fmt/format.h>

#include "core/error.hpp"
#include "core/perlin_permutation.hpp"
#include "gpu/layout.hpp"

namespace lancer::gpu {

std::vector<BufferNeed> scene_buffer_needs(const Scene& scene, std::uint64_t output_bytes) {
    std::uint64_t primitives = 0, bounded = 0, leaves = 0, surfaces = 0, cells = 0;
    for (const Object& o : scene.objects) {
        if (const auto* b = std::get_if<BezierSurface>(&o.shape)) {
            std::uint64_t n = std::uint64_t(b->patches.size()) << (2 * b->subdivision);  // 4^s leaves per patch
            leaves += n;
            primitives += n;
            bounded += n;
        } else if (const auto* p = std::get_if<ParametricObject>(&o.shape)) {
            ++surfaces;
            cells += p->cells.size();
            primitives += p->cells.size();
            bounded += p->cells.size();
        } else {
            surfaces += std::holds_alternative<ImplicitObject>(o.shape);
            ++primitives;
            bounded += !std::holds_alternative<Plane>(o.shape);
        }
    }
    // Textures: each image once, however many materials use it; patterns: colour and bump.
    std::uint64_t texture_maps = 0, texels = 0, patterns = 0;
    std::set<const TextureImage*> images;
    for (const lancer::Material& m : scene.materials) {
        if (m.texture) {
            ++texture_maps;
            if (images.insert(m.texture->image.get()).second) texels += m.texture->image->rgba.size() / 4;
        }
        patterns += m.pattern.has_value() + m.bump.has_value();
    }
    auto need = [](const char* what, std::uint64_t count, std::uint64_t size) {
        return BufferNeed{what, count, count * size};
    };
    return {need("primitives", primitives, sizeof(Primitive)),
            need("BVH nodes", bounded ? 2 * bounded - 1 : 0, sizeof(BvhNode)),
            need("Bezier patch leaves", leaves, sizeof(PatchLeaf)),
            need("parametric surfaces", surfaces, sizeof(SurfaceInfo)),
            need("parametric cells", cells, sizeof(ParametricCell)),
            need("materials", scene.materials.size(), sizeof(Material)),
            need("lights", scene.lights.size(), sizeof(Light)),
            need("textures", texture_maps, sizeof(TextureInfo)),
            need("texture texels", texels, sizeof(uint)),
            need("patterns", patterns, sizeof(PatternInfo)),
            need("noise permutation", patterns ? kPerlinPermutation.size() : 0, sizeof(int)),
            {"output rows", output_bytes / sizeof(vec4), output_bytes}};
}

std::string format_bytes(std::uint64_t bytes) {
    constexpr double kMiB = 1024.0 * 1024.0, kGiB = kMiB * 1024.0;
    if (bytes >= std::uint64_t(kGiB)) return fmt::format("{:.1f} GiB", bytes / kGiB);
    if (bytes >= std::uint64_t(kMiB)) return fmt::format("{:.0f} MiB", bytes / kMiB);
    return fmt::format("{} bytes", bytes);
}

void check_memory_budget(const std::vector<BufferNeed>& needs, const DeviceMemoryLimits& limits) {
    std::uint64_t total = 0;
    for (const BufferNeed& n : needs) {
        if (n.bytes > limits.max_buffer_bytes)
            throw UserError(fmt::format(
                "the scene needs {} of GPU memory for its {} ({} of them), more than {} allows in one buffer ({}, "
                "maxStorageBufferRange); use fewer or simpler objects (a lower subdivision for Bezier patches), or "
                "render with --backend cpu",
                format_bytes(n.bytes), n.what, n.count, limits.device, format_bytes(limits.max_buffer_bytes)));
        total += n.bytes;
    }
    if (total > limits.heap_bytes)
        throw UserError(fmt::format("the scene needs {} of GPU memory in all, more than {} has ({} in its memory heap); "
                                    "use fewer or simpler objects, or render with --backend cpu",
                                    format_bytes(total), limits.device, format_bytes(limits.heap_bytes)));
}

}  // namespace lancer::gpu
