#pragma once
// From linear radiance to what a PNG shows: times 2^exposure, a tone curve, POV-Ray's
// assumed_gamma, then sRGB (docs/scene-format.md, "[render]"). The defaults (0 stops, clamp,
// gamma 1) are the identity on [0, 1].
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

// POV-Ray's assumed_gamma g: a scene's colours are taken as light^(1/g) and lit as they are, so
// a computed value v is the light v^g (POV-Ray 3.7's conversion to the output file); g = 2.2
// gives POV-Ray 3.6's look, colours and light mixed in gamma space. Within these bounds.
constexpr double kMinAssumedGamma = 0.1, kMaxAssumedGamma = 10.0;

struct ToneMapping {
    double exposure = 0.0;  // stops
    Tone tone = Tone::Clamp;
    double assumed_gamma = 1.0;
};

// A linear value as the tone curve maps it (before sRGB), in [0, 1].
float tone_map(float linear, const ToneMapping& mapping);

}  // namespace lancer
