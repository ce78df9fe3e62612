#include "app/file_watcher.hpp"

#include <algorithm>
#include <cerrno>
#include <cstring>

#include <poll.h>
#include <sys/eventfd.h>
#include <sys/inotify.h>
#include <unistd.h>

#include "core/error.hpp"

namespace lancer {
namespace fs = std::filesystem;

namespace {

constexpr std::uint32_t kEvents = IN_CLOSE_WRITE | IN_MOVED_TO | IN_CREATE | IN_DELETE | IN_MODIFY | IN_ATTRIB;

bool ends_with_any(const std::string& name, const std::set<std::string>& suffixes) {
    for (const auto& s : suffixes)
        if (name.size() >= s.size() && name.compare(name.size() - s.size(), s.size(), s) == 0) return true;
    return false;
}

// `path` is `root` or below it (compared by components: /a/shaders2 is not within /a/shaders).
bool within(const fs::path& root, const fs::path& path) {
    return std::mismatch(root.begin(), root.end(), path.begin(), path.end()).first == root.end();
}

}  // namespace

FileWatcher::FileWatcher() {
    inotify_fd_ = ::inotify_init1(IN_NONBLOCK | IN_CLOEXEC);
    if (inotify_fd_ < 0) throw UserError(std::string("cannot watch files (inotify): ") + std::strerror(errno));
    interrupt_fd_ = ::eventfd(0, EFD_NONBLOCK | EFD_CLOEXEC);
}

FileWatcher::~FileWatcher() {
    if (inotify_fd_ >= 0) ::close(inotify_fd_);
    if (interrupt_fd_ >= 0) ::close(interrupt_fd_);
}

void FileWatcher::interrupt() {
    std::uint64_t one = 1;
    [[maybe_unused]] ssize_t n = ::write(interrupt_fd_, &one, sizeof(one));
}

fs::path FileWatcher::identity(const fs::path& path) {
    std::error_code ec;
    fs::path absolute = fs::absolute(path, ec);
    if (ec) return path.lexically_normal();
    fs::path resolved = fs::weakly_canonical(absolute, ec);
    return ec ? absolute.lexically_normal() : resolved;
}

void FileWatcher::add_dir(const fs::path& dir) {
    for (const auto& [wd, path] : dirs_)
        if (path == dir) return;
    int wd = ::inotify_add_watch(inotify_fd_, dir.c_str(), kEvents);
    if (wd < 0) throw UserError("cannot watch '" + dir.string() + "': " + std::strerror(errno));
    dirs_[wd] = dir;
}

bool FileWatcher::in_tree(const fs::path& path) const {
    for (const auto& [root, suffixes] : trees_)
        if (within(root, path)) return true;
    return false;
}

void FileWatcher::watch_tree(const fs::path& dir, const std::set<std::string>& suffixes) {
    fs::path root = identity(dir);
    std::lock_guard lock(mutex_);
    trees_[root] = suffixes;
    add_dir(root);
    for (const auto& entry : fs::recursive_directory_iterator(root))
        if (entry.is_directory()) add_dir(entry.path());
}

void FileWatcher::watch_files(const std::set<fs::path>& files) {
    std::set<fs::path> wanted, dirs;
    for (const auto& f : files) {
        fs::path id = identity(f);
        dirs.insert(id.parent_path());
        wanted.insert(std::move(id));
    }
    std::lock_guard lock(mutex_);
    files_ = std::move(wanted);
    for (auto it = dirs_.begin(); it != dirs_.end();) {
        if (in_tree(it->second) || dirs.count(it->second)) {
            ++it;
        } else {
            ::inotify_rm_watch(inotify_fd_, it->first);
            it = dirs_.erase(it);
        }
    }
    for (const auto& dir : dirs) add_dir(dir);
}

FileWatcher::Result FileWatcher::wait(std::chrono::milliseconds quiet) {
    Result result{Wake::Changed, {}};
    alignas(inotify_event) char buffer[16 * 1024];
    for (;;) {
        if (signal_pending()) return {Wake::Signal, {}};
        pollfd fds[3] = {{inotify_fd_, POLLIN, 0}, {interrupts_.fd(), POLLIN, 0}, {interrupt_fd_, POLLIN, 0}};
        // Until something changed, wait indefinitely; then only for the quiet period.
        int timeout = result.changed.empty() ? -1 : static_cast<int>(quiet.count());
        int ready = ::poll(fds, 3, timeout);
        if (ready < 0 && errno == EINTR) continue;
        if (ready == 0) return result;  // quiet long enough after a change
        if (fds[2].revents & POLLIN) return {Wake::Interrupted, {}};
        if (fds[1].revents & POLLIN) continue;  // handled by signal_pending() above
        ssize_t n = ::read(inotify_fd_, buffer, sizeof(buffer));
        for (ssize_t offset = 0; n > 0 && offset < n;) {
            auto* event = reinterpret_cast<inotify_event*>(buffer + offset);
            offset += static_cast<ssize_t>(sizeof(inotify_event) + event->len);
            std::lock_guard lock(mutex_);
            auto dir = dirs_.find(event->wd);
            if (dir == dirs_.end() || event->len == 0) continue;
            fs::path path = dir->second / event->name;
            if ((event->mask & IN_ISDIR) && (event->mask & (IN_CREATE | IN_MOVED_TO))) {
                if (in_tree(path)) add_dir(path);
                continue;
            }
            bool interesting = files_.count(path) > 0;
            for (const auto& [root, suffixes] : trees_)
                if (path != root && within(root, path) && ends_with_any(path.filename().string(), suffixes))
                    interesting = true;
            if (interesting) result.changed.insert(path);
        }
    }
}

}  // namespace lancer
