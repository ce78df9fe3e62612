#include "gpu/gpu_renderer.hpp"

#include <algorithm>
#include <cstring>
#include <stdexcept>

#include <fmt/format.h>

#include "core/cancel.hpp"
#include "gpu/vulkan/driver_memory.hpp"
#include "gpu/vulkan/driver_quirks.hpp"
#include "gpu/shaders/embedded_shaders.hpp"
#include "gpu/layout.hpp"
#include "gpu/packing/scene_packing.hpp"
#include "gpu/vulkan/submit.hpp"
#include "gpu/shaders/spirv_cache.hpp"
#include "gpu/shaders/surface_codegen.hpp"
#include "gpu/tile_order.hpp"
#include "gpu/vulkan/vk_check.hpp"
#include "render/adaptive_render.hpp"

namespace lancer {
namespace {

// Rows per dispatch: about this many pixels, so progress is reported often and no dispatch runs
// for minutes, while keeping the per-submit cost (~0.2 ms on lavapipe) negligible.
constexpr std::size_t kBandPixels = 128 * 1024;

}  // namespace

// The passes of render/adaptive_render.hpp with the picture on the device: the first picture
// goes there, each choice is made there (its count comes back), each refining band is merged
// there, and the host reads the picture when it shows or returns it.
class GpuRenderer::DevicePicture final : public AdaptivePicture {
public:
    DevicePicture(GpuRenderer& renderer, std::uint64_t pixels) : renderer_(renderer) {
        renderer_.selection_pixels_ = pixels;
    }
    ~DevicePicture() override { renderer_.selection_pixels_ = 0; }
    DevicePicture(const DevicePicture&) = delete;
    DevicePicture& operator=(const DevicePicture&) = delete;

    void render_first(const Scene& one_ray, const ProgressFn& progress) override {
        FloatImage first;
        renderer_.render_with(one_ray, false, {0, 1}, first, progress);
        renderer_.selection().start(first, renderer_.resources_);
    }
    std::size_t choose(double threshold, bool by_spread) override {
        ++renderer_.device_selections_;
        chosen_ = renderer_.selection().choose(threshold, by_spread, renderer_.resources_, {}, 0.0);
        return chosen_;
    }
    void refine(const Scene& grid, bool keep_spread, const ProgressFn& progress) override {
        renderer_.render_device_list(grid, chosen_, keep_spread, progress);
    }
    FloatImage picture() override { return renderer_.selection().picture(renderer_.resources_); }

private:
    GpuRenderer& renderer_;
    std::uint32_t chosen_ = 0;
};

namespace {

// Runs before the context is made: under a memory limit too small for the driver, a clear error
// rather than a crash inside it.
std::shared_ptr<gpu::Context> make_context(const gpu::ContextOptions& options) {
    gpu::check_driver_startup_memory();
    return std::make_shared<gpu::Context>(options);
}

}  // namespace

std::vector<gpu::BufferNeed> gpu::render_buffer_needs(const PackedScene& packed, std::uint64_t output_bytes,
                                                      std::uint64_t selection_pixels) {
    std::vector<gpu::BufferNeed> needs = gpu::scene_buffer_needs(packed);
    const std::uint64_t band_pixels = output_bytes / sizeof(gpu::vec4);
    needs.push_back(gpu::resource_need(gpu::BINDING_OUTPUT, band_pixels));
    needs.push_back(gpu::resource_need(gpu::BINDING_REFINE, band_pixels));
    auto add = [&](const std::vector<gpu::BufferNeed>& more) { needs.insert(needs.end(), more.begin(), more.end()); };
    if (packed.features.has_photons) add(gpu::PhotonPass::buffer_needs(gpu::photon_capacity(packed.photon_count)));
    if (selection_pixels) add(gpu::RefineSelection::buffer_needs(selection_pixels));
    return needs;
}

GpuRenderer::GpuRenderer(const gpu::ContextOptions& options, Acceleration acceleration)
    : context_(make_context(options)),
      layout_(std::make_shared<gpu::TraceLayout>(*context_)),
      submission_(*context_, "band"),
      base_tree_(gpu::embedded_tree()),
      spirv_(gpu::embedded_trace_spirv()),
      resources_(*context_, layout_->set_layout()),
      photons_(std::make_unique<gpu::PhotonPass>(*context_, *layout_)),
      acceleration_(acceleration),
      check_grid_contract_(options.validation) {}

GpuRenderer::~GpuRenderer() {
    vkDeviceWaitIdle(context_->device());
    photons_.reset();
    selection_.reset();
    pipelines_.clear();
}

void GpuRenderer::use_shaders(const gpu::ShaderTree& tree, const std::string& display_root) {
    std::vector<std::uint32_t> spirv =
        gpu::compile_compute(gpu::with_files(tree, generated_), gpu::kTraceShader, {}, display_root);
    // Prove the new code builds before dropping the old pipelines (the plain variant is cheap).
    auto probe = std::make_unique<gpu::PipelineBuild>(
        context_, layout_, spirv, gpu::ShaderFeatures{}, gpu::spirv_cleanup_for(gpu::ShaderFeatures{}));
    if (!probe->wait([] { return !cancellation_requested(); })) throw Cancelled();
    VK_CHECK(vkDeviceWaitIdle(context_->device()));  // old pipelines may still be in use
    pipelines_.clear();
    pipelines_[gpu::ShaderFeatures{}] = std::move(probe);
    spirv_ = std::move(spirv);
    photon_spirv_.clear();  // built again from the new sources when a scene needs it
    base_tree_ = tree;
    base_is_embedded_ = false;
    display_root_ = display_root;
}

void GpuRenderer::use_shader_directory(const std::string& directory) {
    use_shaders(gpu::directory_tree(directory), directory);
}

std::vector<std::string> GpuRenderer::notes() const {
    std::vector<std::string> notes = float_notes_;
    if (bands_rerendered_)
        notes.push_back(fmt::format("{} band(s) rendered again with one sample per shader invocation: the driver limits "
                                    "loop iterations per invocation (lavapipe)",
                                    bands_rerendered_));
    return notes;
}

void GpuRenderer::ensure_program(const gpu::ShaderFiles& generated, bool photons) {
    auto build = [&](const char* entry) {
        return generated.empty() && base_is_embedded_
                   ? gpu::embedded_spirv(entry)
                   : gpu::cached_compile(base_tree_, generated, entry, {}, display_root_);
    };
    if (generated != generated_) {
        std::vector<std::uint32_t> spirv = build(gpu::kTraceShader);
        VK_CHECK(vkDeviceWaitIdle(context_->device()));
        pipelines_.clear();
        spirv_ = std::move(spirv);
        photon_spirv_.clear();
        generated_ = generated;
    }
    // The photon pass traces the same surfaces, with the same generated code.
    if (photons && photon_spirv_.empty()) photon_spirv_ = build(gpu::kPhotonShader);
}

gpu::EmbeddedModule GpuRenderer::program(const char* entry, const std::vector<std::uint32_t>& spirv,
                                         const gpu::ShaderFeatures& features) const {
    // A scene of fewer shape types starts from the embedded build for them alone.
    if (generated_.empty() && base_is_embedded_) return gpu::embedded_module(entry, features);
    return {spirv, false};
}

gpu::PipelineBuild& GpuRenderer::start_pipeline(const gpu::ShaderFeatures& features) {
    auto& slot = pipelines_[features];
    if (!slot) {
        gpu::EmbeddedModule tracer = program(gpu::kTraceShader, spirv_, features);
        const gpu::SpirvCleanup cleanup = gpu::spirv_cleanup_for(features, tracer.locals_in_ssa);
        slot = std::make_unique<gpu::PipelineBuild>(context_, layout_, std::move(tracer.spirv), features, cleanup);
    }
    return *slot;
}

void GpuRenderer::select_pipeline(const gpu::ShaderFeatures& features, const ProgressFn& progress) {
    pipeline_ = start_pipeline(features).wait([&] { return !progress || progress(0.0); });
    if (!pipeline_) throw RenderCancelled();
}

std::string GpuRenderer::description() const {
    const gpu::DeviceInfo& info = context_->info();
    return "gpu: " + info.name + " (" + info.type + ", " + info.driver + ")";
}

gpu::ShaderFeatures GpuRenderer::upload_scene(const Scene& scene, std::uint64_t output_bytes, bool output_hits,
                                              std::uint64_t compile_bytes) {
    const gpu::DeviceMemoryLimits limits = gpu::buffer_memory_limits(*context_);
    // A still's trees are built once: no cache.
    BvhCache* cache = one_still_ ? nullptr : &bvh_cache_;
    ElementTreeCache* trees = one_still_ ? nullptr : &element_trees_;
    // The pipeline builds on another core while the packer builds the meshes' trees.
    gpu::PackOptions options{acceleration_, grid_use_, cache, trees, &limits,
                             [&](const gpu::ShaderFeatures& f) { start_pipeline(pipeline_features(f, output_hits)); }};
    if (upload_once_) {
        // Packed once for the whole render: render_once's objects can go as they are packed.
        options.release_objects = release_objects_;
        gpu::PackedScene packed = gpu::pack_scene(scene, options);
        ++scenes_packed_;
        admit_packed(scene, packed, output_bytes, limits, compile_bytes);
        const gpu::ShaderFeatures features = pipeline_features(packed.features, output_hits);
        resources_.upload_releasing(packed, gpu::pack_frame(scene, packed));
        return features;
    }
    std::shared_ptr<const gpu::PackedScene> fresh;
    if (!packing_once_ || !packed_) {
        (packing_once_ ? packed_ : fresh) = std::make_shared<const gpu::PackedScene>(gpu::pack_scene(scene, options));
        ++scenes_packed_;
    }
    const std::shared_ptr<const gpu::PackedScene>& shared = fresh ? fresh : packed_;
    admit_packed(scene, *shared, output_bytes, limits, compile_bytes);
    resources_.upload(shared, gpu::pack_frame(scene, *shared));
    return pipeline_features(shared->features, output_hits);
}

gpu::ShaderFeatures GpuRenderer::pipeline_features(gpu::ShaderFeatures f, bool output_hits) const {
    f.check_loop_limit = gpu::limits_loop_iterations(context_->info());
    f.check_grid_contract = check_grid_contract_;
    if (override_features_) override_features_(f);
    f.output_hits = output_hits;
    return f;
}

void GpuRenderer::admit_packed(const Scene& scene, const gpu::PackedScene& packed, std::uint64_t output_bytes,
                               const gpu::DeviceMemoryLimits& limits, std::uint64_t compile_bytes) {
    std::vector<gpu::BufferNeed> needs = gpu::render_buffer_needs(packed, output_bytes, selection_pixels_);
    gpu::check_memory_budget(needs, limits);
    std::uint64_t buffer_bytes = 0;
    for (const gpu::BufferNeed& need : needs) buffer_bytes += need.bytes;
    gpu::check_render_memory(scene.render, buffer_bytes, compile_bytes);
    emitters_ = packed.emitters;
    float_notes_ = packed.float_notes;
}

void GpuRenderer::dispatch_band(const gpu::BandParams& band, std::uint32_t per_pass, std::uint32_t width, double done,
                                const ProgressFn& progress) {
    VkCommandBuffer commands = submission_.begin();
    vkCmdBindPipeline(commands, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline_->handle());
    VkDescriptorSet set = resources_.descriptor_set();
    vkCmdBindDescriptorSets(commands, VK_PIPELINE_BIND_POINT_COMPUTE, layout_->pipeline_layout(), 0, 1, &set, 0,
                            nullptr);
    const std::uint32_t groups_x = (width + gpu::WORKGROUP_X - 1) / gpu::WORKGROUP_X;
    const std::uint32_t groups_y = (band.rows + gpu::WORKGROUP_Y - 1) / gpu::WORKGROUP_Y;
    const std::uint32_t stride = gpu::hands_each_thread_one_run(context_->info()) ? gpu::spread_group_stride(groups_x * groups_y) : 1;
    const std::uint32_t end = band.sample_first + band.sample_count;
    for (std::uint32_t first = band.sample_first; first < end; first += per_pass) {
        if (first > band.sample_first) gpu::compute_barrier(commands);  // the next pass continues the sums this one wrote
        gpu::BandParams pass = band;
        pass.sample_first = first;
        pass.sample_count = std::min(per_pass, end - first);
        pass.group_stride = stride;
        vkCmdPushConstants(commands, layout_->pipeline_layout(), VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof(pass),
                           &pass);
        vkCmdDispatch(commands, groups_x, groups_y, 1);
    }
    // The host reads the mapped output after the fence.
    gpu::compute_barrier(commands, VK_ACCESS_HOST_READ_BIT, VK_PIPELINE_STAGE_HOST_BIT);
    submission_.end_and_wait(progress, done);
}

FloatImage GpuRenderer::render(const Scene& scene, const ProgressFn& progress) { return render_in_steps(scene, progress, {}); }

FloatImage GpuRenderer::render_once(Scene& scene, const ProgressFn& progress) {
    if (one_still_) release_objects_ = &scene.objects;
    struct Forget {
        std::vector<Object>*& objects;
        ~Forget() { objects = nullptr; }
    } forget{release_objects_};
    return render(scene, progress);
}

FloatImage GpuRenderer::render_in_steps(const Scene& scene, const ProgressFn& progress, const AdaptiveStepFn& step) {
    // A render's photon passes and adaptive steps differ only in what pack_frame writes (the
    // pass, the grid), so the scene is packed once for all of them (a parametric surface's
    // cells take 20-120 ms).
    packing_once_ = true;
    upload_once_ = one_still_ && !scene.photons && !scene.render.aa_threshold;
    struct PackedOnce {
        GpuRenderer& renderer;
        ~PackedOnce() {
            renderer.packing_once_ = false;
            renderer.upload_once_ = false;
            renderer.packed_.reset();
        }
    } packed_once{*this};
    FloatImage image;
    if (scene.photons) {
        render_passes(scene, scene.photons->first_pass, scene.photons->last_pass(), image, progress);
        return image;
    }
    auto all = static_cast<std::uint32_t>(scene.render.samples * scene.render.samples);
    if (!scene.render.aa_threshold) {
        render_with(scene, false, {0, all}, image, progress);
        return image;
    }
    // Adaptive: each refinement is dispatched over the compact list of its pixels, which the
    // device makes from the picture it keeps (only the count comes back), unless the picture is
    // too large for its buffers.
    const std::uint64_t pixels = std::uint64_t(scene.render.width) * std::uint64_t(scene.render.height);
    if (!choose_on_host_ && gpu::RefineSelection::fits(pixels, *context_)) {
        DevicePicture picture(*this, pixels);
        return render_adaptive(scene, picture, progress, step);
    }
    HostAdaptivePicture picture(
        [&](const Scene& one_ray, const ProgressFn& p) {
            FloatImage every_pixel;
            render_with(one_ray, false, {0, 1}, every_pixel, p);
            return every_pixel;
        },
        [&](const Scene& grid, const std::vector<std::uint32_t>& listed, bool spread, const ProgressFn& p) {
            return render_list(grid, listed, spread, p);
        });
    return render_adaptive(scene, picture, progress, step);
}

void GpuRenderer::render_passes(const Scene& scene, int first, int last, FloatImage& sums, const ProgressFn& progress) {
    check_photon_lights(scene);
    const PhotonSettings& ps = *scene.photons;
    for (int pass = first; pass < last; ++pass) {
        auto in_pass = [&](double f) { return !progress || progress((pass - ps.first_pass + f) / (ps.last_pass() - ps.first_pass)); };
        render_with(scene, false, {static_cast<std::uint32_t>(pass - ps.first_pass), 1}, sums, in_pass, pass);
    }
}

void GpuRenderer::prepare(const Scene& scene, const ProgressFn& progress) {
    // A 1x1 render of the scene: the same pipeline variant (it depends on the scene's contents,
    // not its size), compiled by the driver at this first dispatch, and the scene's buffers.
    Scene tiny = scene;
    tiny.render.width = tiny.render.height = tiny.render.samples = 1;
    if (tiny.photons) {  // one pass of a few photons compiles the photon pipelines too
        tiny.photons->count = std::min(tiny.photons->count, 64);
        tiny.photons->first_pass = 0;
        tiny.photons->pass_count = 1;
    }
    render(tiny, progress ? [&](double) { return progress(0.0); } : ProgressFn{});
}

FloatImage GpuRenderer::render_hits(const Scene& scene) {
    FloatImage image;
    render_with(scene, true, {0, 1}, image, {});
    return image;
}

void GpuRenderer::render_samples(const Scene& scene, std::uint32_t first, std::uint32_t count, FloatImage& sums,
                                 const ProgressFn& progress) {
    if (scene.photons) {  // the passes of photon mapping play the part of the samples
        const int base = scene.photons->first_pass;
        render_passes(scene, base + int(first), base + int(first + count), sums, progress);
        return;
    }
    render_with(scene, false, {first, count}, sums, progress);
}

std::size_t GpuRenderer::band_rows(const RenderSettings& rs, std::uint32_t samples_per_dispatch) const {
    const std::size_t row_bytes = std::size_t(rs.width) * sizeof(gpu::vec4);
    std::size_t max_rows = std::max<std::size_t>(1, context_->limits().maxStorageBufferRange / row_bytes);
    std::size_t band_pixels = kBandPixels;
    if (max_dispatch_samples_)
        band_pixels = std::min(band_pixels, max_dispatch_samples_ / std::max<std::uint32_t>(1, samples_per_dispatch));
    std::size_t rows = std::clamp<std::size_t>(band_pixels / std::size_t(rs.width), gpu::WORKGROUP_Y, std::size_t(rs.height));
    return std::min(rows, max_rows);
}

gpu::ShaderFeatures GpuRenderer::prepare_band_output(const Scene& scene, bool output_hits, std::size_t rows,
                                                     const ProgressFn& progress, int photon_pass) {
    const std::size_t row_bytes = std::size_t(scene.render.width) * sizeof(gpu::vec4);
    // The program first: its pipeline starts building as soon as the packing knows its features.
    gpu::ShaderFiles generated;
    if (std::string code = gpu::surface_functions_glsl(scene, context_->float64()); !code.empty()) generated["surface_functions.glsl"] = code;
    ensure_program(generated, photon_pass >= 0);
    const gpu::ShaderFeatures features = upload_scene(scene, rows * row_bytes, output_hits, gpu::compile_memory(scene));
    if (photon_pass >= 0) {
        // The pass's photons and their grid first; the tracer gathers from them. Its pipeline
        // builds on another core meanwhile: started where the scene was packed, and here where a
        // packed scene was reused after the programs changed (a no-op otherwise).
        start_pipeline(features);
        photons_->use_programs(program(gpu::kPhotonShader, photon_spirv_, features).spirv,
                               gpu::embedded_spirv(gpu::kGridShader));
        photons_->run(scene, photon_pass, features, emitters_, resources_, progress, 0.0);
    }
    select_pipeline(features, progress);
    resources_.output(rows * row_bytes);
    return features;
}

void GpuRenderer::dispatch_checked(const gpu::BandParams& params, std::uint32_t width, std::size_t entries,
                                   const glm::vec4* sums_before, bool check_loop_limit, double done,
                                   const ProgressFn& progress) {
    const gpu::Buffer& output = resources_.output(entries * sizeof(gpu::vec4));
    const auto* band = static_cast<const gpu::vec4*>(output.data());
    auto check_grid_contract = [&] {
        if (check_grid_contract_ && std::any_of(band, band + entries, [](const gpu::vec4& p) { return p.a == -3.0f; }))
            throw std::logic_error("a ray without a direction grid met a pipeline without the BVH's traversal (GRIDS_ONLY): "
                                   "the acceleration plan and the shader's rays disagree");
    };
    auto cut_short = [&] {
        return check_loop_limit && std::any_of(band, band + entries, [](const gpu::vec4& p) { return p.a < 0.0f; });
    };
    if (sums_before) std::memcpy(output.data(), sums_before, entries * sizeof(gpu::vec4));
    // All of the range's samples in one invocation is fastest (lavapipe: ~1.5x one per
    // invocation); where the driver's loop limit cut that short, one sample per pass.
    dispatch_band(params, params.sample_count, width, done, progress);
    check_grid_contract();
    if (params.sample_count > 1 && cut_short()) {
        ++bands_rerendered_;
        if (sums_before) std::memcpy(output.data(), sums_before, entries * sizeof(gpu::vec4));  // the sums before this range
        dispatch_band(params, 1, width, done, progress);
    }
    if (cut_short())
        throw UserError(fmt::format(
            "a sample of this scene needs more loop iterations than the {} driver allows in one shader "
            "invocation (65535); render with --backend cpu, or lower max_depth, the number of lights or, with photon "
            "mapping, the photons per pass (--photons)",
            context_->info().name));
}

void GpuRenderer::render_with(const Scene& scene, bool output_hits, SampleRange samples, FloatImage& image,
                              const ProgressFn& progress, int photon_pass) {
    const RenderSettings& rs = scene.render;
    const auto width = static_cast<std::uint32_t>(rs.width);
    const auto height = static_cast<std::uint32_t>(rs.height);
    const bool continues = samples.first > 0;
    if (continues && (image.width != rs.width || image.height != rs.height))
        throw std::logic_error("render_samples: the sums so far are not of the scene's size");

    const std::size_t rows = band_rows(rs, samples.count);
    const gpu::ShaderFeatures features = prepare_band_output(scene, output_hits, rows, progress, photon_pass);
    if (!continues) image = FloatImage(rs.width, rs.height);
    for (std::uint32_t y0 = 0; y0 < height; y0 += static_cast<std::uint32_t>(rows)) {
        auto rows_here = static_cast<std::uint32_t>(std::min<std::size_t>(rows, height - y0));
        glm::vec4* band_start = &image.pixels[std::size_t(y0) * width];
        const std::size_t entries = std::size_t(rows_here) * width;
        const gpu::BandParams params{y0, rows_here, samples.first, samples.count, 0, 0, 0, 0};
        dispatch_checked(params, width, entries, continues ? band_start : nullptr,
                         features.check_loop_limit && !output_hits, double(y0) / height, progress);
        std::memcpy(band_start, resources_.output(0).data(), entries * sizeof(gpu::vec4));
        if (progress && !progress(double(y0 + rows_here) / height)) throw RenderCancelled();
    }
}

gpu::RefineSelection& GpuRenderer::selection() {
    if (!selection_)
        selection_ = std::make_unique<gpu::RefineSelection>(*context_, *layout_, gpu::embedded_spirv(gpu::kSelectShader));
    return *selection_;
}

void GpuRenderer::render_device_list(const Scene& scene, std::uint32_t count, bool spread, const ProgressFn& progress) {
    const RenderSettings& rs = scene.render;
    const auto width = static_cast<std::uint32_t>(rs.width);
    const auto all = static_cast<std::uint32_t>(rs.samples * rs.samples);
    const std::size_t rows = band_rows(rs, all);
    const gpu::ShaderFeatures features = prepare_band_output(scene, false, rows, progress);
    // With the spread, each pixel's colour is followed by its samples' extremes (BandParams):
    // a third as many pixels per band, in the same output buffer.
    const auto per_band = static_cast<std::uint32_t>(std::max<std::size_t>(1, rows * width / (spread ? 3 : 1)));
    for (std::uint32_t first = 0; first < count; first += per_band) {
        const std::uint32_t entries = std::min(per_band, count - first);
        const std::uint32_t rows_here = (entries + width - 1) / width;
        const gpu::BandParams params{0, rows_here, 0, all, entries, spread ? 1u : 0u, first, 0};
        const double done = double(first) / double(count);
        dispatch_checked(params, width, entries, nullptr, features.check_loop_limit, done, progress);
        selection().merge(first, entries, spread, resources_, progress, done);
        if (progress && !progress(double(first + entries) / double(count))) throw RenderCancelled();
    }
}

std::vector<ListedPixel> GpuRenderer::render_list(const Scene& scene, const std::vector<std::uint32_t>& pixels,
                                                  bool spread, const ProgressFn& progress) {
    const RenderSettings& rs = scene.render;
    const auto width = static_cast<std::uint32_t>(rs.width);
    const auto all = static_cast<std::uint32_t>(rs.samples * rs.samples);
    const std::size_t rows = band_rows(rs, all);
    const gpu::ShaderFeatures features = prepare_band_output(scene, false, rows, progress);
    std::vector<ListedPixel> refined(pixels.size());
    // With the spread, each pixel's colour is followed by its samples' extremes (BandParams):
    // a third as many pixels per band, in the same output buffer.
    const std::size_t per_band = std::max<std::size_t>(1, rows * width / (spread ? 3 : 1));
    for (std::size_t first = 0; first < pixels.size(); first += per_band) {
        const std::size_t entries = std::min(per_band, pixels.size() - first);
        const auto rows_here = static_cast<std::uint32_t>((entries + width - 1) / width);
        resources_.write_refine_list(pixels.data() + first, entries);
        const gpu::BandParams params{0, rows_here, 0, all, static_cast<std::uint32_t>(entries), spread ? 1u : 0u, 0, 0};
        const double done = double(first) / double(pixels.size());
        dispatch_checked(params, width, entries, nullptr, features.check_loop_limit, done, progress);
        const auto* out = static_cast<const glm::vec4*>(resources_.output(0).data());
        for (std::size_t i = 0; i < entries; ++i) {
            ListedPixel& p = refined[first + i];
            p.colour = out[i];
            if (spread) {
                p.lo = glm::vec3(out[entries + i]);
                p.hi = glm::vec3(out[2 * entries + i]);
            }
        }
        if (progress && !progress(double(first + entries) / double(pixels.size()))) throw RenderCancelled();
    }
    return refined;
}

}  // namespace lancer
