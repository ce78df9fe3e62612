#pragma once
// The [animation] table: frames, fps, cyclic, and what moves (docs/scene-format.md, "Animation").
#include <span>

#include <toml++/toml.h>

#include "scene/scene.hpp"
#include "scene/toml_reader.hpp"

namespace lancer {

// Reads [animation] from the scene's top-level table into scene.animation, once lights and
// objects are read (animations refer to them by name or index). Also checks that light and
// object names are unique, with or without [animation]. Errors are SceneErrors.
// entry_starts: entry i of [[object]] made scene objects [entry_starts[i], entry_starts[i + 1])
// (a group, all its members).
void read_animation(TableReader& top, const toml::table& root, Scene& scene, std::span<const std::size_t> entry_starts);

}  // namespace lancer
