#pragma once
// The CPU reference's photon pass (docs/scene-format.md, "Photon mapping"): photons leave the
// lights in proportion to their power, bounce through mirrors, glass, metals and diffuse
// surfaces with Russian roulette, and are stored where they land on diffuse surfaces. Written
// independently of shaders/photons.comp; both draw their random numbers from the same integer
// hash, so a pass's photons start alike on both backends.
#include <cstdint>
#include <vector>

#include "cpu/photon_map.hpp"
#include "cpu/tracer.hpp"

namespace lancer::cpu {

// The photons one pass stored, by map.
struct StoredPhotons {
    std::vector<Photon> caustic;  // arrived through specular and glossy surfaces only
    std::vector<Photon> global;   // arrived after at least one diffuse bounce
    std::vector<Photon> direct;   // straight from a light (kept only when asked for: tests)
};

// Shoots the scene's PhotonSettings::count photons of pass `pass` (scene.photons must be set,
// and every light must have a power: check_photon_lights). `threads` workers; the result does
// not depend on their number.
StoredPhotons shoot_photons(const Tracer& tracer, int pass, unsigned threads, bool keep_direct = false);

// The numbers photon i of a pass draws (docs/scene-format.md): base = h(h(h(seed) ^ pass) ^ i),
// then number k is the top 24 bits of h(base ^ h(k)) over 2^24, k = 0, 1, 2, ...
class PhotonRandom {
public:
    PhotonRandom(std::uint32_t seed, std::uint32_t pass, std::uint32_t photon);
    double next();

private:
    std::uint32_t base_;
    std::uint32_t k_ = 0;
};

}  // namespace lancer::cpu
