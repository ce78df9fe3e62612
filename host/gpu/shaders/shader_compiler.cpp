#include "gpu/shaders/shader_compiler.hpp"

#include <algorithm>
#include <map>

#include <memory>
#include <mutex>
#include <sstream>

#include <fmt/format.h>
#include <glslang/Public/ResourceLimits.h>
#include <glslang/Public/ShaderLang.h>
#include <glslang/SPIRV/GlslangToSpv.h>

#include "core/file_reading.hpp"

namespace lancer::gpu {
namespace {

// A shader file larger than this is not read (the largest of shaders/ is about 21 KiB).
constexpr std::size_t kMaxShaderFileBytes = std::size_t{16} << 20;

void initialize_glslang() {
    static std::once_flag once;
    std::call_once(once, [] {
        glslang::InitializeProcess();
        std::atexit([] { glslang::FinalizeProcess(); });
    });
}

// Resolves "#include "x"" relative to the including file's directory within the tree. Includes
// may nest kMaxIncludeDepth deep, and no file may include itself, directly or through others:
// glslang would expand such a cycle until memory runs out. The refusal names the chain.
class TreeIncluder final : public glslang::TShader::Includer {
public:
    static constexpr std::size_t kMaxIncludeDepth = 32;

    explicit TreeIncluder(const ShaderTree& tree) : tree_(tree) {}

    IncludeResult* includeLocal(const char* header, const char* includer, size_t depth) override {
        std::string base(includer);
        auto slash = base.rfind('/');
        std::string dir = slash == std::string::npos ? "" : base.substr(0, slash + 1);
        note_includer(includer, depth);
        if (auto found = resolve(dir + header)) return found;
        return resolve(header);
    }
    IncludeResult* includeSystem(const char* header, const char* includer, size_t depth) override {
        note_includer(includer, depth);
        return resolve(header);
    }
    void releaseInclude(IncludeResult* result) override {
        if (result) {
            delete static_cast<std::string*>(result->userData);
            delete result;
        }
    }

    // Why an include was refused ("" if none was): glslang then reports only that it could not
    // be processed.
    const std::string& refusal() const { return refusal_; }

private:
    // chain_[k] is the file at inclusion depth k (0: the entry point).
    void note_includer(const char* includer, std::size_t depth) {
        chain_.resize(std::max<std::size_t>(depth, 1));
        chain_[chain_.size() - 1] = includer;
    }
    std::string chain_text(const std::string& last) const {
        std::string text;
        for (const std::string& name : chain_) text += name + " -> ";
        return text + last;
    }
    IncludeResult* resolve(const std::string& name) {
        if (!refusal_.empty()) return nullptr;
        auto text = tree_(name);
        if (!text) return nullptr;
        if (std::find(chain_.begin(), chain_.end(), name) != chain_.end()) {
            refusal_ = "#include cycle: " + chain_text(name);
            return nullptr;
        }
        if (chain_.size() >= kMaxIncludeDepth) {
            refusal_ = fmt::format("#include nested more than {} deep: {}", kMaxIncludeDepth, chain_text(name));
            return nullptr;
        }
        auto* owned = new std::string(std::move(*text));
        return new IncludeResult(name, owned->data(), owned->size(), owned);
    }
    const ShaderTree& tree_;
    std::vector<std::string> chain_;
    std::string refusal_;
};

std::string preamble(const std::vector<ShaderDefine>& defines) {
    std::string text;
    for (const auto& d : defines) text += "#define " + d.name + " " + d.value + "\n";
    return text;
}

struct Compiled {
    std::unique_ptr<glslang::TShader> shader;
    std::unique_ptr<glslang::TProgram> program;
};

// glslang says "ERROR: name:12: 'x' : undeclared identifier"; lancer says
// "root/name:12: error: 'x' : undeclared identifier", the form editors and terminals link.
std::string format_log(const std::string& log, const std::string& root) {
    std::istringstream in(log);
    std::string line, out;
    while (std::getline(in, line)) {
        if (line.empty() || line.find("compilation errors.  No code generated") != std::string::npos) continue;
        for (const char* level : {"ERROR: ", "WARNING: "}) {
            std::string tag(level);
            if (line.rfind(tag, 0) != 0) continue;
            std::string rest = line.substr(tag.size());
            // rest = "name:line: message" when the error has a location.
            auto colon = rest.find(':');
            auto second = colon == std::string::npos ? std::string::npos : rest.find(':', colon + 1);
            bool located = second != std::string::npos && second > colon + 1 &&
                           rest.find_first_not_of("0123456789", colon + 1) == second;
            std::string kind = tag == "ERROR: " ? "error" : "warning";
            if (located) {
                std::string prefix = root.empty() ? "" : root + "/";
                line = prefix + rest.substr(0, second) + ": " + kind + ":" + rest.substr(second + 1);
            } else {
                line = kind + ": " + rest;
            }
            break;
        }
        out += (out.empty() ? "" : "\n") + line;
    }
    return out.empty() ? log : out;
}

Compiled compile(const ShaderTree& tree, const std::string& entry, const std::vector<ShaderDefine>& defines,
                 const std::string& display_root) {
    initialize_glslang();
    auto source = tree(entry);
    if (!source) throw ShaderCompileError("shader '" + entry + "' not found");

    Compiled c;
    c.shader = std::make_unique<glslang::TShader>(EShLangCompute);
    const char* text = source->c_str();
    const char* name = entry.c_str();
    c.shader->setStringsWithLengthsAndNames(&text, nullptr, &name, 1);
    std::string pre = preamble(defines);
    c.shader->setPreamble(pre.c_str());
    c.shader->setEnvInput(glslang::EShSourceGlsl, EShLangCompute, glslang::EShClientVulkan, 100);
    c.shader->setEnvClient(glslang::EShClientVulkan, glslang::EShTargetVulkan_1_2);
    c.shader->setEnvTarget(glslang::EShTargetSpv, glslang::EShTargetSpv_1_5);
    TreeIncluder includer(tree);
    auto messages = static_cast<EShMessages>(EShMsgSpvRules | EShMsgVulkanRules);
    if (!c.shader->parse(GetDefaultResources(), 450, false, messages, includer)) {
        std::string log = format_log(c.shader->getInfoLog(), display_root);
        if (!includer.refusal().empty()) log += "\n" + std::string(display_root.empty() ? "" : display_root + "/") +
                                                entry + ": error: " + includer.refusal();
        throw ShaderCompileError(log);
    }
    c.program = std::make_unique<glslang::TProgram>();
    c.program->addShader(c.shader.get());
    if (!c.program->link(messages)) throw ShaderCompileError(format_log(c.program->getInfoLog(), display_root));
    return c;
}

}  // namespace

ShaderTree directory_tree(const std::string& root) {
    // The names come from #include lines and from a cache entry's manifest (spirv_cache), which
    // may name anything: a FIFO or a device there is a file not found, not a wait, and no file
    // is read past kMaxShaderFileBytes. Links are followed (the directory is the user's).
    return [root](const std::string& name) -> std::optional<std::string> {
        return read_regular_file_nonblocking(root + "/" + name, kMaxShaderFileBytes, Links::follow);
    };
}

ShaderTree with_files(ShaderTree tree, ShaderFiles files) {
    if (files.empty()) return tree;
    return [tree = std::move(tree), files = std::move(files)](const std::string& name) -> std::optional<std::string> {
        if (auto file = files.find(name); file != files.end()) return file->second;
        return tree(name);
    };
}

std::vector<std::uint32_t> compile_compute(const ShaderTree& tree, const std::string& entry,
                                           const std::vector<ShaderDefine>& defines, const std::string& display_root) {
    Compiled c = compile(tree, entry, defines, display_root);
    std::vector<std::uint32_t> spirv;
    spv::SpvBuildLogger logger;
    glslang::SpvOptions options;
    glslang::GlslangToSpv(*c.program->getIntermediate(EShLangCompute), spirv, &logger, &options);
    std::string log = logger.getAllMessages();
    if (spirv.empty()) throw ShaderCompileError("SPIR-V generation failed: " + log);
    return spirv;
}

std::vector<ReflectedMember> reflect_block_members(const ShaderTree& tree, const std::string& entry) {
    Compiled c = compile(tree, entry, {}, "");
    c.program->buildReflection(EShReflectionAllBlockVariables | EShReflectionSeparateBuffers);
    std::vector<ReflectedMember> members;
    for (int i = 0; i < c.program->getNumUniformVariables(); ++i) {
        const auto& u = c.program->getUniform(i);
        if (u.getType()->getBasicType() == glslang::EbtSampler) continue;  // not in a block (texel buffers)
        members.push_back({u.name, u.offset, 0});
    }
    for (int i = 0; i < c.program->getNumBufferVariables(); ++i) {
        const auto& b = c.program->getBufferVariable(i);
        members.push_back({b.name, b.offset, b.topLevelArrayStride});
    }
    return members;
}

std::vector<ReflectedResource> reflect_resources(const ShaderTree& tree, const std::string& entry) {
    Compiled c = compile(tree, entry, {}, "");
    c.program->buildReflection(EShReflectionSeparateBuffers);
    std::vector<ReflectedResource> resources;
    for (int i = 0; i < c.program->getNumUniformBlocks(); ++i) {
        const glslang::TObjectReflection& block = c.program->getUniformBlock(i);
        const bool push = block.getType()->getQualifier().isPushConstant();
        resources.push_back({block.name, push ? "push constants" : "uniform block", block.getBinding()});
    }
    for (int i = 0; i < c.program->getNumBufferBlocks(); ++i)
        resources.push_back({c.program->getBufferBlock(i).name, "storage block", c.program->getBufferBlock(i).getBinding()});
    for (int i = 0; i < c.program->getNumUniformVariables(); ++i) {
        const glslang::TObjectReflection& u = c.program->getUniform(i);
        const glslang::TType* type = u.getType();
        if (type->getBasicType() != glslang::EbtSampler) continue;  // a member of a uniform block
        std::string kind = "other uniform";
        if (type->getSampler().dim == glslang::EsdBuffer && !type->getSampler().isImage()) {
            switch (type->getSampler().type) {
                case glslang::EbtUint: kind = "uint texel buffer"; break;
                case glslang::EbtInt: kind = "int texel buffer"; break;
                default: kind = "float texel buffer"; break;
            }
        }
        resources.push_back({u.name, kind, u.getBinding()});
    }
    return resources;
}

}  // namespace lancer::gpu
