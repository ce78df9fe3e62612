#pragma once
// The renderer made on another thread while the caller reads its scene: on lavapipe the Vulkan
// instance and device take 40-50 ms (loading LLVM and the driver), which then overlap the parse
// of the scene file and its meshes.
#include <future>
#include <memory>

#include "app/render_options.hpp"

namespace lancer {

class RendererStart {
public:
    explicit RendererStart(const RenderOptions& options)
        : made_(std::async(std::launch::async, [options] { return make_renderer(options); })) {}
    // The renderer, or make_renderer's error; once. An unused start is waited for and dropped
    // (a scene's error is reported as if it had never begun).
    std::unique_ptr<Renderer> take() { return made_.get(); }

private:
    std::future<std::unique_ptr<Renderer>> made_;
};

}  // namespace lancer
