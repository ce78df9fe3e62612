#include "gpu/passes/photon_pass.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>

#include <fmt/format.h>

#include "gpu/vulkan/submit.hpp"
#include "gpu/vulkan/vk_check.hpp"

namespace lancer::gpu {
namespace {

// A photon's power in the gather's integer sums: the brightest a light emits is 2^20 quanta.
constexpr double kQuantaPerPhoton = 1048576.0;

std::uint32_t groups(std::uint64_t invocations) {
    return static_cast<std::uint32_t>((invocations + PHOTON_WORKGROUP - 1) / PHOTON_WORKGROUP);
}

}  // namespace

std::uint32_t photon_capacity(std::uint32_t count) {
    return static_cast<std::uint32_t>(std::min<std::uint64_t>(2ull * count + 1024, 1u << 26));
}

std::uint32_t photon_buckets(std::uint32_t capacity) {
    return std::clamp(std::bit_ceil(capacity / 8), 1024u, 1u << 20);
}

std::vector<BufferNeed> PhotonPass::buffer_needs(std::uint32_t capacity) {
    const std::uint64_t buckets = 2ull * photon_buckets(capacity);  // the caustic map's, then the global map's
    return {resource_need(BINDING_PHOTON_PARAMS, 1),
            resource_need(BINDING_PHOTONS, capacity),
            resource_need(BINDING_PHOTONS_SORTED, capacity),
            resource_need(BINDING_PHOTON_COUNTER, 1),
            resource_need(BINDING_CELL_COUNT, buckets),
            resource_need(BINDING_CELL_START, buckets + 1),
            resource_need(BINDING_BLOCK_SUMS, groups(buckets) + 1),
            resource_need(BINDING_GATHER_PHOTONS, capacity),
            resource_need(BINDING_GATHER_STARTS, buckets + 1)};
}

PhotonPass::PhotonPass(const Context& context, const TraceLayout& layout)
    : context_(context), layout_(layout), submission_(context, "photon pass") {}

PhotonPass::~PhotonPass() {
    vkDeviceWaitIdle(context_.device());
    pipelines_.clear();
}

void PhotonPass::use_programs(std::vector<std::uint32_t> photons, std::vector<std::uint32_t> grid) {
    if (photons == photons_spirv_ && grid == grid_spirv_) return;
    VK_CHECK(vkDeviceWaitIdle(context_.device()));
    pipelines_.clear();
    photons_spirv_ = std::move(photons);
    grid_spirv_ = std::move(grid);
}

ComputePipeline& PhotonPass::pipeline(bool grid, const ShaderFeatures& features) {
    auto& slot = pipelines_[{grid, features}];
    if (!slot) slot = std::make_unique<ComputePipeline>(context_, layout_, grid ? grid_spirv_ : photons_spirv_, features);
    return *slot;
}

PhotonParams PhotonPass::params(const Scene& scene, int pass, std::uint32_t capacity, const std::vector<Emitter>& emitters) {
    const PhotonSettings& ps = *scene.photons;
    float brightest = 0.0f;
    for (const Emitter& e : emitters) brightest = std::max({brightest, e.power.r, e.power.g, e.power.b});
    PhotonParams p{};
    p.radii = vec4(float(photon_radius(ps.caustic_radius, ps.alpha, pass)),
                   float(photon_radius(ps.global_radius, ps.alpha, pass)),
                   brightest > 0.0f ? float(brightest / kQuantaPerPhoton) : 1.0f, 0.0f);
    p.pass = static_cast<uint>(pass);
    p.count = static_cast<uint>(ps.count);
    p.seed = ps.seed;
    p.max_bounces = static_cast<uint>(ps.max_bounces);
    p.capacity = capacity;
    p.table_size = photon_buckets(capacity);
    p.first_pass = static_cast<uint>(ps.first_pass);
    p.last_pass = static_cast<uint>(ps.last_pass());
    return p;
}

std::uint32_t PhotonPass::run(const Scene& scene, int pass, const ShaderFeatures& features,
                              const std::vector<Emitter>& emitters, TraceResources& resources, const ProgressFn& progress,
                              double done) {
    capacity_ = std::max(capacity_, photon_capacity(static_cast<std::uint32_t>(scene.photons->count)));
    for (;;) {
        PhotonParams p = params(scene, pass, capacity_, emitters);
        std::uint32_t stored = submit(p, features, resources, progress, done);
        if (stored <= capacity_) return stored;
        // Too many for the buffers: make room for them (and a margin) and shoot the same photons again.
        const std::uint64_t wanted = std::min<std::uint64_t>(std::uint64_t(stored) + stored / 4, UINT32_MAX);
        const DeviceMemoryLimits limits = buffer_memory_limits(context_);
        for (const BufferNeed& need : buffer_needs(static_cast<std::uint32_t>(wanted)))
            if (!fits(need, limits))
                throw UserError(fmt::format("a photon pass stored {} photons, more than this device holds in one buffer "
                                            "of {}; lower [photons] count",
                                            stored, need.what));
        capacity_ = static_cast<std::uint32_t>(wanted);
    }
}

std::uint32_t PhotonPass::submit(const PhotonParams& p, const ShaderFeatures& features, TraceResources& resources,
                                 const ProgressFn& progress, double done) {
    const std::uint64_t buckets = 2ull * p.table_size;
    for (const BufferNeed& need : buffer_needs(p.capacity)) resources.working(need.binding, need.bytes);
    resources.working(BINDING_PHOTON_PARAMS, 0).write(&p, sizeof(p));
    const Buffer& counter = resources.working(BINDING_PHOTON_COUNTER, 0);
    const uint zero = 0;
    counter.write(&zero, sizeof(zero));

    VkCommandBuffer commands = submission_.begin();
    VkDescriptorSet set = resources.descriptor_set();
    vkCmdBindDescriptorSets(commands, VK_PIPELINE_BIND_POINT_COMPUTE, layout_.pipeline_layout(), 0, 1, &set, 0, nullptr);
    vkCmdBindPipeline(commands, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline(false, features).handle());
    vkCmdDispatch(commands, groups(p.count), 1, 1);
    compute_barrier(commands);
    vkCmdBindPipeline(commands, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline(true, features).handle());
    const std::pair<uint, std::uint64_t> steps[] = {{GRID_CLEAR, buckets}, {GRID_COUNT, p.capacity}, {GRID_SCAN, buckets},
                                                    {GRID_BLOCKS, 1},      {GRID_OFFSET, buckets},   {GRID_SCATTER, p.capacity}};
    for (const auto& [kind, invocations] : steps) {
        GridStep step{kind, 0, 0, 0};
        vkCmdPushConstants(commands, layout_.pipeline_layout(), VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof(step), &step);
        vkCmdDispatch(commands, groups(invocations), 1, 1);
        compute_barrier(commands);
    }
    compute_barrier(commands, VK_ACCESS_HOST_READ_BIT, VK_PIPELINE_STAGE_HOST_BIT);  // the counter, read below
    submission_.end_and_wait(progress, done);
    uint stored = 0;
    std::memcpy(&stored, counter.data(), sizeof(stored));
    if (stored <= p.capacity) {
        // The tracer gathers from texel buffers: the sorted photons and the bucket starts copied
        // there (the buffers are mapped on the host; a few MiB per pass).
        const Buffer& sorted = resources.working(BINDING_PHOTONS_SORTED, 0);
        const Buffer& starts = resources.working(BINDING_CELL_START, 0);
        const std::size_t photon_bytes = std::size_t(stored) * sizeof(Photon), start_bytes = (buckets + 1) * sizeof(uint);
        resources.working(BINDING_GATHER_PHOTONS, 0).write(sorted.data(), photon_bytes);
        resources.working(BINDING_GATHER_STARTS, 0).write(starts.data(), start_bytes);
    }
    return stored;
}

}  // namespace lancer::gpu
