#pragma once
// Specialised tracer modules kept on disk between runs. Specialising the tracer with SPIRV-Tools
// (gpu/spirv_specialize) is most of lancer's start-up once Mesa's shader cache holds the
// driver's compile, yet its result depends only on the module and the feature set: a scene of
// the same kind rendered again reuses it, as Mesa reuses the compile.
//
// The directory is $LANCER_CACHE_DIR, else $XDG_CACHE_HOME/lancer, else $HOME/.cache/lancer;
// LANCER_CACHE_DISABLE=1 (or true) turns the cache off. A missing, unwritable, damaged or
// foreign entry is never an error: it is specialised again (and written back if possible).
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "gpu/layout.hpp"
#include "gpu/spirv_specialize.hpp"

namespace lancer::gpu {

// Where entries go; nullopt when the cache is off or no directory can be named.
std::optional<std::string> spirv_cache_directory();

// specialize_spirv(spirv, features, cleanup), from the cache when an entry matches all three exactly.
std::vector<std::uint32_t> cached_specialization(const std::vector<std::uint32_t>& spirv, const ShaderFeatures& features,
                                                 SpirvCleanup cleanup = SpirvCleanup::dead_code);

}  // namespace lancer::gpu
