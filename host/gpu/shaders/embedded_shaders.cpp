#include "gpu/shaders/embedded_shaders.hpp"

#include <iterator>
#include <stdexcept>

// generated: const uint32_t lancer_ENTRY_spv[] (see host/CMakeLists.txt)
#include "photon_grid.spv.h"
#include "photons.spv.h"
#include "refine_select.spv.h"
#include "trace.spv.h"

namespace lancer::gpu {

std::vector<std::uint32_t> embedded_trace_spirv() { return embedded_spirv(kTraceShader); }

std::vector<std::uint32_t> embedded_spirv(const std::string& entry) {
    if (entry == kTraceShader) return {std::begin(lancer_trace_spv), std::end(lancer_trace_spv)};
    if (entry == kPhotonShader) return {std::begin(lancer_photons_spv), std::end(lancer_photons_spv)};
    if (entry == kGridShader) return {std::begin(lancer_photon_grid_spv), std::end(lancer_photon_grid_spv)};
    if (entry == kSelectShader) return {std::begin(lancer_refine_select_spv), std::end(lancer_refine_select_spv)};
    throw std::logic_error("embedded_spirv: no shader " + entry);
}

ShaderTree embedded_tree() {
    return [](const std::string& name) -> std::optional<std::string> {
        const auto& files = embedded_shader_files();
        auto found = files.find(name);
        if (found == files.end()) return std::nullopt;
        return found->second;
    };
}

}  // namespace lancer::gpu
