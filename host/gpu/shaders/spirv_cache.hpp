#pragma once
// Compiled and specialised tracer modules kept on disk between runs. Specialising the tracer
// with SPIRV-Tools (gpu/shaders/spirv_specialize) is most of lancer's start-up once Mesa's shader cache
// holds the driver's compile, and compiling it with glslang is most of the rest for a scene with
// expression surfaces (their generated code), yet both depend only on their inputs: a scene
// rendered again reuses them, as Mesa reuses its compile.
//
// The directory is $LANCER_CACHE_DIR, else $XDG_CACHE_HOME/lancer, else $HOME/.cache/lancer;
// LANCER_CACHE_DISABLE=1 (or true) turns the cache off. A missing, unwritable, damaged or
// foreign entry is never an error: it is specialised again (and written back if possible).
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "gpu/layout.hpp"
#include "gpu/shaders/shader_compiler.hpp"
#include "gpu/shaders/spirv_specialize.hpp"

namespace lancer::gpu {

// Where entries go; nullopt when the cache is off or no directory can be named.
std::optional<std::string> spirv_cache_directory();

// compile_compute(with_files(base, generated), entry, defines, display_root), from the cache
// when an entry of the same compiler, generated files, entry point text and defines was compiled
// from files that all read the same today (every name the compile looked up: included files,
// and files it did not find). A compile that fails is not kept.
std::vector<std::uint32_t> cached_compile(const ShaderTree& base, const ShaderFiles& generated,
                                          const std::string& entry, const std::vector<ShaderDefine>& defines = {},
                                          const std::string& display_root = "");

// specialize_spirv(spirv, features, cleanup), from the cache when an entry matches all three exactly.
std::vector<std::uint32_t> cached_specialization(const std::vector<std::uint32_t>& spirv, const ShaderFeatures& features,
                                                 SpirvCleanup cleanup = SpirvCleanup::dead_code);

}  // namespace lancer::gpu
