#include "app/option_checks.hpp"

#include <cmath>
#include <filesystem>

#include <fmt/format.h>

#include "core/error.hpp"
#include "image/image.hpp"
#include "image/tone.hpp"

namespace lancer {

CLI::Validator decimal_integer() {
    return CLI::Validator(
        [](std::string& text) -> std::string {
            const std::size_t sign = !text.empty() && text[0] == '-' ? 1 : 0;
            bool digits = text.size() > sign;
            for (std::size_t i = sign; i < text.size(); ++i)
                digits = digits && text[i] >= '0' && text[i] <= '9';
            if (!digits) return "'" + text + "' is not a whole number: write it in decimal digits";
            const std::size_t first = text.find_first_not_of('0', sign);
            text = first == std::string::npos ? "0" : text.substr(0, sign) + text.substr(first);
            return "";
        },
        "INT");
}

CLI::Validator exposure_stops() {
    return CLI::Validator(
        [](std::string& text) -> std::string {
            double v = 0.0;
            if (!CLI::detail::lexical_cast(text, v)) return "'" + text + "' is not a number";
            if (!(std::isfinite(v) && std::abs(v) <= kMaxExposureStops))
                return fmt::format("the exposure must be a finite number of stops in [-{0}, {0}], not {1}",
                                   kMaxExposureStops, text);
            return "";
        },
        "STOPS");
}

CLI::Validator not_empty(const std::string& expected) {
    return CLI::Validator([expected](std::string& text) -> std::string { return text.empty() ? "empty: " + expected : ""; },
                          "");
}

CLI::Validator png_file_name() {
    return CLI::Validator(
        [](std::string& text) -> std::string {
            if (text.empty()) return "the output file name is empty";
            if (image_format_of(text) != ImageFormat::Png) return "'" + text + "': a PNG image is written, so the name must end in .png";
            return "";
        },
        "FILE.png");
}

void check_output_is_not_an_input(const std::string& output, const std::vector<std::string>& inputs) {
    for (const std::string& input : inputs) {
        std::error_code ec;
        if (std::filesystem::equivalent(output, input, ec) && !ec)
            throw UserError(output == input ? fmt::format("cannot write '{}': it is an input of this command", output)
                                            : fmt::format("cannot write '{}': it is the input '{}'", output, input));
    }
}

}  // namespace lancer
