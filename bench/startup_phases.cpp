// Where lancer's start-up goes on the GPU path, phase by phase, for one scene (a benchmark, not
// a test): Vulkan instance and device, packing and upload, pipeline creation (lavapipe turns the
// SPIR-V into NIR here), and the first dispatch of one pixel (llvmpipe compiles the NIR with
// LLVM here, or finds it in Mesa's shader cache).
//
//   build/bench/lancer_startup_phases SCENE [SPIRV_FILE]
//
// With SPIRV_FILE, the pipeline is built from that module instead of the embedded tracer (to
// measure what a smaller or pre-optimised module costs the driver).
// Each phase prints its wall time and the CPU time of the whole process (all threads, the
// driver's included), which a loaded machine disturbs far less.
#include <chrono>
#include <cstdio>
#include <ctime>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "gpu/shaders/embedded_shaders.hpp"
#include "gpu/vulkan/pipeline.hpp"
#include "gpu/packing/scene_packing.hpp"
#include "gpu/shaders/spirv_specialize.hpp"
#include "gpu/trace_resources.hpp"
#include "gpu/vulkan/vk_check.hpp"
#include "scene/load_scene.hpp"

namespace {

using Clock = std::chrono::steady_clock;

double cpu_ms() {
    timespec t{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return 1e3 * double(t.tv_sec) + 1e-6 * double(t.tv_nsec);
}

// A phase's start; elapsed() is "wall ms, CPU ms" since then.
struct Phase {
    Clock::time_point wall = Clock::now();
    double cpu = cpu_ms();
    std::string elapsed() const {
        char text[64];
        std::snprintf(text, sizeof text, "%8.1f ms wall %8.1f ms CPU",
                      std::chrono::duration<double, std::milli>(Clock::now() - wall).count(), cpu_ms() - cpu);
        return text;
    }
};

}  // namespace

int main(int argc, char** argv) {
    using namespace lancer;
    if (argc < 2) {
        std::fprintf(stderr, "usage: %s SCENE [SPIRV_FILE]\n", argv[0]);
        return 2;
    }
    Phase t;
    Scene scene = load_scene(argv[1]);
    scene.render.width = scene.render.height = scene.render.samples = 1;
    std::printf("load scene        %s\n", t.elapsed().c_str());

    t = Phase();
    gpu::Context context(gpu::ContextOptions{});
    gpu::TraceLayout layout(context);
    gpu::TraceResources resources(context, layout.set_layout());
    std::printf("instance, device  %s  (%s)\n", t.elapsed().c_str(), context.info().name.c_str());

    t = Phase();
    gpu::PackedScene packed = gpu::pack_scene(scene);
    resources.upload(packed, gpu::pack_frame(scene, packed));
    const gpu::Buffer& output = resources.output(sizeof(gpu::vec4));
    std::printf("pack, upload      %s\n", t.elapsed().c_str());

    // The embedded tracer lancer would choose for the scene's shapes.
    gpu::EmbeddedModule tracer = gpu::embedded_module(gpu::kTraceShader, packed.features);
    std::vector<std::uint32_t> spirv = tracer.spirv;
    if (argc > 2) {
        std::ifstream in(argv[2], std::ios::binary);
        std::vector<char> bytes((std::istreambuf_iterator<char>(in)), {});
        spirv.assign(bytes.size() / 4, 0);
        std::memcpy(spirv.data(), bytes.data(), spirv.size() * 4);
    }
    std::printf("SPIR-V            %8zu words\n", spirv.size());
    gpu::ShaderFeatures features = packed.features;
    // As lancer chooses; a SPIRV_FILE is taken as glslang wrote it (its locals not yet SSA values).
    const gpu::SpirvCleanup cleanup = gpu::spirv_cleanup_for(features, tracer.locals_in_ssa && argc == 2);
    t = Phase();
    std::size_t specialized = gpu::specialize_spirv(spirv, features, cleanup).size();
    std::printf("specialise        %s  (%zu words; done again inside pipeline creation)\n", t.elapsed().c_str(), specialized);
    t = Phase();
    gpu::ComputePipeline pipeline(context, layout, spirv, features, "tracer", cleanup);
    std::printf("create pipeline   %s\n", t.elapsed().c_str());

    t = Phase();
    VkDevice device = context.device();
    VkCommandBuffer commands;
    VkCommandBufferAllocateInfo alloc{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
    alloc.commandPool = context.command_pool();
    alloc.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
    alloc.commandBufferCount = 1;
    VK_CHECK(vkAllocateCommandBuffers(device, &alloc, &commands));
    VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
    VK_CHECK(vkBeginCommandBuffer(commands, &begin));
    vkCmdBindPipeline(commands, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline.handle());
    VkDescriptorSet set = resources.descriptor_set();
    vkCmdBindDescriptorSets(commands, VK_PIPELINE_BIND_POINT_COMPUTE, layout.pipeline_layout(), 0, 1, &set, 0, nullptr);
    gpu::BandParams band{0, 1, 0, 1, 0, 0, 0, 1};  // one row, one sample, tiles in order
    vkCmdPushConstants(commands, layout.pipeline_layout(), VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof(band), &band);
    vkCmdDispatch(commands, 1, 1, 1);
    VK_CHECK(vkEndCommandBuffer(commands));
    VkSubmitInfo submit{VK_STRUCTURE_TYPE_SUBMIT_INFO};
    submit.commandBufferCount = 1;
    submit.pCommandBuffers = &commands;
    VK_CHECK(vkQueueSubmit(context.queue(), 1, &submit, VK_NULL_HANDLE));
    VK_CHECK(vkQueueWaitIdle(context.queue()));
    std::printf("first dispatch    %s  (pixel %.3f %.3f %.3f)\n", t.elapsed().c_str(),
                static_cast<const gpu::vec4*>(output.data())->r, static_cast<const gpu::vec4*>(output.data())->g,
                static_cast<const gpu::vec4*>(output.data())->b);
    vkFreeCommandBuffers(device, context.command_pool(), 1, &commands);
    return 0;
}
