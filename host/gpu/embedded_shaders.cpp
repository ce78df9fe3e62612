#include "gpu/embedded_shaders.hpp"

#include <iterator>

#include "trace.spv.h"  // generated: const uint32_t lancer_trace_spv[] (see host/CMakeLists.txt)

namespace lancer::gpu {

std::vector<std::uint32_t> embedded_trace_spirv() {
    return {std::begin(lancer_trace_spv), std::end(lancer_trace_spv)};
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
