#include "fuzz/toml_tree_difference.hpp"

#include <cstring>
#include <sstream>
#include <type_traits>

#include <fmt/format.h>

namespace lancer::fuzz {
namespace {

std::string position_text(const toml::source_position& p) { return fmt::format("{}:{}", p.line, p.column); }

std::string region_text(const toml::source_region& r, const std::string* root_path) {
    return fmt::format("{}-{} in {}{}", position_text(r.begin), position_text(r.end), r.path ? *r.path : std::string("(none)"),
                       r.path.get() == root_path ? "" : " (not the root's)");
}

// Compares regions, each tree's path judged against its root's.
std::string region_difference(const toml::source_region& e, const toml::source_region& a, const std::string* e_root,
                              const std::string* a_root, const std::string& where) {
    const std::string et = region_text(e, e_root), at = region_text(a, a_root);
    if (et == at) return "";
    return fmt::format("{}: source {} read, {} expected", where, at, et);
}

template <class T>
std::string scalar_difference(const toml::node& e, const toml::node& a, const std::string& where) {
    const auto& ev = *e.as<T>();
    const auto& av = *a.as<T>();
    if (ev.flags() != av.flags()) return where + ": value flags differ";
    bool same;
    if constexpr (std::is_same_v<T, double>) {
        same = std::memcmp(&ev.get(), &av.get(), sizeof(double)) == 0;  // -0.0 and NaN's bits count
    } else {
        same = ev.get() == av.get();
    }
    if (same) return "";
    std::ostringstream o;
    o << where << ": " << av << " read, " << ev << " expected";
    return o.str();
}

struct Roots {
    const std::string* expected;
    const std::string* actual;
};

std::string node_difference(const toml::node& e, const toml::node& a, const Roots& roots, const std::string& where) {
    if (e.type() != a.type()) {
        std::ostringstream o;
        o << where << ": " << a.type() << " read, " << e.type() << " expected";
        return o.str();
    }
    if (std::string d = region_difference(e.source(), a.source(), roots.expected, roots.actual, where); !d.empty()) return d;
    switch (e.type()) {
        case toml::node_type::table: {
            const toml::table& et = *e.as_table();
            const toml::table& at = *a.as_table();
            if (et.is_inline() != at.is_inline()) return where + ": inline differs";
            if (et.size() != at.size()) return fmt::format("{}: {} keys read, {} expected", where, at.size(), et.size());
            for (auto ei = et.begin(), ai = at.begin(); ei != et.end(); ++ei, ++ai) {
                const std::string key_where = where + "." + std::string(ei->first.str());
                if (ei->first.str() != ai->first.str()) return fmt::format("{}: key '{}' read instead", key_where, ai->first.str());
                if (std::string d = region_difference(ei->first.source(), ai->first.source(), roots.expected, roots.actual, key_where + " (key)");
                    !d.empty())
                    return d;
                if (std::string d = node_difference(ei->second, ai->second, roots, key_where); !d.empty()) return d;
            }
            return "";
        }
        case toml::node_type::array: {
            const toml::array& ea = *e.as_array();
            const toml::array& aa = *a.as_array();
            if (ea.size() != aa.size()) return fmt::format("{}: {} values read, {} expected", where, aa.size(), ea.size());
            for (std::size_t i = 0; i < ea.size(); ++i)
                if (std::string d = node_difference(ea[i], aa[i], roots, fmt::format("{}[{}]", where, i)); !d.empty()) return d;
            return "";
        }
        case toml::node_type::string: return scalar_difference<std::string>(e, a, where);
        case toml::node_type::integer: return scalar_difference<std::int64_t>(e, a, where);
        case toml::node_type::floating_point: return scalar_difference<double>(e, a, where);
        case toml::node_type::boolean: return scalar_difference<bool>(e, a, where);
        case toml::node_type::date: return scalar_difference<toml::date>(e, a, where);
        case toml::node_type::time: return scalar_difference<toml::time>(e, a, where);
        case toml::node_type::date_time: return scalar_difference<toml::date_time>(e, a, where);
        default: return where + ": a node of no type";
    }
}

}  // namespace

std::string toml_tree_difference(const toml::table& expected, const toml::table& actual) {
    return node_difference(expected, actual, {expected.source().path.get(), actual.source().path.get()}, "(root)");
}

}  // namespace lancer::fuzz
