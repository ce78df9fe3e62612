#pragma once
// Run-time GLSL -> SPIR-V with the glslang library: the path the hot reloader and the
// expression-surface compiler take. It resolves #include against a ShaderTree (a directory on
// disk, or the copy of shaders/ embedded in the binary) and reports errors with the file and
// line they occur in, included files too.
#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "core/error.hpp"

namespace lancer::gpu {

// Where shader files come from: name relative to the shader root -> contents.
using ShaderTree = std::function<std::optional<std::string>(const std::string& name)>;

// The files under `root`; a name that is not a regular file there (or a link to one) of at most
// 16 MiB reads as not found, at once (a FIFO does not wait for a writer).
ShaderTree directory_tree(const std::string& root);

// Files that stand in for files of a tree, by name (code generated for a scene).
using ShaderFiles = std::map<std::string, std::string>;
// `tree` with `files` in place of the files of the same names.
ShaderTree with_files(ShaderTree tree, ShaderFiles files);

struct ShaderDefine {
    std::string name;
    std::string value;
};

class ShaderCompileError : public MultiLineUserError {
public:
    using MultiLineUserError::MultiLineUserError;
};

// Compiles `entry` (e.g. "trace.comp") as a Vulkan 1.2 compute shader. Throws ShaderCompileError
// when it does not compile, with glslang's messages as "ROOT/file:line: error: ..." lines, file
// being the (possibly included) file the error is in and ROOT `display_root` when given.
std::vector<std::uint32_t> compile_compute(const ShaderTree& tree, const std::string& entry,
                                           const std::vector<ShaderDefine>& defines = {},
                                           const std::string& display_root = "");

// One member of a uniform or storage block as glslang lays it out, for layout tests.
struct ReflectedMember {
    std::string name;  // e.g. "FrameBlock.frame.eye" or "PrimitiveBlock.primitives.p0"
    int offset;
    int top_level_stride;  // for members of a runtime-sized array of structs: the struct's stride
};
std::vector<ReflectedMember> reflect_block_members(const ShaderTree& tree, const std::string& entry);

// One resource of the shader's interface as glslang reflects it, for layout tests.
struct ReflectedResource {
    std::string name;  // a block's name ("FRAME_Block") or a texel buffer's ("PRIMITIVES_texels")
    std::string kind;  // "uniform block", "storage block", "push constants", "uint texel buffer",
                       // "int texel buffer", "float texel buffer", or "other uniform" (images, ...)
    int binding;       // -1 for push constants
};
std::vector<ReflectedResource> reflect_resources(const ShaderTree& tree, const std::string& entry);

}  // namespace lancer::gpu
