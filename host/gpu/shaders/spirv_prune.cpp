#include "gpu/shaders/spirv_prune.hpp"

#include <stdexcept>
#include <string>
#include <unordered_map>

#include <spirv-tools/libspirv.hpp>
#include <spirv-tools/optimizer.hpp>
#include <glslang/SPIRV/spirv.hpp>

namespace lancer::gpu {

namespace {

constexpr std::size_t kHeaderWords = 5;

std::uint32_t opcode_of(std::uint32_t first_word) { return first_word & spv::OpCodeMask; }
std::uint32_t length_of(std::uint32_t first_word) { return first_word >> spv::WordCountShift; }
std::uint32_t first_word(std::uint32_t length, spv::Op op) { return length << spv::WordCountShift | op; }

// One pass over the module's words: each OpSpecConstantOp whose value its constant operands
// decide alone becomes a constant (OpConstant 0, OpConstantTrue, OpConstantFalse). Definitions
// come before uses in SPIR-V, so a chain folds in one pass. Returns how many were folded.
std::size_t fold_decided_spec_ops(std::vector<std::uint32_t>& words) {
    enum class Known : std::uint8_t { zero, yes, no };
    std::unordered_map<std::uint32_t, Known> known;  // result id -> its decided value
    std::unordered_map<std::uint32_t, bool> int_types;  // OpTypeInt of 32 bits
    std::vector<std::uint32_t> out(words.begin(), words.begin() + kHeaderWords);
    out.reserve(words.size());
    std::size_t folded = 0;
    for (std::size_t i = kHeaderWords; i < words.size();) {
        const std::uint32_t n = length_of(words[i]);
        if (n == 0 || i + n > words.size()) throw std::runtime_error("prune_spirv: a malformed instruction");
        const std::uint32_t* ins = &words[i];
        const auto op = static_cast<spv::Op>(opcode_of(ins[0]));
        std::vector<std::uint32_t> replacement;
        if (op == spv::OpTypeInt && n == 4 && ins[2] == 32) int_types[ins[1]] = true;
        if (op == spv::OpConstant && n == 4 && ins[3] == 0) known[ins[2]] = Known::zero;
        if (op == spv::OpConstantTrue) known[ins[2]] = Known::yes;
        if (op == spv::OpConstantFalse) known[ins[2]] = Known::no;
        if (op == spv::OpSpecConstantOp && n == 6) {
            const std::uint32_t type = ins[1], id = ins[2];
            const auto is = [&](std::uint32_t operand, Known value) {
                auto found = known.find(operand);
                return found != known.end() && found->second == value;
            };
            const bool either_zero = is(ins[4], Known::zero) || is(ins[5], Known::zero);
            switch (static_cast<spv::Op>(ins[3])) {
                case spv::OpBitwiseAnd:
                    if (either_zero && int_types.count(type)) replacement = {first_word(4, spv::OpConstant), type, id, 0};
                    break;
                case spv::OpLogicalAnd:
                    if (is(ins[4], Known::no) || is(ins[5], Known::no))
                        replacement = {first_word(3, spv::OpConstantFalse), type, id};
                    break;
                case spv::OpLogicalOr:
                    if (is(ins[4], Known::yes) || is(ins[5], Known::yes))
                        replacement = {first_word(3, spv::OpConstantTrue), type, id};
                    break;
                default:
                    break;
            }
        }
        if (replacement.empty()) {
            out.insert(out.end(), ins, ins + n);
        } else {
            known[replacement[2]] = opcode_of(replacement[0]) == spv::OpConstant ? Known::zero
                                    : opcode_of(replacement[0]) == spv::OpConstantTrue ? Known::yes
                                                                                      : Known::no;
            out.insert(out.end(), replacement.begin(), replacement.end());
            ++folded;
        }
        i += n;
    }
    words = std::move(out);
    return folded;
}

std::vector<std::uint32_t> run_passes(const std::vector<std::uint32_t>& words, bool remove_dead_code) {
    spvtools::Optimizer optimizer(SPV_ENV_VULKAN_1_2);
    std::string messages;
    optimizer.SetMessageConsumer([&](spv_message_level_t, const char*, const spv_position_t&, const char* message) {
        messages += std::string(message) + "\n";
    });
    // Folds the expressions whose operands are all constants now, as the run-time specialisation does.
    optimizer.RegisterPass(spvtools::CreateFoldSpecConstantOpAndCompositePass());
    if (remove_dead_code)
        for (int round = 0; round < 2; ++round)  // as in specialize_spirv: merged blocks expose more dead branches
            optimizer.RegisterPass(spvtools::CreateDeadBranchElimPass())
                .RegisterPass(spvtools::CreateAggressiveDCEPass())
                .RegisterPass(spvtools::CreateEliminateDeadFunctionsPass())
                .RegisterPass(spvtools::CreateBlockMergePass());
    std::vector<std::uint32_t> out;
    if (!optimizer.Run(words.data(), words.size(), &out)) throw std::runtime_error("prune_spirv: " + messages);
    return out;
}

}  // namespace

std::vector<std::uint32_t> prune_spirv(const std::vector<std::uint32_t>& spirv) {
    if (spirv.size() < kHeaderWords || spirv[0] != spv::MagicNumber)
        throw std::runtime_error("prune_spirv: not a SPIR-V module");
    std::vector<std::uint32_t> words = spirv;
    // Folding one expression can decide another that SPIRV-Tools then folds, and the other way round.
    while (fold_decided_spec_ops(words) > 0) words = run_passes(words, false);
    words = run_passes(words, true);
    spvtools::SpirvTools tools(SPV_ENV_VULKAN_1_2);
    std::string messages;
    tools.SetMessageConsumer([&](spv_message_level_t, const char*, const spv_position_t&, const char* message) {
        messages += std::string(message) + "\n";
    });
    if (!tools.Validate(words)) throw std::runtime_error("prune_spirv: the pruned module is not valid:\n" + messages);
    return words;
}

}  // namespace lancer::gpu
