#include "gpu/shaders/spirv_cache.hpp"

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <sstream>

#include <glslang/build_info.h>

#include <fmt/format.h>

#include "core/error.hpp"
#include "gpu/shaders/spirv_specialize.hpp"
#include "image/image.hpp"

namespace lancer::gpu {
namespace {

// An entry: this header, then the specialised module's words.
struct EntryHeader {
    char magic[8];                 // kMagic: also versions the entry format
    std::uint64_t input_hash;      // of the unspecialised module
    std::uint64_t features;        // a hash of every LANCER_FEATURES value, in table order
    std::uint64_t recipe_hash;     // of spirv_recipe(cleanup): the passes run
    std::uint64_t words;           // the module's length
    std::uint64_t output_hash;     // of the module's words: a torn or damaged file does not match
};
constexpr char kMagic[8] = {'l', 'a', 'n', 'c', 's', 'p', 'v', '2'};

// Entries kept: editing shaders (lancer watch, view) makes a new one per edit, and each is
// 50-200 KiB; the least recently written go first.
constexpr std::size_t kMaxEntries = 256;

// FNV-1a over 64 bits: enough to tell modules and sources apart, cheap next to the optimizer
// and the compiler it saves.
std::uint64_t hash_bytes(const void* data, std::size_t size, std::uint64_t h = 14695981039346656037ull) {
    const auto* bytes = static_cast<const unsigned char*>(data);
    for (std::size_t i = 0; i < size; ++i) {
        h ^= bytes[i];
        h *= 1099511628211ull;
    }
    return h;
}

std::uint64_t hash_words(const std::vector<std::uint32_t>& words) {
    return hash_bytes(words.data(), words.size() * sizeof(std::uint32_t));
}

std::uint64_t hash_text(const std::string& text, std::uint64_t h = 14695981039346656037ull) {
    return hash_bytes(text.data(), text.size() + 1, h);  // the terminator separates consecutive texts
}

std::uint64_t feature_key(const ShaderFeatures& features) {
    std::uint64_t h = 14695981039346656037ull;
    for (std::size_t i = 0; i < kFeatureCount; ++i) {
        const std::uint32_t value = feature_value(features, i);
        h = hash_bytes(&value, sizeof value, h);
    }
    return h;
}

bool is_set(const char* name) {
    const char* v = std::getenv(name);
    return v && (std::strcmp(v, "1") == 0 || std::strcmp(v, "true") == 0);
}

std::optional<std::vector<std::uint32_t>> read_entry(const std::string& path, const EntryHeader& wanted) {
    std::ifstream in(path, std::ios::binary);
    EntryHeader header{};
    if (!in.read(reinterpret_cast<char*>(&header), sizeof header)) return std::nullopt;
    if (std::memcmp(header.magic, kMagic, sizeof kMagic) != 0 || header.input_hash != wanted.input_hash ||
        header.features != wanted.features || header.recipe_hash != wanted.recipe_hash || header.words == 0 || header.words > (std::uint64_t{1} << 24))
        return std::nullopt;
    std::vector<std::uint32_t> words(header.words);
    if (!in.read(reinterpret_cast<char*>(words.data()), std::streamsize(words.size() * sizeof(std::uint32_t))))
        return std::nullopt;
    if (hash_words(words) != header.output_hash) return std::nullopt;
    return words;
}

void evict_oldest(const std::filesystem::path& dir) {
    namespace fs = std::filesystem;
    std::error_code ec;
    std::vector<std::pair<fs::file_time_type, fs::path>> entries;
    for (const auto& e : fs::directory_iterator(dir, ec))
        if (e.path().extension() == ".spv") entries.emplace_back(e.last_write_time(ec), e.path());
    if (entries.size() <= kMaxEntries) return;
    std::sort(entries.begin(), entries.end());
    for (std::size_t i = 0; i + kMaxEntries < entries.size(); ++i) fs::remove(entries[i].second, ec);
}

void write_bytes(const std::string& path, const std::vector<char>& bytes) {
    try {
        std::filesystem::create_directories(std::filesystem::path(path).parent_path());
        write_file_atomically(path, bytes.data(), bytes.size());
    } catch (const std::exception&) {
        // A read-only home or a full disk: the next run specialises again, nothing worse.
        return;
    }
    evict_oldest(std::filesystem::path(path).parent_path());
}

void write_entry(const std::string& path, EntryHeader header, const std::vector<std::uint32_t>& words) {
    header.words = words.size();
    header.output_hash = hash_words(words);
    std::vector<char> bytes(sizeof header + words.size() * sizeof(std::uint32_t));
    std::memcpy(bytes.data(), &header, sizeof header);
    std::memcpy(bytes.data() + sizeof header, words.data(), words.size() * sizeof(std::uint32_t));
    write_bytes(path, bytes);
}

// A compiled entry: this header, a manifest of every file the compile looked up, found or not
// ("HASH NAME" lines, HASH of the contents in hex, 0 for a file not found), then the words.
struct CompiledHeader {
    char magic[8];
    std::uint64_t key;  // of the compiler's version, the entry point and its text, the defines
    std::uint64_t manifest_bytes;
    std::uint64_t words;
    std::uint64_t output_hash;  // of the manifest and the words
};
constexpr char kCompiledMagic[8] = {'l', 'a', 'n', 'c', 'g', 'l', 's', '1'};

std::uint64_t contents_hash(const std::optional<std::string>& contents) {
    return contents ? hash_text(*contents) | 1u : 0;  // never 0 for a file that exists
}

// The module of a compile whose files all read as they did then; nullopt for anything else.
std::optional<std::vector<std::uint32_t>> read_compiled(const std::string& path, std::uint64_t key,
                                                        const ShaderTree& tree) {
    std::ifstream in(path, std::ios::binary);
    CompiledHeader header{};
    if (!in.read(reinterpret_cast<char*>(&header), sizeof header)) return std::nullopt;
    if (std::memcmp(header.magic, kCompiledMagic, sizeof kCompiledMagic) != 0 || header.key != key ||
        header.manifest_bytes > (std::uint64_t{1} << 20) || header.words == 0 || header.words > (std::uint64_t{1} << 24))
        return std::nullopt;
    std::string manifest(header.manifest_bytes, '\0');
    std::vector<std::uint32_t> words(header.words);
    if (!in.read(manifest.data(), std::streamsize(manifest.size())) ||
        !in.read(reinterpret_cast<char*>(words.data()), std::streamsize(words.size() * sizeof(std::uint32_t))))
        return std::nullopt;
    if ((hash_words(words) ^ hash_text(manifest)) != header.output_hash) return std::nullopt;
    std::istringstream lines(manifest);
    for (std::string line; std::getline(lines, line);) {
        const std::size_t space = line.find(' ');
        if (space == std::string::npos) return std::nullopt;
        if (fmt::format("{:016x}", contents_hash(tree(line.substr(space + 1)))) != line.substr(0, space))
            return std::nullopt;
    }
    return words;
}

void write_compiled(const std::string& path, std::uint64_t key, const std::string& manifest,
                    const std::vector<std::uint32_t>& words) {
    CompiledHeader header{};
    std::memcpy(header.magic, kCompiledMagic, sizeof kCompiledMagic);
    header.key = key;
    header.manifest_bytes = manifest.size();
    header.words = words.size();
    header.output_hash = hash_words(words) ^ hash_text(manifest);
    const std::size_t word_bytes = words.size() * sizeof(std::uint32_t);
    std::vector<char> bytes(sizeof header + manifest.size() + word_bytes);
    std::memcpy(bytes.data(), &header, sizeof header);
    std::memcpy(bytes.data() + sizeof header, manifest.data(), manifest.size());
    std::memcpy(bytes.data() + sizeof header + manifest.size(), words.data(), word_bytes);
    write_bytes(path, bytes);
}

}  // namespace

std::optional<std::string> spirv_cache_directory() {
    if (is_set("LANCER_CACHE_DISABLE")) return std::nullopt;
    if (const char* dir = std::getenv("LANCER_CACHE_DIR"); dir && *dir) return std::string(dir);
    if (const char* xdg = std::getenv("XDG_CACHE_HOME"); xdg && *xdg) return std::string(xdg) + "/lancer";
    if (const char* home = std::getenv("HOME"); home && *home) return std::string(home) + "/.cache/lancer";
    return std::nullopt;
}

std::vector<std::uint32_t> cached_compile(const ShaderTree& base, const ShaderFiles& generated,
                                          const std::string& entry, const std::vector<ShaderDefine>& defines,
                                          const std::string& display_root) {
    const ShaderTree tree = with_files(base, generated);
    const std::optional<std::string> dir = spirv_cache_directory();
    if (!dir) return compile_compute(tree, entry, defines, display_root);
    // The generated files and the entry point's text are in the key, so that each scene's code
    // and each edit of the entry point gets an entry of its own rather than replacing another's;
    // the files it includes are checked against the entry's manifest.
    std::uint64_t key = hash_text(fmt::format("glslang {}.{}.{}{}", GLSLANG_VERSION_MAJOR, GLSLANG_VERSION_MINOR,
                                              GLSLANG_VERSION_PATCH, GLSLANG_VERSION_FLAVOR));
    key = hash_text(entry, key);
    for (const ShaderDefine& d : defines) key = hash_text(d.value, hash_text(d.name, key));
    for (const auto& [name, contents] : generated) key = hash_text(contents, hash_text(name, key));
    if (std::optional<std::string> text = tree(entry)) key = hash_text(*text, key);
    const std::string path = fmt::format("{}/glsl-{:016x}.spv", *dir, key);
    if (std::optional<std::vector<std::uint32_t>> hit = read_compiled(path, key, tree)) return std::move(*hit);

    std::map<std::string, std::uint64_t> looked_up;
    const ShaderTree recording = [&tree, &looked_up](const std::string& name) {
        std::optional<std::string> contents = tree(name);
        looked_up[name] = contents_hash(contents);
        return contents;
    };
    std::vector<std::uint32_t> spirv = compile_compute(recording, entry, defines, display_root);
    std::string manifest;
    for (const auto& [name, hash] : looked_up) manifest += fmt::format("{:016x} {}\n", hash, name);
    write_compiled(path, key, manifest, spirv);
    return spirv;
}

std::vector<std::uint32_t> cached_specialization(const std::vector<std::uint32_t>& spirv, const ShaderFeatures& features,
                                                 SpirvCleanup cleanup) {
    const std::optional<std::string> dir = spirv_cache_directory();
    if (!dir) return specialize_spirv(spirv, features, cleanup);
    EntryHeader key{};
    std::memcpy(key.magic, kMagic, sizeof kMagic);
    key.input_hash = hash_words(spirv);
    key.features = feature_key(features);
    key.recipe_hash = hash_text(spirv_recipe(cleanup));
    const std::string path = fmt::format("{}/tracer-{:016x}-{:016x}-{}.spv", *dir, key.input_hash, key.features,
                                         static_cast<int>(cleanup));
    if (std::optional<std::vector<std::uint32_t>> hit = read_entry(path, key)) return std::move(*hit);
    std::vector<std::uint32_t> specialized = specialize_spirv(spirv, features, cleanup);
    write_entry(path, key, specialized);
    return specialized;
}

}  // namespace lancer::gpu
