#pragma once
// The largest magnitude lancer accepts for any number in its input (scene values, patch file
// coordinates) and for any point of the geometry built from them (transformed patches, the boxes
// of parametric surfaces). The GPU computes in float (largest value about 3.4e38); within 1e12,
// every product the tracer forms (a colour times an intensity times a coefficient, summed over
// the lights; a squared distance) stays finite, so no infinity and no NaN can reach a pixel.
namespace lancer {

constexpr double kMaxMagnitude = 1e12;

}  // namespace lancer
