// `lancer diff A.png B.png`: how different two images are, with the metric the image tests use
// (PSNR, and the share of pixels off by more than a threshold), and optionally a picture of
// both side by side with their amplified difference. For comparing backends, devices, or
// lancer with POV-Ray (bench/).
#include <cstdio>
#include <memory>

#include <fmt/format.h>

#include "app/option_checks.hpp"
#include "cli/commands.hpp"
#include "image/diff.hpp"

namespace lancer {
namespace {

struct DiffCommand {
    std::string a, b, side_by_side;
    int threshold = 4;

    // a | b | 8 x |a - b|, on one row.
    static Rgb8Image three_up(const Rgb8Image& a, const Rgb8Image& b) {
        Rgb8Image d = difference_image(a, b);
        Rgb8Image out{a.width * 3, a.height, std::vector<std::uint8_t>(std::size_t(a.width) * 3 * a.height * 3)};
        const Rgb8Image* parts[] = {&a, &b, &d};
        for (int y = 0; y < a.height; ++y)
            for (int k = 0; k < 3; ++k)
                std::copy_n(parts[k]->at(0, y), a.width * 3, &out.bytes[(std::size_t(y) * out.width + k * a.width) * 3]);
        return out;
    }

    int run() const {
        if (!side_by_side.empty()) check_output_is_not_an_input(side_by_side, {a, b});
        Rgb8Image ia = read_png(a), ib = read_png(b);
        ImageDiff d = compare_images(ia, ib, threshold);
        std::printf("%s vs %s: PSNR %.2f dB, %.3f%% of pixels off by more than %d/255, largest difference %d/255\n",
                    a.c_str(), b.c_str(), d.psnr_db, 100.0 * d.fraction_over, threshold, d.max_abs);
        if (!side_by_side.empty()) write_png(side_by_side, three_up(ia, ib));
        return 0;
    }
};

}  // namespace

Subcommand add_diff_command(CLI::App& parent) {
    auto state = std::make_shared<DiffCommand>();
    CLI::App* cmd = parent.add_subcommand("diff", "Compare two PNG images (PSNR, pixels over a threshold)");
    cmd->add_option("a", state->a, "First image")->required();
    cmd->add_option("b", state->b, "Second image")->required();
    cmd->add_option("--threshold", state->threshold, "A pixel differs when a channel is off by more than this (0-255)")
        ->transform(decimal_integer())
        ->check(CLI::Range(0, 255));
    cmd->add_option("--side-by-side", state->side_by_side, "Write A | B | 8 x |A - B| to this PNG")->check(png_file_name());
    return {cmd, [state] { return state->run(); }};
}

}  // namespace lancer
