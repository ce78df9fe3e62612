// POV-Ray's text object:
//   type = "text"   text = "lancer"   font = "DejaVuSans.ttf"   thickness = 0.3   offset = [0, 0]
// POV-Ray's text { ttf "font.ttf" "string" thickness, offset }: the glyphs one unit per em, the
// baseline on the x axis from the origin, their fronts in the plane z = 0, extruded along +z by
// the thickness. Each glyph's outline (quadratic or cubic Bézier contours, FreeType reads the
// font) becomes the outline of one prism for the whole string, exact on both backends.
#include <filesystem>
#include <map>
#include <mutex>
#include <string>
#include <system_error>
#include <vector>

#include <fmt/format.h>
#include <glm/mat4x4.hpp>

#include "font/text_outline.hpp"
#include "scene/limits.hpp"
#include "scene/parse_surfaces.hpp"
#include "scene/prism.hpp"

namespace lancer {
namespace {

namespace fs = std::filesystem;

// Where the system's fonts are (Debian's fonts-dejavu-core and fonts-povray put DejaVu and
// POV-Ray's own timrom.ttf, cyrvetic.ttf, crystal.ttf and povlogo.ttf under the first).
constexpr const char* kFontFolders[] = {"/usr/share/fonts", "/usr/local/share/fonts"};

// The system font of that file name (empty where none): the first in path order, so that the
// choice does not depend on the file system's order; remembered, as a scene may name it often.
fs::path find_system_font(const fs::path& name) {
    static std::mutex mutex;
    static std::map<fs::path, fs::path> known;
    const std::lock_guard<std::mutex> lock(mutex);
    if (auto k = known.find(name); k != known.end()) return k->second;
    fs::path first;
    std::error_code ec;
    for (const char* folder : kFontFolders) {
        fs::recursive_directory_iterator it(folder, fs::directory_options::skip_permission_denied, ec), end;
        for (; !ec && it != end; it.increment(ec))
            if (it->path().filename() == name && it->is_regular_file(ec) && (first.empty() || it->path() < first))
                first = it->path();
    }
    return known[name] = first;
}

// A font named in a scene: a path with a folder is the scene file's relative one; a bare file
// name is looked for beside the scene file, then among the system's fonts.
std::string find_font(TableReader& t, const std::string& name) {
    const fs::path scene_folder = fs::path(t.file().str()).parent_path();
    const fs::path named(name);
    std::error_code ec;
    if (named.is_absolute() || named.has_parent_path()) {
        const fs::path path = named.is_absolute() ? named : scene_folder / named;
        if (!fs::is_regular_file(path, ec)) t.fail("font", fmt::format("no font file '{}'", path.string()));
        return path.string();
    }
    if (fs::is_regular_file(scene_folder / named, ec)) return (scene_folder / named).string();
    const fs::path found = find_system_font(named);
    if (found.empty())
        t.fail("font", fmt::format("no font '{}' beside the scene file or among the system's fonts (/usr/share/fonts); "
                                   "DejaVu comes with Debian's fonts-dejavu-core, POV-Ray's own fonts with fonts-povray",
                                   name));
    return found.string();
}

// POV-Ray's offset: how far each glyph moves besides its advance, [x, y] in em units.
glm::dvec2 read_offset(TableReader& t) {
    const toml::array* pair = t.array("offset");
    if (!pair) return glm::dvec2(0.0);
    if (pair->size() != 2) t.fail("offset", t.what() + ": offset must be [x, y], the move between glyphs besides the advance");
    const std::string what = t.what() + " offset";
    return {node_number(*pair->get(0), t.file(), what), node_number(*pair->get(1), t.file(), what)};
}

}  // namespace

// Text is a prism (outlines in x-z, extruded along y) with its y and z swapped: the glyphs'
// (x, y) are the outline's (x, z), and the extrusion runs along +z. A mirror, so that the prism's
// texture (u, v) = (x, z) is the text's (x, y), as POV-Ray's planar image map on text.
glm::dmat4 text_frame() {
    glm::dmat4 swap(1.0);
    swap[1] = glm::dvec4(0.0, 0.0, 1.0, 0.0);  // the prism's y (the extrusion) to z
    swap[2] = glm::dvec4(0.0, 1.0, 0.0, 0.0);  // its z (the glyphs' y) to y
    return swap;
}

Shape read_text(TableReader& t, const glm::dmat4&) {
    const std::string text = t.required_string("text");
    if (text.empty()) t.fail("text", t.what() + ": the text is empty");
    const std::string font = find_font(t, t.string("font", "DejaVuSans.ttf"));
    const double thickness = t.required_number("thickness");
    if (!(thickness > 0.0)) t.fail("thickness", fmt::format("a text's thickness must be positive, not {:g}", thickness));
    const glm::dvec2 offset = read_offset(t);
    font::TextOutline outline;
    try {
        outline = font::outline_text(font, text, offset);
    } catch (const font::FontFileError& e) {
        t.fail(t.has("font") ? "font" : "text", e.what());
    } catch (const UserError& e) {
        t.fail("text", e.what());
    }
    if (outline.segments.empty()) t.fail("text", t.what() + ": the text has no glyph with an outline (only spaces?)");
    if (outline.segments.size() > limits::kMaxPrismSegments)
        t.fail("text", fmt::format("the text's outline has {} pieces; the limit is {} per text or prism",
                                   outline.segments.size(), limits::kMaxPrismSegments));
    std::vector<PrismSegment> segments;
    segments.reserve(outline.segments.size());
    for (const font::OutlineSegment& g : outline.segments) {
        PrismSegment s;
        s.degree = g.degree;
        for (int k = 0; k <= g.degree; ++k) s.p[k] = g.points[k];
        segments.push_back(s);
    }
    Prism prism;
    try {
        prism = make_prism(std::move(segments), 0.0, thickness);
    } catch (const std::invalid_argument& e) {  // a font's contour that does not close
        t.fail("text", fmt::format("{}: the font's outline cannot be extruded: {}", t.what(), e.what()));
    }
    check_world_extent(t, "offset", glm::dvec3(prism.lo.x, prism.y0, prism.lo.y), glm::dvec3(prism.hi.x, prism.y1, prism.hi.y));
    return prism;
}

}  // namespace lancer
