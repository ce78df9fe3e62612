#pragma once
// From linear radiance to what a PNG shows: times 2^exposure, a tone curve, then sRGB
// (docs/scene-format.md, "[render]"). The defaults (0 stops, clamp) are the identity on [0, 1].
namespace lancer {

enum class Tone {
    Clamp,     // values above 1 are white
    Reinhard,  // x / (1 + x): every value keeps a distinct level, 1 becomes 0.5
    Aces,      // the ACES filmic curve (Narkowicz's fit): a toe, a shoulder, white from 7.24
};

// The exposures lancer accepts, in stops, wherever one is given: [render] exposure, --exposure of
// render, watch, view and combine, and an OpenEXR part's lancerExposure attribute. 2^64 takes
// the faintest float radiance to white and back; anything beyond is a mistake, as is NaN.
constexpr double kMaxExposureStops = 64.0;

struct ToneMapping {
    double exposure = 0.0;  // stops
    Tone tone = Tone::Clamp;
};

// A linear value as the tone curve maps it (before sRGB), in [0, 1].
float tone_map(float linear, const ToneMapping& mapping);

}  // namespace lancer
