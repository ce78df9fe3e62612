#pragma once
// Checks of command-line values shared by the commands (render, watch, view, diff, combine), as
// CLI11 validators: a value they refuse is one message, "--option: why", and exit code 2.
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

namespace lancer {

// An integer written in plain decimal digits (a leading minus allowed). CLI11 itself reads
// integers with strtoll's base 0, so "0x10" would be 16 and "010" 8, while "1e3" is refused
// with a message about the range; this says what is expected instead, and strips leading zeros
// so that the value is read as decimal. Add it with Option::transform (check() would not let
// it change the value; a transform also runs before the checks, such as CLI::Range).
CLI::Validator decimal_integer();

// An exposure in stops: a finite number within +-kMaxExposureStops (image/tone.hpp).
// (CLI::Range lets NaN through: every comparison with it is false.)
CLI::Validator exposure_stops();

// A value that must not be empty ('' on a command line would otherwise mean "not given"):
// "empty: EXPECTED".
CLI::Validator not_empty(const std::string& expected);

// An output file written as PNG: the name must end in .png.
CLI::Validator png_file_name();

// Refuses to write `output` over one of `inputs` (the same file by any name: hard links,
// symbolic links, ./a.png and a.png): "cannot write 'OUT': it is the input 'IN'".
void check_output_is_not_an_input(const std::string& output, const std::vector<std::string>& inputs);

}  // namespace lancer
