#pragma once
// The Vulkan compute backend. Device, pipeline and buffers live as long as the renderer, so a
// sequence of renders (animation frames) pays the start-up cost once.
#include <cstddef>
#include <memory>
#include <vector>

#include "gpu/buffer.hpp"
#include "gpu/context.hpp"
#include "gpu/layout.hpp"
#include "gpu/pipeline.hpp"
#include "gpu/shader_compiler.hpp"
#include "render/renderer.hpp"

namespace lancer {

// What the last render() copied to the GPU. Scene buffers whose packed contents equal what the
// GPU already holds are skipped, so an animation frame that only moves the camera writes the
// frame uniform alone, and one that moves lights writes the light buffer too.
struct UploadStats {
    std::size_t bytes_written = 0;  // frame uniform included
    std::size_t bytes_skipped = 0;  // scene buffers left as they were
};

class GpuRenderer final : public Renderer {
public:
    explicit GpuRenderer(const gpu::ContextOptions& options);
    ~GpuRenderer() override;

    std::string description() const override;
    FloatImage render(const Scene& scene, const ProgressFn& progress) override;

    const gpu::Context& context() const { return *context_; }
    const UploadStats& last_upload() const { return last_upload_; }

    // Rebuilds the tracer from GLSL sources at run time (same entry point, same defines as the
    // embedded SPIR-V). Throws ShaderCompileError and keeps the current pipeline if they do not
    // compile; on success the next render uses the new pipeline.
    void use_shaders(const gpu::ShaderTree& tree);

private:
    void upload_scene(const Scene& scene);
    template <typename T>
    void upload(gpu::Buffer& buffer, std::vector<T>& shadow, std::vector<T>&& items);
    void ensure_output(std::size_t bytes);
    void update_descriptors();
    void dispatch_band(std::uint32_t y0, std::uint32_t rows, std::uint32_t width, double done, const ProgressFn& progress);

    std::unique_ptr<gpu::Context> context_;
    std::unique_ptr<gpu::TraceLayout> layout_;
    std::unique_ptr<gpu::ComputePipeline> pipeline_;
    gpu::Buffer frame_, primitives_, materials_, lights_, output_;
    VkDescriptorPool descriptor_pool_ = VK_NULL_HANDLE;
    VkDescriptorSet descriptor_set_ = VK_NULL_HANDLE;
    VkCommandBuffer command_buffer_ = VK_NULL_HANDLE;
    VkFence fence_ = VK_NULL_HANDLE;
    bool descriptors_dirty_ = true;
    // What each scene buffer holds, kept on the host to compare against (reading mapped GPU
    // memory back can be very slow on discrete GPUs).
    std::vector<gpu::Primitive> primitives_shadow_;
    std::vector<gpu::Material> materials_shadow_;
    std::vector<gpu::Light> lights_shadow_;
    UploadStats last_upload_;
};

}  // namespace lancer
