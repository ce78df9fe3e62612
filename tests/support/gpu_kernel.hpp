#pragma once
// Runs a test compute shader against the tracer's interface, on the test GPU renderer's device,
// under the validation layer: GLSL functions of the tracer (intersectors, readers, shading) are
// tested directly, ray by ray, instead of through pictures.
//
// The shader's source is a complete compute shader that includes "interface.glsl" (and whatever
// else of shaders/ it needs), so it sees every scene array through its reader and the output
// array pixels[]. It is compiled against shaders/ (with `surface_code` as
// surface_functions.glsl when given) and runs `invocations` invocations of local size 1 x 1.
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include <glm/vec4.hpp>

#include "gpu/layout.hpp"
#include "gpu/packing/scene_packing.hpp"

namespace lancer::test {

class GpuKernel {
public:
    explicit GpuKernel(const std::string& source, const std::string& surface_code = "",
                       const gpu::ShaderFeatures& features = all_features());
    ~GpuKernel();

    // pixels[] holds `io` when the shader starts; returns pixels[] when it ends (as many vec4s).
    std::vector<glm::vec4> run(const gpu::PackedScene& scene, const gpu::FrameParams& frame,
                               const std::vector<glm::vec4>& io, std::uint32_t invocations);
    std::vector<glm::vec4> run(const std::vector<glm::vec4>& io, std::uint32_t invocations) {
        return run(gpu::PackedScene{}, gpu::FrameParams{}, io, invocations);
    }

    static gpu::ShaderFeatures all_features();

private:
    struct State;
    std::unique_ptr<State> state_;
};

}  // namespace lancer::test
