#pragma once
// What a scene reads from a big file (a mesh, a point set), shared while any scene holds it: a
// file placed many times (a declared object, a group repeated) is read once; a file changed since
// (hot reload) is read again.
#include <filesystem>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <string>

namespace lancer {

// The value read from `path` by `read` (with `variant`, what else shaped it, in the key), or the
// one read before if the file's time and size are unchanged and some scene still holds it.
template <class T>
std::shared_ptr<const T> shared_from_file(const std::filesystem::path& path, const std::string& variant,
                                          const std::function<std::shared_ptr<const T>()>& read) {
    struct Entry {
        std::filesystem::file_time_type written;
        std::uintmax_t size;
        std::weak_ptr<const T> value;
    };
    static std::mutex mutex;
    static std::map<std::string, Entry> cache;
    std::error_code error;
    const std::string key = std::filesystem::absolute(path, error).string() + '\n' + variant;
    const auto written = std::filesystem::last_write_time(path, error);
    const auto size = std::filesystem::file_size(path, error);
    if (!error) {
        std::lock_guard lock(mutex);
        auto found = cache.find(key);
        if (found != cache.end() && found->second.written == written && found->second.size == size)
            if (auto value = found->second.value.lock()) return value;
    }
    std::shared_ptr<const T> value = read();
    if (!error) {
        std::lock_guard lock(mutex);
        cache[key] = Entry{written, size, value};
    }
    return value;
}

}  // namespace lancer
