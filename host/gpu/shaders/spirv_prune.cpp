#include "gpu/shaders/spirv_prune.hpp"

#include <optional>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <unordered_set>

#include <spirv-tools/libspirv.hpp>
#include <spirv-tools/optimizer.hpp>
#include <glslang/SPIRV/spirv.hpp>

#include "gpu/shaders/spirv_passes.hpp"

namespace lancer::gpu {

namespace {

constexpr std::size_t kHeaderWords = 5;

std::uint32_t opcode_of(std::uint32_t word) { return word & spv::OpCodeMask; }
std::uint32_t length_of(std::uint32_t word) { return word >> spv::WordCountShift; }
std::uint32_t first_word(std::uint32_t length, spv::Op op) { return length << spv::WordCountShift | op; }

// One pass over the module's words: each OpSpecConstantOp whose value its constant operands
// decide alone becomes a constant (OpConstant 0, OpConstantTrue, OpConstantFalse). Definitions
// come before uses in SPIR-V, so a chain folds in one pass. Returns how many were folded.
std::size_t fold_decided_spec_ops(std::vector<std::uint32_t>& words) {
    enum class Known : std::uint8_t { zero, yes, no };
    std::unordered_map<std::uint32_t, Known> known;  // result id -> its value, where decided
    std::unordered_set<std::uint32_t> int_types;      // the ids of 32-bit OpTypeInts
    std::vector<std::uint32_t> out(words.begin(), words.begin() + kHeaderWords);
    out.reserve(words.size());
    std::size_t folded = 0;
    for (std::size_t i = kHeaderWords; i < words.size();) {
        const std::uint32_t n = length_of(words[i]);
        if (n == 0 || i + n > words.size()) throw std::runtime_error("prune_spirv: a malformed instruction");
        const std::uint32_t* ins = &words[i];
        i += n;
        const auto op = static_cast<spv::Op>(opcode_of(ins[0]));
        if (op == spv::OpTypeInt && n == 4 && ins[2] == 32) int_types.insert(ins[1]);
        if (op == spv::OpConstant && n == 4 && ins[3] == 0) known[ins[2]] = Known::zero;
        if (op == spv::OpConstantTrue) known[ins[2]] = Known::yes;
        if (op == spv::OpConstantFalse) known[ins[2]] = Known::no;
        std::optional<Known> value;
        if (op == spv::OpSpecConstantOp && n == 6) {
            const auto either = [&](Known v) {
                for (std::uint32_t operand : {ins[4], ins[5]})
                    if (auto found = known.find(operand); found != known.end() && found->second == v) return true;
                return false;
            };
            const auto spec_op = static_cast<spv::Op>(ins[3]);
            if (spec_op == spv::OpBitwiseAnd && int_types.count(ins[1]) && either(Known::zero)) value = Known::zero;
            if (spec_op == spv::OpLogicalAnd && either(Known::no)) value = Known::no;
            if (spec_op == spv::OpLogicalOr && either(Known::yes)) value = Known::yes;
        }
        if (!value) {
            out.insert(out.end(), ins, ins + n);
            continue;
        }
        const std::uint32_t type = ins[1], id = ins[2];
        known[id] = *value;
        if (*value == Known::zero) out.insert(out.end(), {first_word(4, spv::OpConstant), type, id, 0});
        else out.insert(out.end(), {first_word(3, *value == Known::yes ? spv::OpConstantTrue : spv::OpConstantFalse), type, id});
        ++folded;
    }
    words = std::move(out);
    return folded;
}

// The folding of constant expressions, then `rounds` of dead-code removal, then `flags`.
std::vector<std::uint32_t> run_passes(const std::vector<std::uint32_t>& words, int rounds,
                                      const std::vector<std::string>& flags = {}) {
    spvtools::Optimizer optimizer(SPV_ENV_VULKAN_1_2);
    std::string messages;
    optimizer.SetMessageConsumer([&](spv_message_level_t, const char*, const spv_position_t&, const char* message) {
        messages += std::string(message) + "\n";
    });
    // Folds the expressions whose operands are all constants now, as the run-time specialisation does.
    optimizer.RegisterPass(spvtools::CreateFoldSpecConstantOpAndCompositePass());
    add_dead_code_rounds(optimizer, rounds);
    if (!optimizer.RegisterPassesFromFlags(flags)) throw std::logic_error("prune_spirv: unknown passes");
    std::vector<std::uint32_t> out;
    if (!optimizer.Run(words.data(), words.size(), &out)) throw std::runtime_error("prune_spirv: " + messages);
    return out;
}

}  // namespace

std::vector<std::uint32_t> prune_spirv(const std::vector<std::uint32_t>& spirv, bool locals_to_ssa) {
    if (spirv.size() < kHeaderWords || spirv[0] != spv::MagicNumber)
        throw std::runtime_error("prune_spirv: not a SPIR-V module");
    std::vector<std::uint32_t> words = spirv;
    // Folding one expression can decide another that SPIRV-Tools then folds, and the other way round.
    while (fold_decided_spec_ops(words) > 0) words = run_passes(words, 0);
    words = run_passes(words, 2, locals_to_ssa ? kLocalVariablePasses : std::vector<std::string>{});
    spvtools::SpirvTools tools(SPV_ENV_VULKAN_1_2);
    std::string messages;
    tools.SetMessageConsumer([&](spv_message_level_t, const char*, const spv_position_t&, const char* message) {
        messages += std::string(message) + "\n";
    });
    if (!tools.Validate(words)) throw std::runtime_error("prune_spirv: the pruned module is not valid:\n" + messages);
    return words;
}

}  // namespace lancer::gpu
