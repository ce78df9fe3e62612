// Test main for the render tests: after all tests, destroy the shared GPU renderer and fail if
// the validation layer said anything at any point, teardown included.
#include <gtest/gtest.h>

#include "gpu/vulkan/context.hpp"
#include "gpu/vulkan/pipeline.hpp"
#include "support/test_support.hpp"

namespace {

class ValidationEnvironment : public testing::Environment {
public:
    void TearDown() override {
        lancer::test::release_gpu_renderer();
        EXPECT_EQ(lancer::gpu::validation_message_count(), 0u) << "Vulkan validation messages (see stderr)";
    }
};

}  // namespace

int main(int argc, char** argv) {
    testing::InitGoogleTest(&argc, argv);
    testing::AddGlobalTestEnvironment(new ValidationEnvironment);
    const int result = RUN_ALL_TESTS();
    // A test that cancels a render while its pipeline builds leaves the build running: the exit
    // handlers (the driver's static destructors) must not run under it. (NVIDIA's driver aborted
    // in free() after Progressive.ACancelledPassThrows.)
    lancer::gpu::wait_for_abandoned_pipeline_builds();
    return result;
}
