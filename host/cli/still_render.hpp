#pragma once
// One static scene -> one PNG, with the progress line and the summary line.
#include <string>

#include "app/render_options.hpp"
#include "app/renderer_start.hpp"

namespace lancer {

// Renders `scene` (already static: scene_at() for a frame of an animation) to `output` with the
// renderer from `renderer_start`, taken once the output is known to be writable; the renderer may
// free the scene's objects as it packs them (Renderer::render_once). Returns the exit code: 1 when
// the Vulkan validation layer reported anything.
int render_still(const RenderOptions& options, Scene scene, const std::string& output, RendererStart& renderer_start);

}  // namespace lancer
