// `lancer combine PART.exr... -o OUT`: the parts of a photon-mapped still rendered on several
// machines (each --pass-range A-B, written as OpenEXR) made into the one image a single machine
// would have rendered: the mean of all passes, each part weighted by its number of passes.
// The parts must cover the passes 0 to K - 1 exactly once (docs/farm.md).
#include <algorithm>
#include <cstdio>
#include <map>
#include <memory>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "cli/commands.hpp"
#include "core/error.hpp"
#include "image/image.hpp"

namespace lancer {
namespace {

struct CombineCommand {
    std::vector<std::string> parts;
    std::string output;
    std::optional<double> exposure;
    std::string tone;

    int run() const {
        if (!image_format_of(output))
            throw UserError("-o " + output + ": the name must end in .png, .exr or .pfm");
        FloatImage sum;
        ExrInfo first{};
        std::map<int, std::pair<int, std::string>> covered;  // first pass -> (count, file)
        for (std::size_t i = 0; i < parts.size(); ++i) {
            ExrInfo info;
            FloatImage part = read_exr(parts[i], &info);
            if (info.passes <= 0)
                throw UserError("'" + parts[i] + "' is not a part of a photon render (no lancerPasses attribute)");
            if (i == 0) {
                first = info;
                sum = FloatImage(part.width, part.height);
            } else if (part.width != sum.width || part.height != sum.height || info.total_passes != first.total_passes) {
                throw UserError(fmt::format("'{}' ({}x{}, {} passes in all) does not belong with '{}' ({}x{}, {} passes)",
                                            parts[i], part.width, part.height, info.total_passes, parts[0], sum.width,
                                            sum.height, first.total_passes));
            }
            for (std::size_t p = 0; p < part.pixels.size(); ++p) sum.pixels[p] += part.pixels[p] * float(info.passes);
            auto [it, fresh] = covered.emplace(info.first_pass, std::pair{info.passes, parts[i]});
            if (!fresh) throw UserError("'" + parts[i] + "' and '" + it->second.second + "' hold the same passes");
        }
        // The parts must tile 0 .. K - 1: name what is missing or rendered twice.
        int next = 0;
        std::vector<std::string> missing;
        for (const auto& [start, part] : covered) {
            if (start < next) throw UserError(fmt::format("'{}' overlaps the passes of another part", part.second));
            if (start > next) missing.push_back(fmt::format("{}-{}", next, start - 1));
            next = start + part.first;
        }
        if (next < first.total_passes) missing.push_back(fmt::format("{}-{}", next, first.total_passes - 1));
        if (!missing.empty())
            throw UserError(fmt::format("the parts do not cover every pass: passes {} are missing", fmt::join(missing, ", ")));
        for (glm::vec4& p : sum.pixels) p /= float(first.total_passes);
        ExrInfo info{0, first.total_passes, first.total_passes, first.tone};
        if (exposure) info.tone.exposure = *exposure;
        if (tone == "clamp") info.tone.tone = Tone::Clamp;
        if (tone == "reinhard") info.tone.tone = Tone::Reinhard;
        if (tone == "aces") info.tone.tone = Tone::Aces;
        write_image(output, sum, info);
        std::fprintf(stderr, "%s: %zu parts, %d passes\n", output.c_str(), parts.size(), first.total_passes);
        return 0;
    }
};

}  // namespace

Subcommand add_combine_command(CLI::App& parent) {
    auto state = std::make_shared<CombineCommand>();
    CLI::App* cmd = parent.add_subcommand("combine", "Combine the OpenEXR parts of a photon render made on several machines");
    cmd->add_option("parts", state->parts, "The parts (lancer render --pass-range A-B -o PART.exr)")->required();
    cmd->add_option("-o,--output", state->output, "The image: .png (tone-mapped as the scene says), .exr or .pfm")->required();
    cmd->add_option("--exposure", state->exposure, "Stops, instead of the scene's exposure")->check(CLI::Range(-64.0, 64.0));
    cmd->add_option("--tone", state->tone, "clamp, reinhard or aces, instead of the scene's tone curve")
        ->check(CLI::IsMember({"clamp", "reinhard", "aces"}));
    return {cmd, [state] { return state->run(); }};
}

}  // namespace lancer
