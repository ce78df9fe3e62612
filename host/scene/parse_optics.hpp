#pragma once
// A material's optics keys: transmission, ior, absorption (refraction) and highlight (the
// highlight model), with their defaults and checks (docs/scene-format.md, "Refraction").
#include "scene/scene.hpp"
#include "scene/toml_reader.hpp"

namespace lancer {

// Reads the optics keys of a [material.NAME] table into `m`.
void read_optics(TableReader& t, Material& m);

}  // namespace lancer
