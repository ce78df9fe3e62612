#include "ray_query_structures.hpp"

#include <cstring>

#include "gpu/vulkan/vk_check.hpp"

namespace lancer::bench {
namespace {

constexpr VkBufferUsageFlags kStructureUsage =
    VK_BUFFER_USAGE_ACCELERATION_STRUCTURE_STORAGE_BIT_KHR | VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT;
constexpr VkBufferUsageFlags kScratchUsage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT;
constexpr VkBufferUsageFlags kInputUsage =
    VK_BUFFER_USAGE_ACCELERATION_STRUCTURE_BUILD_INPUT_READ_ONLY_BIT_KHR | VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT;

VkDeviceSize round_up(VkDeviceSize n, VkDeviceSize alignment) { return (n + alignment - 1) / alignment * alignment; }

// Builds written by earlier commands (the bottom level, for the top level's build) are read
// by later builds.
void build_barrier(VkCommandBuffer commands) {
    VkMemoryBarrier barrier{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
    barrier.srcAccessMask = VK_ACCESS_ACCELERATION_STRUCTURE_WRITE_BIT_KHR;
    barrier.dstAccessMask = VK_ACCESS_ACCELERATION_STRUCTURE_READ_BIT_KHR;
    vkCmdPipelineBarrier(commands, VK_PIPELINE_STAGE_ACCELERATION_STRUCTURE_BUILD_BIT_KHR,
                         VK_PIPELINE_STAGE_ACCELERATION_STRUCTURE_BUILD_BIT_KHR, 0, 1, &barrier, 0, nullptr, 0, nullptr);
}

// One structure of `size` bytes in a buffer of its own.
VkAccelerationStructureKHR create_structure(const RayQueryDevice& device, VkAccelerationStructureTypeKHR type,
                                            VkDeviceSize size, DeviceBuffer& storage) {
    storage = device.buffer(size, kStructureUsage, "structure");
    VkAccelerationStructureCreateInfoKHR info{VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_CREATE_INFO_KHR};
    info.buffer = storage.handle();
    info.size = size;
    info.type = type;
    VkAccelerationStructureKHR structure = VK_NULL_HANDLE;
    VK_CHECK(device.functions().create_structure(device.device(), &info, nullptr, &structure));
    return structure;
}

}  // namespace

DriverStructures::DriverStructures(const RayQueryDevice& device, const MeshSet& set, const DeviceBuffer& positions,
                                   const DeviceBuffer& indices)
    : device_(device) {
    const RayQueryFunctions& vk = device.functions();
    const VkDeviceSize align = device.scratch_alignment();

    // The bottom level: each mesh's triangles, sized, then all built in one command.
    const std::size_t n = set.meshes.size();
    std::vector<VkAccelerationStructureGeometryKHR> geometries(n, {VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_GEOMETRY_KHR});
    std::vector<VkAccelerationStructureBuildGeometryInfoKHR> builds(
        n, {VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_BUILD_GEOMETRY_INFO_KHR});
    std::vector<VkAccelerationStructureBuildRangeInfoKHR> ranges(n);
    std::vector<VkDeviceSize> scratch_offsets(n);
    VkDeviceSize bottom_scratch = 0;
    for (std::size_t i = 0; i < n; ++i) {
        const MeshRange& mesh = set.meshes[i];
        VkAccelerationStructureGeometryTrianglesDataKHR& t = geometries[i].geometry.triangles;
        geometries[i].geometryType = VK_GEOMETRY_TYPE_TRIANGLES_KHR;
        geometries[i].flags = VK_GEOMETRY_OPAQUE_BIT_KHR;
        t.sType = VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_GEOMETRY_TRIANGLES_DATA_KHR;
        t.vertexFormat = VK_FORMAT_R32G32B32_SFLOAT;
        t.vertexData.deviceAddress = positions.address() + VkDeviceSize(mesh.first_vertex) * 3 * sizeof(float);
        t.vertexStride = 3 * sizeof(float);
        t.maxVertex = mesh.vertex_count - 1;
        t.indexType = VK_INDEX_TYPE_UINT32;
        t.indexData.deviceAddress = indices.address() + VkDeviceSize(mesh.first_index) * sizeof(std::uint32_t);
        VkAccelerationStructureBuildGeometryInfoKHR& b = builds[i];
        b.type = VK_ACCELERATION_STRUCTURE_TYPE_BOTTOM_LEVEL_KHR;
        b.flags = VK_BUILD_ACCELERATION_STRUCTURE_PREFER_FAST_TRACE_BIT_KHR;
        b.mode = VK_BUILD_ACCELERATION_STRUCTURE_MODE_BUILD_KHR;
        b.geometryCount = 1;
        b.pGeometries = &geometries[i];
        ranges[i] = {mesh.triangle_count, 0, 0, 0};
        VkAccelerationStructureBuildSizesInfoKHR sizes{VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_BUILD_SIZES_INFO_KHR};
        vk.build_sizes(device.device(), VK_ACCELERATION_STRUCTURE_BUILD_TYPE_DEVICE_KHR, &b, &mesh.triangle_count, &sizes);
        bottom_storage_.emplace_back();
        bottom_.push_back(create_structure(device, b.type, sizes.accelerationStructureSize, bottom_storage_.back()));
        b.dstAccelerationStructure = bottom_.back();
        scratch_offsets[i] = bottom_scratch;
        bottom_scratch += round_up(sizes.buildScratchSize, align);
        report_.bottom_bytes += sizes.accelerationStructureSize;
    }
    {
        DeviceBuffer scratch = device.buffer(bottom_scratch + align, kScratchUsage, "scratch");
        const VkDeviceAddress base = round_up(scratch.address(), align);
        std::vector<const VkAccelerationStructureBuildRangeInfoKHR*> range_pointers;
        for (std::size_t i = 0; i < n; ++i) {
            builds[i].scratchData.deviceAddress = base + scratch_offsets[i];
            range_pointers.push_back(&ranges[i]);
        }
        report_.bottom_seconds = device.run([&](VkCommandBuffer commands) {
            vk.build(commands, static_cast<std::uint32_t>(n), builds.data(), range_pointers.data());
        });
    }

    // The top level: one instance per placement, its custom index the mesh's.
    std::vector<VkAccelerationStructureInstanceKHR> instances(set.instances.size());
    for (std::size_t i = 0; i < instances.size(); ++i) {
        const MeshInstance& placed = set.instances[i];
        VkAccelerationStructureInstanceKHR& instance = instances[i];
        std::memcpy(&instance.transform, placed.to_world.data(), sizeof instance.transform);
        instance.instanceCustomIndex = placed.mesh;
        instance.mask = 0xFF;
        instance.instanceShaderBindingTableRecordOffset = 0;
        instance.flags = VK_GEOMETRY_INSTANCE_TRIANGLE_FACING_CULL_DISABLE_BIT_KHR;
        VkAccelerationStructureDeviceAddressInfoKHR where{VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_DEVICE_ADDRESS_INFO_KHR};
        where.accelerationStructure = bottom_[placed.mesh];
        instance.accelerationStructureReference = vk.structure_address(device.device(), &where);
    }
    report_.instance_bytes = instances.size() * sizeof(VkAccelerationStructureInstanceKHR);
    instances_ = device.buffer(report_.instance_bytes, kInputUsage, "instances");
    std::memcpy(instances_.data(), instances.data(), report_.instance_bytes);

    VkAccelerationStructureGeometryKHR geometry{VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_GEOMETRY_KHR};
    geometry.geometryType = VK_GEOMETRY_TYPE_INSTANCES_KHR;
    geometry.flags = VK_GEOMETRY_OPAQUE_BIT_KHR;
    geometry.geometry.instances.sType = VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_GEOMETRY_INSTANCES_DATA_KHR;
    geometry.geometry.instances.arrayOfPointers = VK_FALSE;
    geometry.geometry.instances.data.deviceAddress = instances_.address();
    VkAccelerationStructureBuildGeometryInfoKHR build{VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_BUILD_GEOMETRY_INFO_KHR};
    build.type = VK_ACCELERATION_STRUCTURE_TYPE_TOP_LEVEL_KHR;
    build.flags = VK_BUILD_ACCELERATION_STRUCTURE_PREFER_FAST_TRACE_BIT_KHR;
    build.mode = VK_BUILD_ACCELERATION_STRUCTURE_MODE_BUILD_KHR;
    build.geometryCount = 1;
    build.pGeometries = &geometry;
    const auto count = static_cast<std::uint32_t>(instances.size());
    VkAccelerationStructureBuildSizesInfoKHR sizes{VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_BUILD_SIZES_INFO_KHR};
    vk.build_sizes(device.device(), VK_ACCELERATION_STRUCTURE_BUILD_TYPE_DEVICE_KHR, &build, &count, &sizes);
    top_ = create_structure(device, build.type, sizes.accelerationStructureSize, top_storage_);
    build.dstAccelerationStructure = top_;
    report_.top_bytes = sizes.accelerationStructureSize;
    report_.scratch_bytes = bottom_scratch + sizes.buildScratchSize;
    DeviceBuffer scratch = device.buffer(sizes.buildScratchSize + align, kScratchUsage, "scratch");
    build.scratchData.deviceAddress = round_up(scratch.address(), align);
    const VkAccelerationStructureBuildRangeInfoKHR range{count, 0, 0, 0};
    const VkAccelerationStructureBuildRangeInfoKHR* range_pointer = &range;
    report_.top_seconds = device.run([&](VkCommandBuffer commands) {
        build_barrier(commands);
        vk.build(commands, 1, &build, &range_pointer);
    });
}

DriverStructures::~DriverStructures() {
    const RayQueryFunctions& vk = device_.functions();
    if (top_) vk.destroy_structure(device_.device(), top_, nullptr);
    for (VkAccelerationStructureKHR s : bottom_) vk.destroy_structure(device_.device(), s, nullptr);
}

}  // namespace lancer::bench
