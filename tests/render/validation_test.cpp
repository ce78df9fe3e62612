// The validation safety net itself must work: if the layer were silently absent, every "no
// validation messages" assertion would pass vacuously.
#include <gtest/gtest.h>

#include "gpu/vulkan/context.hpp"
#include "gpu/vulkan/vk_check.hpp"
#include "support/test_support.hpp"

namespace lancer {
namespace {

TEST(Validation, LayerIsActiveAndReportsMisuse) {
    const gpu::Context& context = test::gpu_renderer().context();
    std::uint32_t before = gpu::validation_message_count();
    // Deliberately invalid: a buffer of size 0 violates VUID-VkBufferCreateInfo-size-00912.
    VkBufferCreateInfo info{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
    info.size = 0;
    info.usage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT;
    VkBuffer buffer = VK_NULL_HANDLE;
    VkResult result = vkCreateBuffer(context.device(), &info, nullptr, &buffer);
    if (result == VK_SUCCESS && buffer) vkDestroyBuffer(context.device(), buffer, nullptr);
    std::uint32_t reported = gpu::validation_message_count() - before;
    EXPECT_GE(reported, 1u) << "the validation layer did not report an invalid vkCreateBuffer";
    // Take the provoked message back out of the count the suite checks at exit.
    gpu::forget_validation_messages(reported);
}

}  // namespace
}  // namespace lancer
