// `lancer combine PART.exr... -o OUT`: the parts of a photon-mapped still rendered on several
// machines (each --pass-range A-B, written as OpenEXR) made into the one image a single machine
// would have rendered: the mean of all passes, each part weighted by its number of passes.
// The parts must cover the passes 0 to K - 1 exactly once, and be parts of one render: the same
// stamp (the scene's files and the settings that determine the pixels), exposure and tone curve
// (docs/farm.md).
#include <algorithm>
#include <cstdio>
#include <map>
#include <memory>
#include <sstream>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "app/option_checks.hpp"
#include "cli/commands.hpp"
#include "core/error.hpp"
#include "image/image.hpp"
#include "scene/limits.hpp"

namespace lancer {
namespace {

const char* const kToneNames[] = {"clamp", "reinhard", "aces"};

// The pass attributes, checked before any arithmetic on them (a forged file may hold any int).
void check_passes(const std::string& file, const ExrInfo& info) {
    if (info.passes == 0 && info.first_pass == 0 && info.total_passes == 0)
        throw UserError("'" + file + "' is not a part of a photon render (no lancerPasses attribute)");
    if (info.total_passes < 1 || info.total_passes > limits::kMaxPhotonPasses || info.passes < 1 || info.first_pass < 0 ||
        static_cast<long long>(info.first_pass) + info.passes > info.total_passes)
        throw UserError(fmt::format("'{}' claims passes {} to {} of {}: a part holds 1 or more of the passes 0 to K - 1, "
                                    "K at most {}",
                                    file, info.first_pass, static_cast<long long>(info.first_pass) + info.passes - 1,
                                    info.total_passes, limits::kMaxPhotonPasses));
}

// "name value" lines -> name -> value (the stamp's settings).
std::map<std::string, std::string> settings_lines(const std::string& text) {
    std::map<std::string, std::string> lines;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);) {
        const std::size_t space = line.find(' ');
        lines[line.substr(0, space)] = space == std::string::npos ? "" : line.substr(space + 1);
    }
    return lines;
}

// Why two parts' stamps say they are parts of different renders; empty when they agree.
std::string stamp_difference(const ExrInfo& a, const ExrInfo& b) {
    std::vector<std::string> differences;
    const auto la = settings_lines(a.settings), lb = settings_lines(b.settings);
    for (const auto& [name, value] : la) {
        auto other = lb.find(name);
        if (other == lb.end()) differences.push_back(fmt::format("{} {} against none", name, value));
        else if (other->second != value) differences.push_back(fmt::format("{} {} against {}", name, value, other->second));
    }
    for (const auto& [name, value] : lb)
        if (!la.count(name)) differences.push_back(fmt::format("{} none against {}", name, value));
    if (a.scene_hash != b.scene_hash)
        differences.push_back(fmt::format("the scene or a file it reads differs (hash {} against {})", a.scene_hash, b.scene_hash));
    return fmt::format("{}", fmt::join(differences, "; "));
}

struct CombineCommand {
    std::vector<std::string> parts;
    std::string output;
    std::optional<double> exposure;
    std::string tone;

    int run() const {
        if (!image_format_of(output))
            throw UserError("-o " + output + ": the name must end in .png, .exr or .pfm");
        check_output_is_not_an_input(output, parts);
        FloatImage sum;
        ExrInfo first{};
        std::map<int, std::pair<int, std::string>> covered;  // first pass -> (count, file)
        for (std::size_t i = 0; i < parts.size(); ++i) {
            ExrInfo info;
            FloatImage part = read_exr(parts[i], &info);
            check_passes(parts[i], info);
            if (info.scene_hash.empty() || info.settings.empty())
                throw UserError("'" + parts[i] + "' has no stamp of its render (lancerSceneHash, lancerSettings): render it "
                                "again with this lancer");
            if (i == 0) {
                first = info;
                sum = FloatImage(part.width, part.height);
            } else if (part.width != sum.width || part.height != sum.height || info.total_passes != first.total_passes) {
                throw UserError(fmt::format("'{}' ({}x{}, {} passes in all) does not belong with '{}' ({}x{}, {} passes)",
                                            parts[i], part.width, part.height, info.total_passes, parts[0], sum.width,
                                            sum.height, first.total_passes));
            } else if (std::string why = stamp_difference(info, first); !why.empty()) {
                throw UserError(fmt::format("'{}' and '{}' are parts of different renders: {}", parts[i], parts[0], why));
            } else if (info.tone.exposure != first.tone.exposure || info.tone.tone != first.tone.tone ||
                       info.tone.assumed_gamma != first.tone.assumed_gamma) {
                throw UserError(fmt::format("'{}' (exposure {}, tone {}, assumed gamma {}) and '{}' (exposure {}, tone {}, "
                                            "assumed gamma {}) disagree on the picture's exposure, tone curve or gamma",
                                            parts[i], info.tone.exposure, kToneNames[int(info.tone.tone)],
                                            info.tone.assumed_gamma, parts[0], first.tone.exposure,
                                            kToneNames[int(first.tone.tone)], first.tone.assumed_gamma));
            }
            for (std::size_t p = 0; p < part.pixels.size(); ++p) sum.pixels[p] += part.pixels[p] * float(info.passes);
            auto [it, fresh] = covered.emplace(info.first_pass, std::pair{info.passes, parts[i]});
            if (!fresh) throw UserError("'" + parts[i] + "' and '" + it->second.second + "' hold the same passes");
        }
        // The parts must tile 0 .. K - 1: name what is missing or rendered twice. (check_passes
        // bounds every number by K <= kMaxPhotonPasses: no sum here overflows.)
        long long next = 0;
        std::vector<std::string> missing;
        for (const auto& [start, part] : covered) {
            if (start < next) throw UserError(fmt::format("'{}' overlaps the passes of another part", part.second));
            if (start > next) missing.push_back(fmt::format("{}-{}", next, start - 1));
            next = static_cast<long long>(start) + part.first;
        }
        if (next < first.total_passes) missing.push_back(fmt::format("{}-{}", next, first.total_passes - 1));
        if (!missing.empty())
            throw UserError(fmt::format("the parts do not cover every pass: passes {} are missing", fmt::join(missing, ", ")));
        for (glm::vec4& p : sum.pixels) p /= float(first.total_passes);
        ExrInfo info = first;
        info.first_pass = 0;
        info.passes = first.total_passes;
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
    cmd->add_option("--exposure", state->exposure, "Stops, instead of the scene's exposure (-64 to 64)")->check(exposure_stops());
    cmd->add_option("--tone", state->tone, "clamp, reinhard or aces, instead of the scene's tone curve")
        ->check(CLI::IsMember({"clamp", "reinhard", "aces"}));
    return {cmd, [state] { return state->run(); }};
}

}  // namespace lancer
