#pragma once
// The [animation] table: frames, fps, cyclic, and what moves (docs/scene-format.md, "Animation").
#include <cstddef>
#include <map>
#include <span>
#include <string>

#include <toml++/toml.h>

#include "scene/scene.hpp"
#include "scene/toml_reader.hpp"

namespace lancer {

// The names of the entries of a top-level array ([[light]], [[object]]), read as the array is:
// whole, or in batches. A name used twice is an error at its second use, so that a reference
// can never be ambiguous; so is an empty one.
class EntryNames {
public:
    explicit EntryNames(std::string what) : what_(std::move(what)) {}
    // The next entries of the array, numbered on from the last.
    void add(const toml::array& entries, const std::string& file);
    // Each name's entry.
    const std::map<std::string, std::size_t, std::less<>>& index() const { return index_; }

private:
    std::string what_;
    std::map<std::string, std::size_t, std::less<>> index_;
    std::map<std::string, int, std::less<>> first_line_;
    std::size_t count_ = 0;
};

// Reads [animation] from the scene's top-level table into scene.animation, once lights and
// objects are read (animations refer to them by name or index). Also checks that light and
// object names are unique, with or without [animation]. Errors are SceneErrors. entry_starts:
// entry i of [[object]] made scene objects [entry_starts[i], entry_starts[i + 1]) (a group, all
// its members). object_names: the objects' where they were read in batches (and checked there);
// nullptr: root's [[object]] array is read here.
void read_animation(TableReader& top, const toml::table& root, Scene& scene, std::span<const std::size_t> entry_starts,
                    const EntryNames* object_names = nullptr);

}  // namespace lancer
