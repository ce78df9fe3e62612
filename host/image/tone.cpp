#include "image/tone.hpp"

#include <algorithm>
#include <cmath>

namespace lancer {

float tone_map(float linear, const ToneMapping& mapping) {
    float x = linear;
    if (mapping.exposure != 0.0) x = static_cast<float>(x * std::exp2(mapping.exposure));
    switch (mapping.tone) {
        case Tone::Clamp: break;
        case Tone::Reinhard: x = x > 0.0f ? x / (1.0f + x) : 0.0f; break;
        case Tone::Aces:
            // Narkowicz 2015, "ACES filmic tone mapping curve"; it reaches 1 at x = 7.24.
            x = std::max(x, 0.0f);
            x = std::min(1.0f, (x * (2.51f * x + 0.03f)) / (x * (2.43f * x + 0.59f) + 0.14f));
            break;
    }
    if (mapping.assumed_gamma != 1.0) x = static_cast<float>(std::pow(std::max(x, 0.0f), mapping.assumed_gamma));
    return x;
}

}  // namespace lancer
