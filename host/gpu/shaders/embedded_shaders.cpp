#include "gpu/shaders/embedded_shaders.hpp"

#include <iterator>
#include <stdexcept>

// generated: const uint32_t lancer_ENTRY_spv[], and lancer_ENTRY_SET_spv[] for the entries built
// again for a shape set of shapes.h (see host/CMakeLists.txt)
#include "photon_grid.spv.h"
#include "photons.spv.h"
#include "photons_cheap.spv.h"
#include "photons_common.spv.h"
#include "refine_select.spv.h"
#include "trace.spv.h"
#include "trace_cheap.spv.h"
#include "trace_common.spv.h"

namespace lancer::gpu {

namespace {

constexpr bool some_shape_keeps_locals(std::uint32_t shape_types) {
    for (std::uint32_t type = 0; type < SHAPE_COUNT; ++type)
        if ((shape_types >> type & 1u) && shape_has(type, SHAPE_KEEPS_LOCALS)) return true;
    return false;
}
// The smaller tracers are built with their locals as SSA values, which would slow those shapes.
static_assert(!some_shape_keeps_locals(COMMON_SHAPE_TYPES), "a SHAPE_KEEPS_LOCALS shape in a smaller tracer's set");

struct ModuleForShapes {
    const char* entry;
    std::uint32_t shape_types;
    const std::uint32_t* begin;
    const std::uint32_t* end;
    bool locals_in_ssa;
};

// Smallest first, for each entry.
const ModuleForShapes kModulesForShapes[] = {
    {kTraceShader, CHEAP_SHAPE_TYPES, std::begin(lancer_trace_cheap_spv), std::end(lancer_trace_cheap_spv),
     lancer_trace_cheap_spv_locals_in_ssa},
    {kTraceShader, COMMON_SHAPE_TYPES, std::begin(lancer_trace_common_spv), std::end(lancer_trace_common_spv),
     lancer_trace_common_spv_locals_in_ssa},
    {kPhotonShader, CHEAP_SHAPE_TYPES, std::begin(lancer_photons_cheap_spv), std::end(lancer_photons_cheap_spv),
     lancer_photons_cheap_spv_locals_in_ssa},
    {kPhotonShader, COMMON_SHAPE_TYPES, std::begin(lancer_photons_common_spv), std::end(lancer_photons_common_spv),
     lancer_photons_common_spv_locals_in_ssa},
};

}  // namespace

std::vector<std::uint32_t> embedded_trace_spirv() { return embedded_spirv(kTraceShader); }

bool traces_only(const ShaderFeatures& features, std::uint32_t shape_types) {
    const std::uint32_t used =
        features.scene_shapes | features.boxed_families | features.split_families | features.csg_leaf_shapes;
    return (used & ~shape_types) == 0;
}

std::vector<std::uint32_t> embedded_spirv(const std::string& entry) {
    if (entry == kTraceShader) return {std::begin(lancer_trace_spv), std::end(lancer_trace_spv)};
    if (entry == kPhotonShader) return {std::begin(lancer_photons_spv), std::end(lancer_photons_spv)};
    if (entry == kGridShader) return {std::begin(lancer_photon_grid_spv), std::end(lancer_photon_grid_spv)};
    if (entry == kSelectShader) return {std::begin(lancer_refine_select_spv), std::end(lancer_refine_select_spv)};
    throw std::logic_error("embedded_spirv: no shader " + entry);
}

EmbeddedModule embedded_module(const std::string& entry, const ShaderFeatures& features) {
    for (const ModuleForShapes& module : kModulesForShapes)
        if (entry == module.entry && traces_only(features, module.shape_types))
            return {{module.begin, module.end}, module.locals_in_ssa};
    return {embedded_spirv(entry), false};
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
