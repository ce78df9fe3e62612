#pragma once
// bench/ray_query.comp as a compute pipeline with its one descriptor set: the top-level
// structure, the meshes' vertices and triangles, where each mesh starts, the output pixels and
// the view. trace() dispatches one invocation per pixel and waits.
#include <vector>

#include "image/image.hpp"
#include "ray_query_device.hpp"
#include "ray_query_scene.hpp"

namespace lancer::bench {

class RayQueryTracer {
public:
    RayQueryTracer(const RayQueryDevice& device, const MeshSet& set, const ViewBlock& view);
    ~RayQueryTracer();
    RayQueryTracer(const RayQueryTracer&) = delete;
    RayQueryTracer& operator=(const RayQueryTracer&) = delete;

    // The meshes' buffers, which the driver's build reads too.
    const DeviceBuffer& positions() const { return positions_; }
    const DeviceBuffer& indices() const { return indices_; }
    // Traces the picture through `top` (built from this tracer's buffers): the host's wall
    // seconds from submission to the fence.
    double trace(VkAccelerationStructureKHR top);
    // The last trace's picture, linear radiance.
    FloatImage picture() const;

private:
    const RayQueryDevice& device_;
    ViewBlock view_;
    DeviceBuffer positions_, indices_, mesh_starts_, pixels_, view_buffer_;
    VkDescriptorSetLayout set_layout_ = VK_NULL_HANDLE;
    VkPipelineLayout pipeline_layout_ = VK_NULL_HANDLE;
    VkPipeline pipeline_ = VK_NULL_HANDLE;
    VkDescriptorPool pool_ = VK_NULL_HANDLE;
    VkDescriptorSet set_ = VK_NULL_HANDLE;
};

}  // namespace lancer::bench
