#pragma once
// What a rendering backend is: scene in, linear float image out.
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "image/image.hpp"
#include "scene/scene.hpp"

namespace lancer {

// Called with the finished fraction of the image (0..1). Returning false cancels the render,
// which then throws RenderCancelled.
using ProgressFn = std::function<bool(double fraction)>;

class RenderCancelled : public std::runtime_error {
public:
    RenderCancelled() : std::runtime_error("render cancelled") {}
};

// How renderers find the objects a ray hits. Brute force tests every object and exists to check
// the BVH: both must give identical images. With only a handful of objects the GPU tests them
// all even with Bvh (faster there); BvhAlways builds the tree anyway, so that tests check it
// on small scenes too.
enum class Acceleration { Bvh, BvhAlways, BruteForce };

class Renderer {
public:
    virtual ~Renderer() = default;
    // A human-readable description, e.g. "gpu: llvmpipe (LLVM 15.0.6, 256 bits)".
    virtual std::string description() const = 0;
    // Renders with scene.render's width, height, samples and max_depth.
    virtual FloatImage render(const Scene& scene, const ProgressFn& progress) = 0;

    // The one-time work for scenes like this one (on the GPU: buffers, shader, pipeline and the
    // driver's compile at the first dispatch), so that a following render() costs what every
    // later one does. Animations call it to report start-up apart from the time per frame.
    // `progress` can cancel it (RenderCancelled), as it can a render.
    virtual void prepare(const Scene& /*scene*/, const ProgressFn& /*progress*/) {}

    // The caller renders one still with this renderer and no frame after it (lancer render):
    // the renderer keeps nothing for frames to come (a BVH cache, the host's copy of what it
    // uploaded), which would only add to the peak memory.
    virtual void expect_one_still() {}

    // Renders a scene that its caller has no more use for but for its settings (lancer render's
    // one still): a renderer may free the objects once it has packed them, leaving scene.objects
    // empty (the GPU path after expect_one_still: 168 MiB of a scene of 10^6 spheres).
    virtual FloatImage render_once(Scene& scene, const ProgressFn& progress) { return render(scene, progress); }

    // For tests of exactness: per pixel, the first hit of the ray through the pixel's centre as
    // (t, u, v, part): t < 0 for a miss, (u, v) the surface's own parameters where it has them,
    // part the index of the patch hit in a Bezier surface (else -1).
    virtual FloatImage render_hits(const Scene& scene) = 0;

    // What the user should know about the renders so far beyond their pictures, one line each
    // (e.g. work the driver's limits made the GPU renderer do again).
    virtual std::vector<std::string> notes() const { return {}; }

    // Renderers that run shaders compile them from the sources in `directory` instead of the
    // built-in ones (development, `lancer watch`); throws ShaderCompileError (a UserError) and
    // keeps the shaders it had when they do not compile. The others refuse.
    virtual bool runs_shaders() const { return false; }
    virtual void use_shader_directory(const std::string& /*directory*/) {
        throw UserError("--shaders needs the gpu backend");
    }
};

}  // namespace lancer
