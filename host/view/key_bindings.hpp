#pragma once
// The viewer's keys and mouse, as the on-screen help (h) lists them. docs/viewer.md's table says the
// same, and a test checks that it names every key listed here.
#include <string>
#include <vector>

namespace lancer::view {

struct KeyHelp {
    std::string keys;    // "q / d"
    std::string action;  // "orbit around the look-at point, left / right"
};

const std::vector<KeyHelp>& key_help();

}  // namespace lancer::view
