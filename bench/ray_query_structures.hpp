#pragma once
// The driver's acceleration structures over a MeshSet (bench/ray_query.sh): one bottom-level
// structure per mesh (its triangles, opaque), one top-level structure over every instance, both
// built by the driver with PREFER_FAST_TRACE, and what that cost in time and bytes.
#include <vector>

#include "ray_query_device.hpp"
#include "ray_query_scene.hpp"

namespace lancer::bench {

struct BuildReport {
    double bottom_seconds = 0, top_seconds = 0;  // host wall time around each build's submission and wait
    VkDeviceSize bottom_bytes = 0, top_bytes = 0;  // accelerationStructureSize, summed
    VkDeviceSize scratch_bytes = 0;                // buildScratchSize of both builds (freed after them)
    VkDeviceSize instance_bytes = 0;               // the instances' array the top level is built from
};

class DriverStructures {
public:
    // Builds the structures over `set`, whose vertices and triangles are already in `positions`
    // and `indices` (buffers with device addresses, which the shader reads too).
    DriverStructures(const RayQueryDevice& device, const MeshSet& set, const DeviceBuffer& positions,
                     const DeviceBuffer& indices);
    ~DriverStructures();
    DriverStructures(const DriverStructures&) = delete;
    DriverStructures& operator=(const DriverStructures&) = delete;

    VkAccelerationStructureKHR top() const { return top_; }
    const BuildReport& report() const { return report_; }

private:
    const RayQueryDevice& device_;
    std::vector<DeviceBuffer> bottom_storage_;
    std::vector<VkAccelerationStructureKHR> bottom_;
    DeviceBuffer instances_;
    DeviceBuffer top_storage_;
    VkAccelerationStructureKHR top_ = VK_NULL_HANDLE;
    BuildReport report_;
};

}  // namespace lancer::bench
