#include "scene/repeat.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "scene/scene_values.hpp"

namespace lancer {

void read_repeated(TableReader& t, const std::function<void(double copies, const std::function<void(const std::string&)>& fail)>& admit,
                   const std::function<void(TableReader&)>& body) {
    const toml::table* repeat = t.table("repeat");
    if (!repeat) return body(t);
    TableReader r(*repeat, t.file(), t.what() + " repeat");
    if (repeat->size() != 1) t.fail("repeat", "repeat takes one index: repeat = { i = [first, last] }");
    const std::string index(repeat->cbegin()->first.str());
    SceneValues& values = *current_scene_values();
    values.check_new_name(index, r.location(index), "repeat index");
    const toml::array* bounds = r.array(index);
    if (!bounds || bounds->size() != 2) r.fail(index, fmt::format("repeat = {{ {} = [first, last] }}: two whole numbers", index));
    const double first = node_number(*bounds->get(0), t.file(), index + "[0]"), last = node_number(*bounds->get(1), t.file(), index + "[1]");
    if (first != std::floor(first) || last != std::floor(last))
        r.fail(index, fmt::format("a repeat's first and last are whole numbers, not {:g} and {:g}", first, last));
    const double copies = std::max(0.0, last - first + 1.0);
    admit(copies, [&](const std::string& message) {
        r.fail(index, fmt::format("repeat {} from {:g} to {:g}: {:g} copies, {}", index, first, last, copies, message));
    });
    for (double i = first; i <= last; ++i) {
        values.bind(index, i);
        TableReader again(t.table(), t.file(), fmt::format("{} ({} = {:g})", t.what(), index, i));
        again.accept("repeat");
        body(again);
    }
    values.unbind(index);
    t.accept("repeat");
}

}  // namespace lancer
