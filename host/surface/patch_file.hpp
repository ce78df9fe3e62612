#pragma once
// Reading Bezier patch sets from text files. Two formats, recognised by content:
//
// (a) BPT (as used by e.g. mkeeter/teapot-mrep):
//         32                 the patch count
//         3 3                per patch: the degrees in u and v (only "3 3", bicubic, is supported)
//         1.4 0.0 2.4        ...then 16 control points, one per line: x y z [w]
//         ...                row-major: line 4*i + j of the patch is P_ij, i along u, j along v.
//     The optional 4th number is the weight of a rational patch (default 1; must be > 0).
//
// (b) The indexed Newell format (as in S. Baker's teaset data):
//         32                 the patch count
//         1, 2, 3, 4, ...    per patch a line of 16 1-based vertex indices, row-major as above
//         306                the vertex count
//         1.4, 0.0, 2.4      per vertex a line x, y, z
//
// Common rules: '#' starts a comment that runs to the end of the line, anywhere. Numbers are
// separated by whitespace and/or commas (both formats accept both). Blank lines are ignored;
// otherwise every record is one line. The line after the patch count decides the format: two
// numbers (degrees) mean BPT, anything with a comma or more than two numbers means Newell.
// Nothing may follow the last record. Limits: at most kMaxPatchesPerFile patches and
// kMaxVerticesPerFile vertices, checked before anything is allocated; coordinates must be finite.
//
// Every problem (unreadable file, truncated file, wrong degree, not a number, NaN or infinity,
// index out of range, a count over its limit...) is a lancer::SceneError at file:line:col.
#include <string>
#include <string_view>
#include <vector>

#include "surface/bezier_patch.hpp"

namespace lancer::surface {

constexpr long long kMaxPatchesPerFile = 1 << 16;
constexpr long long kMaxVerticesPerFile = 1 << 20;
constexpr long long kMaxPatchFileBytes = 256LL << 20;

std::vector<BezierPatch> read_patch_file(const std::string& path);

// The same, from text already in memory; file_name is only used in error locations.
std::vector<BezierPatch> parse_patch_text(std::string_view text, const std::string& file_name);

}  // namespace lancer::surface
