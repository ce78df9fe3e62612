#pragma once
// One static scene -> one PNG, with the progress line and the summary line.
#include <string>

#include "app/render_options.hpp"
#include "app/renderer_start.hpp"

namespace lancer {

// Renders `scene` (already static: scene_at() for a frame of an animation; its objects are
// freed as the renderer packs them) to `output`, with the
// renderer from `renderer_start` (taken once the output is known to be writable). Returns the exit code:
// 1 when the Vulkan validation layer reported anything.
int render_still(const RenderOptions& options, Scene scene, const std::string& output, RendererStart& renderer_start);

}  // namespace lancer
