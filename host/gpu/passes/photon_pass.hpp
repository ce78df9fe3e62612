#pragma once
// Photon mapping's compute passes on the GPU (docs/scene-format.md, "[photons]"): a pass's
// photons shot from the lights (shaders/photons.comp), then sorted into the hashed grid the
// tracer gathers from (shaders/photon_grid.comp, a counting sort), all in one submission. The
// photons' buffers grow when a pass stores more than they hold, and that pass runs again (its
// photons depend only on its number, so the result is the same).
#include <cstdint>
#include <map>
#include <memory>
#include <vector>

#include "gpu/vulkan/context.hpp"
#include "gpu/vulkan/memory_budget.hpp"
#include "gpu/layout.hpp"
#include "gpu/vulkan/pipeline.hpp"
#include "gpu/vulkan/submit.hpp"
#include "gpu/trace_resources.hpp"
#include "render/renderer.hpp"
#include "scene/scene.hpp"

namespace lancer::gpu {

// The photons a pass's buffers hold at first (a pass that stores more grows them), and the
// buckets per map of the hashed grid for a capacity: a power of 2 near an eighth of it (photons
// crowd into few cells; on lavapipe, a bucket per photon made the grid build of the Cornell box
// a third of its photon pass, measured, for no faster gather), at most 2^20 (photon_grid.comp
// scans the block totals in one invocation).
std::uint32_t photon_capacity(std::uint32_t count);
std::uint32_t photon_buckets(std::uint32_t capacity);

class PhotonPass {
public:
    PhotonPass(const Context& context, const TraceLayout& layout);
    ~PhotonPass();
    PhotonPass(const PhotonPass&) = delete;
    PhotonPass& operator=(const PhotonPass&) = delete;

    // The programs to run: the photon pass (built with the scene's surface code, like the
    // tracer) and the grid build. Pipelines made from earlier ones are dropped.
    void use_programs(std::vector<std::uint32_t> photons, std::vector<std::uint32_t> grid);

    // Shoots and sorts pass `pass` of the scene's photon mapping into `resources`, whose scene
    // arrays hold the scene (`emitters`: its packed emitters); `features` as for the tracer.
    // Writes the pass's PhotonParams, which the tracer's gather reads too. Returns the photons
    // stored. `progress` is asked while waiting.
    std::uint32_t run(const Scene& scene, int pass, const ShaderFeatures& features, const std::vector<Emitter>& emitters,
                      TraceResources& resources, const ProgressFn& progress, double done);

    // The parameters of pass `pass` (radii, power quantum, grid size) for a given capacity.
    static PhotonParams params(const Scene& scene, int pass, std::uint32_t capacity, const std::vector<Emitter>& emitters);

    // The buffers of a pass whose photon buffers hold `capacity` photons: what a pass allocates
    // and what the memory budget counts, the gather's copies included.
    static std::vector<BufferNeed> buffer_needs(std::uint32_t capacity);

private:
    ComputePipeline& pipeline(bool grid, const ShaderFeatures& features);
    // Records and submits the pass with the buffers at their current sizes; returns the photons
    // the pass tried to store (more than the capacity when some did not fit).
    std::uint32_t submit(const PhotonParams& params, const ShaderFeatures& features, TraceResources& resources,
                         const ProgressFn& progress, double done);

    const Context& context_;
    const TraceLayout& layout_;
    std::vector<std::uint32_t> photons_spirv_, grid_spirv_;
    std::map<std::pair<bool, ShaderFeatures>, std::unique_ptr<ComputePipeline>> pipelines_;
    Submission submission_;
    std::uint32_t capacity_ = 0;
};

}  // namespace lancer::gpu
