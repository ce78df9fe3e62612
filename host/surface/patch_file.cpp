#include "surface/patch_file.hpp"

#include <cerrno>
#include <algorithm>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "surface/patch_file_lexer.hpp"

namespace lancer::surface {
namespace {

using detail::PatchLexer;
using detail::Record;
using detail::Token;

// Message text from pieces (this library depends on lancer_core and glm only, not on fmt).
template <class... Parts>
std::string cat(const Parts&... parts) {
    std::ostringstream out;
    (out << ... << parts);
    return out.str();
}

// A count on a line of its own: a whole number in [1, limit], checked before anything is sized by it.
long long read_count(PatchLexer& lex, const std::string& what, long long limit, const std::string& expected) {
    const Record& r = lex.next(expected);
    const Token& t = r.tokens[0];
    long long n = lex.whole_number(t, what);
    if (n < 1) lex.fail(t, cat(what, " must be at least 1, not ", n));
    if (n > limit) lex.fail(t, cat(what, " ", n, " exceeds the limit of ", limit));
    if (r.tokens.size() > 1) lex.fail(r.tokens[1], cat("expected only the ", what, " on this line"));
    return n;
}

double read_weight(PatchLexer& lex, const Token& t) {
    double w = lex.finite_number(t, "weight");
    if (!(w > 0.0)) lex.fail(t, cat("weight must be positive, not ", t.text));
    return w;
}

// Room for `count` records of `lines` lines each, but no more than the file has: a short file
// that declares many of them must not cost memory it does not hold.
std::size_t capacity_for(const PatchLexer& lex, long long count, std::size_t lines) {
    return std::min(static_cast<std::size_t>(count), lex.records_left() / lines + 1);
}

std::vector<BezierPatch> read_bpt(PatchLexer& lex, long long count) {
    std::vector<BezierPatch> patches;
    patches.reserve(capacity_for(lex, count, 17));
    for (long long k = 0; k < count; ++k) {
        const std::string early = cat("expected ", count, " patches, found ", k);
        const Record& deg = lex.next(early);
        for (std::size_t i = 0; i < deg.tokens.size(); ++i) {
            const Token& t = deg.tokens[i];
            if (i >= 2) lex.fail(t, "expected only the degrees 'm n' on this line");
            if (lex.whole_number(t, "patch degree") != 3)
                lex.fail(t, cat("only bicubic patches are supported (degrees '3 3'), not degree ", t.text));
        }
        if (deg.tokens.size() < 2) lex.fail_at_end_of(deg, "expected two degrees 'm n' (only '3 3' is supported)");

        BezierPatch p;
        for (int i = 0; i < 16; ++i) {
            const Record& r = lex.next(cat(early, " (patch ", k + 1, " has ", i, " of its 16 control points)"));
            const auto& tok = r.tokens;
            if (tok.size() < 3)
                lex.fail_at_end_of(
                    r, cat("a control point needs 3 coordinates 'x y z' (and an optional weight), found ", tok.size()));
            if (tok.size() > 4) lex.fail(tok[4], "too many numbers for a control point: expected 'x y z' or 'x y z w'");
            for (int c = 0; c < 3; ++c) p.points[i][c] = lex.finite_number(tok[c], "control point coordinate");
            if (tok.size() == 4) p.weights[i] = read_weight(lex, tok[3]);
        }
        patches.push_back(p);
    }
    return patches;
}

std::vector<BezierPatch> read_newell(PatchLexer& lex, long long count) {
    // Indices are range-checked once the vertex count is known; keep their tokens for the message.
    std::vector<std::array<Token, 16>> index_tokens;
    std::vector<std::array<long long, 16>> indices;
    index_tokens.reserve(capacity_for(lex, count, 1));
    indices.reserve(capacity_for(lex, count, 1));
    for (long long k = 0; k < count; ++k) {
        const Record& r = lex.next(cat("expected ", count, " patches, found ", k));
        if (r.tokens.size() < 16)
            lex.fail_at_end_of(r, cat("a patch needs 16 vertex indices, found ", r.tokens.size()));
        if (r.tokens.size() > 16) lex.fail(r.tokens[16], "too many vertex indices: a patch has 16");
        std::array<Token, 16>& tokens = index_tokens.emplace_back();
        std::array<long long, 16>& numbers = indices.emplace_back();
        for (int i = 0; i < 16; ++i) {
            tokens[i] = r.tokens[i];
            numbers[i] = lex.whole_number(r.tokens[i], "vertex index");
        }
    }
    long long vertex_count = read_count(lex, "vertex count", kMaxVerticesPerFile,
                                        cat("expected the vertex count after the ", count, " patches"));
    std::vector<dvec3> vertices;
    vertices.reserve(capacity_for(lex, vertex_count, 1));
    for (long long k = 0; k < vertex_count; ++k) {
        const Record& r = lex.next(cat("expected ", vertex_count, " vertices, found ", k));
        if (r.tokens.size() < 3)
            lex.fail_at_end_of(r, cat("a vertex needs 3 coordinates 'x, y, z', found ", r.tokens.size()));
        if (r.tokens.size() > 3) lex.fail(r.tokens[3], "too many numbers for a vertex: expected 'x, y, z'");
        dvec3 v;
        for (int c = 0; c < 3; ++c) v[c] = lex.finite_number(r.tokens[c], "vertex coordinate");
        vertices.push_back(v);
    }

    std::vector<BezierPatch> patches(static_cast<std::size_t>(count));
    for (long long k = 0; k < count; ++k)
        for (int i = 0; i < 16; ++i) {
            long long idx = indices[k][i];
            if (idx < 1 || idx > vertex_count)
                lex.fail(index_tokens[k][i], cat("vertex index ", idx, " is out of range: the file has ", vertex_count,
                                                 " vertices (indices start at 1)"));
            patches[k].points[i] = vertices[static_cast<std::size_t>(idx - 1)];
        }
    return patches;
}

}  // namespace

std::vector<BezierPatch> parse_patch_text(std::string_view text, const std::string& file_name) {
    PatchLexer lex(text, file_name);
    long long count = read_count(lex, "patch count", kMaxPatchesPerFile, "expected the patch count");
    const Record& second = lex.next(cat("expected ", count, " patches, found 0"));
    const bool newell = second.has_comma || second.tokens.size() > 2;
    lex.unread();
    std::vector<BezierPatch> patches = newell ? read_newell(lex, count) : read_bpt(lex, count);
    if (!lex.at_end())
        lex.fail(lex.peek().tokens[0], cat("unexpected text after the last ", newell ? "vertex" : "patch",
                                           ": the file declares ", count, " patches"));
    return patches;
}

std::vector<BezierPatch> read_patch_file(const std::string& path) {
    std::error_code ec;
    auto status = std::filesystem::status(path, ec);
    // Line 0: the file as a whole; the scene loader puts these reasons after the file's name.
    if (ec) throw SceneError({path, 0, 0}, ec.message());
    if (std::filesystem::is_directory(status)) throw SceneError({path, 0, 0}, "it is a directory");
    if (!std::filesystem::is_regular_file(status)) throw SceneError({path, 0, 0}, "not a regular file");
    auto size = std::filesystem::file_size(path, ec);
    if (!ec && size > static_cast<std::uintmax_t>(kMaxPatchFileBytes))
        throw SceneError({path, 0, 0},
                         cat("it is larger than the limit of ", kMaxPatchFileBytes >> 20, " MiB"));
    std::ifstream in(path, std::ios::binary);
    if (!in) throw SceneError({path, 0, 0}, std::strerror(errno));
    std::ostringstream text;
    text << in.rdbuf();
    if (in.bad()) throw SceneError({path, 0, 0}, "read error");
    return parse_patch_text(text.str(), path);
}

}  // namespace lancer::surface
