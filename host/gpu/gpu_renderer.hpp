#pragma once
// The Vulkan compute backend. Device, pipeline and buffers live as long as the renderer, so a
// sequence of renders (animation frames) pays the start-up cost once.
#include <cstddef>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <vector>

#include "accel/bvh.hpp"
#include "gpu/vulkan/context.hpp"
#include "gpu/layout.hpp"
#include "gpu/passes/photon_pass.hpp"
#include "gpu/vulkan/pipeline.hpp"
#include "gpu/vulkan/submit.hpp"
#include "gpu/passes/refine_selection.hpp"
#include "gpu/packing/scene_packing.hpp"
#include "gpu/shaders/embedded_shaders.hpp"
#include "gpu/shaders/shader_compiler.hpp"
#include "gpu/trace_resources.hpp"
#include "render/adaptive_render.hpp"
#include "render/host_adaptive_picture.hpp"
#include "render/renderer.hpp"

namespace lancer {

namespace gpu {
// Every buffer a render allocates, as each pass states them: the scene's arrays, the output band
// (`output_bytes`) and its list of pixels to refine (at most the band's pixels), photon mapping's
// buffers at the size a pass starts with (a pass that stores more grows them, checked there), and
// adaptive anti-aliasing's picture on the device (`selection_pixels`, 0: none).
std::vector<BufferNeed> render_buffer_needs(const PackedScene& packed, std::uint64_t output_bytes,
                                            std::uint64_t selection_pixels = 0);
}  // namespace gpu

class GpuRenderer final : public Renderer {
public:
    explicit GpuRenderer(const gpu::ContextOptions& options, Acceleration acceleration = Acceleration::Bvh);
    ~GpuRenderer() override;

    std::string description() const override;
    FloatImage render(const Scene& scene, const ProgressFn& progress) override;
    // render(), and with adaptive anti-aliasing the picture after each of its steps to `step`
    // (render/adaptive_render.hpp): the viewer shows them as they come.
    FloatImage render_in_steps(const Scene& scene, const ProgressFn& progress, const AdaptiveStepFn& step);
    FloatImage render_hits(const Scene& scene) override;
    void prepare(const Scene& scene, const ProgressFn& progress) override;
    void expect_one_still() override { one_still_ = true; }
    // After expect_one_still, frees the objects once the scene is packed, where it is packed
    // once for the whole render (no photons, no adaptive steps).
    FloatImage render_once(Scene& scene, const ProgressFn& progress) override;
    std::vector<std::string> notes() const override;
    bool runs_shaders() const override { return true; }
    void use_shader_directory(const std::string& directory) override;

    // Progressive rendering (the viewer): traces samples [first, first + count) of every pixel's
    // N x N grid, continuing `sums`, which holds what the passes before left (ignored, and
    // resized, when first == 0). Between passes its pixels are unnormalised sums (rgb) and ray
    // counts (a); the pass that reaches sample N * N leaves exactly the image render() returns.
    // A cancelled pass (RenderCancelled) leaves `sums` half advanced: start again from 0. With
    // photon mapping, `first` and `count` count passes instead ([photons] passes in all).
    void render_samples(const Scene& scene, std::uint32_t first, std::uint32_t count, FloatImage& sums,
                        const ProgressFn& progress);
    // Caps the camera samples of one dispatch (0: no cap, bands of about 128 K pixels). A cancel
    // waits for the dispatch in flight, so the viewer, which cancels whenever the camera moves,
    // asks for small ones.
    void set_max_dispatch_samples(std::size_t samples) { max_dispatch_samples_ = samples; }

    const gpu::Context& context() const { return *context_; }
    // Whether rays take direction grids (gpu/packing/acceleration_plan.hpp); tests force them
    // on or off to compare the two.
    void set_grid_use(gpu::GridUse use) { grid_use_ = use; }
    // Changes the shader features every render chose (tests: to break a contract on purpose).
    void override_features(std::function<void(gpu::ShaderFeatures&)> change) { override_features_ = std::move(change); }
    // Pipelines built so far, one per set of shader features (for tests: a frame that moves only
    // the camera builds none).
    std::size_t pipelines_built() const { return pipelines_.size(); }

    // Bands rendered again with one sample per invocation because the driver's loop limit cut
    // the first attempt short (lavapipe; see shaders/trace.comp), since this renderer was made.
    std::size_t bands_rerendered() const { return bands_rerendered_; }
    // Scenes packed for the device since this renderer was made (for tests: one per render).
    std::size_t scenes_packed() const { return scenes_packed_; }
    const gpu::UploadStats& last_upload() const { return resources_.last_upload(); }
    std::size_t bvh_builds() const { return bvh_cache_.builds(); }  // trees built so far (for tests)
    std::size_t element_tree_builds() const { return element_trees_.builds(); }  // meshes' and sphere sets' (for tests)
    // Choices of pixels to refine (adaptive anti-aliasing) made on the device so far (for tests).
    std::size_t device_selections() const { return device_selections_; }
    // Adaptive renders choose their pixels on the host, as where the device cannot hold the
    // picture (for tests of that way).
    void choose_on_host(bool on_host) { choose_on_host_ = on_host; }

    // Rebuilds the tracer from GLSL sources at run time (same entry point, same defines as the
    // embedded SPIR-V): the hot-reload path. Throws ShaderCompileError and keeps the current
    // pipelines if they do not compile; on success the next render uses the new code.
    // `display_root` prefixes file names in compiler messages (the watched directory).
    void use_shaders(const gpu::ShaderTree& tree, const std::string& display_root = "");

private:
    // Packs the scene within the device's limits and uploads it; returns the pipeline's features
    // (pipeline_features), having started that pipeline's build as soon as the packing knew them.
    // `compile_bytes`: the pipeline's compile, from the objects before they are packed (and
    // maybe freed: render_once).
    gpu::ShaderFeatures upload_scene(const Scene& scene, std::uint64_t output_bytes, bool output_hits,
                                     std::uint64_t compile_bytes);
    // What upload_scene does with a packed scene before its upload: checks that it fits, keeps
    // its notes and emitters.
    void admit_packed(const Scene& scene, const gpu::PackedScene& packed, std::uint64_t output_bytes,
                      const gpu::DeviceMemoryLimits& limits, std::uint64_t compile_bytes);
    // A packed scene's features with what the device and the render add to them.
    gpu::ShaderFeatures pipeline_features(gpu::ShaderFeatures packed, bool output_hits) const;
    // Makes spirv_ the tracer built from base_tree_ with `generated` in place of the files of
    // the same names, compiling only when that changed; with `photons`, photon_spirv_ the
    // photon pass built the same way.
    void ensure_program(const gpu::ShaderFiles& generated, bool photons = false);
    // Makes pipeline_ the one for `features`, building it first if needed (on a thread of its
    // own: `progress` can cancel the wait, RenderCancelled, and the build goes on for later).
    void select_pipeline(const gpu::ShaderFeatures& features, const ProgressFn& progress);
    // `spirv`, the program ensure_program made for `entry`, or where that is the embedded one,
    // the embedded build that serves `features` (gpu::embedded_module).
    gpu::EmbeddedModule program(const char* entry, const std::vector<std::uint32_t>& spirv,
                                const gpu::ShaderFeatures& features) const;
    // Starts building the pipeline for `features` on its own thread where none is built or
    // building, for select_pipeline to pick up: the photon pass runs meanwhile.
    gpu::PipelineBuild& start_pipeline(const gpu::ShaderFeatures& features);
    struct SampleRange {
        std::uint32_t first, count;
    };
    // Renders `samples` of every pixel into `image`, which holds the sums so far when first > 0.
    // With photon mapping, `photon_pass` is the pass: its photons are shot and sorted first,
    // and the tracer takes that pass's one camera sample per pixel (samples.first is the pass's
    // place in the render, for continuing the sums).
    void render_with(const Scene& scene, bool output_hits, SampleRange samples, FloatImage& image,
                     const ProgressFn& progress, int photon_pass = -1);
    // Photon mapping: passes [first, last) of the scene's render into `sums` (which holds the
    // passes before `first`); the render's last pass leaves the mean of all of them.
    void render_passes(const Scene& scene, int first, int last, FloatImage& sums, const ProgressFn& progress);
    // Adaptive anti-aliasing with its picture on the device (gpu/passes/refine_selection.hpp).
    class DevicePicture;
    gpu::RefineSelection& selection();
    // The full grid of each pixel in `pixels` (y * width + x), in that order, and with `spread`
    // its samples' extremes: bands of the compact list, every lane with a pixel
    // (BandParams::refine_count). Where the host chooses the pixels.
    std::vector<ListedPixel> render_list(const Scene& scene, const std::vector<std::uint32_t>& pixels, bool spread,
                                         const ProgressFn& progress);
    // The same for the `count` pixels the device listed in refine_list, each band merged into the
    // device's picture once traced.
    void render_device_list(const Scene& scene, std::uint32_t count, bool spread, const ProgressFn& progress);
    // Rows per band for dispatches of `samples_per_dispatch` samples per pixel.
    std::size_t band_rows(const RenderSettings& rs, std::uint32_t samples_per_dispatch) const;
    // Uploads the scene, selects its pipeline (and runs a photon pass when `photon_pass` >= 0)
    // and sizes the output for bands of `rows` rows.
    gpu::ShaderFeatures prepare_band_output(const Scene& scene, bool output_hits, std::size_t rows,
                                            const ProgressFn& progress, int photon_pass = -1);
    // Traces one band (`entries` output pixels) into the output buffer, which first gets
    // `sums_before` when the band continues earlier passes; again one sample per pass where the
    // driver's loop limit cut it short (lavapipe; see shaders/trace.comp).
    void dispatch_checked(const gpu::BandParams& params, std::uint32_t width, std::size_t entries,
                          const glm::vec4* sums_before, bool check_loop_limit, double done, const ProgressFn& progress);
    // Renders band.sample_count samples from band.sample_first into output_, `per_pass` of them
    // per invocation (one dispatch per pass).
    void dispatch_band(const gpu::BandParams& band, std::uint32_t per_pass, std::uint32_t width, double done,
                       const ProgressFn& progress);

    // Shared with pipeline builds still running (gpu::PipelineBuild).
    std::shared_ptr<gpu::Context> context_;
    std::shared_ptr<gpu::TraceLayout> layout_;
    gpu::Submission submission_;  // the bands' dispatches
    // Where the tracer's sources come from, the generated surface code compiled in, its SPIR-V,
    // and the pipelines built from that so far, one per variant used.
    gpu::ShaderTree base_tree_;
    bool base_is_embedded_ = true;
    std::string display_root_;
    gpu::ShaderFiles generated_;  // code generated for the current scene, by file name
    std::vector<std::uint32_t> spirv_;
    std::vector<std::uint32_t> photon_spirv_;  // the photon pass, when a scene has needed it
    std::map<gpu::ShaderFeatures, std::unique_ptr<gpu::PipelineBuild>> pipelines_;
    gpu::ComputePipeline* pipeline_ = nullptr;  // the one for the current render
    gpu::TraceResources resources_;
    std::unique_ptr<gpu::PhotonPass> photons_;
    std::vector<gpu::Emitter> emitters_;  // the last uploaded scene's, for the photon pass
    std::vector<std::string> float_notes_;  // the last uploaded scene's objects float cannot resolve
    Acceleration acceleration_;
    gpu::GridUse grid_use_ = gpu::GridUse::Auto;
    // Under the validation layer (tests), a ray that breaks the grids' contract fails the render
    // (shaders/scene.glsl, grid_contract_broken) instead of reading past the grids.
    bool check_grid_contract_ = false;
    std::function<void(gpu::ShaderFeatures&)> override_features_;
    BvhCache bvh_cache_;  // frames of an animation with static geometry share one tree
    ElementTreeCache element_trees_;  // each mesh's and sphere set's tree, built once for every frame
    bool one_still_ = false;  // expect_one_still(): no tree cached, and a one-step render's upload frees the host's arrays
    std::vector<Object>* release_objects_ = nullptr;  // render_once's scene's objects, while it runs
    std::size_t bands_rerendered_ = 0;
    // Within one render_in_steps(): the scene as packed by its first upload, for the others.
    bool packing_once_ = false;
    bool upload_once_ = false;  // a still of one step (no photons, no adaptive steps): uploaded once, nothing kept
    std::size_t scenes_packed_ = 0;
    std::shared_ptr<const gpu::PackedScene> packed_;  // also what resources_ compares the next upload against
    std::size_t max_dispatch_samples_ = 0;
    std::unique_ptr<gpu::RefineSelection> selection_;  // made by the first adaptive render
    // Within an adaptive render choosing on the device: its picture's pixels, which the memory
    // budget counts the selection's buffers for.
    std::uint64_t selection_pixels_ = 0;
    std::size_t device_selections_ = 0;
    bool choose_on_host_ = false;
};

}  // namespace lancer
