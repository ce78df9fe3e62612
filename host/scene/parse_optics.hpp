#pragma once
// A material's optics keys: transmission, ior, absorption (refraction), highlight (the Phong
// highlight model), and the microfacet model's keys (roughness, metal, eta, k), with their
// defaults and checks (docs/scene-format.md, "Refraction" and "Microfacet materials").
#include "scene/scene.hpp"
#include "scene/toml_reader.hpp"

namespace lancer {

// Reads the optics keys of a Phong [material.NAME] table into `m`.
void read_optics(TableReader& t, Material& m);

// Reads a [material.NAME] table with model = "microfacet" into `m`; the keys of Phong materials
// are errors that say so.
void read_microfacet(TableReader& t, Material& m);

// The keys only Phong materials take (ambient, diffuse, ..., texture, pattern, bump); a
// microfacet material rejects them by name.
const std::vector<std::string>& phong_only_keys();

}  // namespace lancer
