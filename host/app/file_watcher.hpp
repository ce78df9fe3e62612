#pragma once
// Waits for files to change, the way editors change them: in several steps (truncate, write,
// rename over, touch). Directories are watched rather than files, so a file replaced by rename
// is still seen; bursts of events are merged into one change after a quiet period.
//
// Paths are compared and reported in one form, FileWatcher::identity() (absolute, symbolic
// links resolved), so callers can tell which of the files they asked for changed. The watch
// lists may be changed while another thread waits (the viewer's watcher thread).
#include <chrono>
#include <filesystem>
#include <map>
#include <mutex>
#include <set>
#include <string>

#include "app/interrupt.hpp"

namespace lancer {

class FileWatcher {
public:
    FileWatcher();
    ~FileWatcher();
    FileWatcher(const FileWatcher&) = delete;
    FileWatcher& operator=(const FileWatcher&) = delete;

    // The form in which paths are watched and reported: absolute, with symbolic links resolved
    // as far as the path exists (a file being replaced may briefly not exist).
    static std::filesystem::path identity(const std::filesystem::path& path);

    // Every file under `dir` (recursively) whose name ends with one of `suffixes`.
    void watch_tree(const std::filesystem::path& dir, const std::set<std::string>& suffixes);
    // Exactly these single files, replacing the previous set (a scene and the files it references
    // change together): each one's directory is watched, events for other names are ignored,
    // and directories no longer needed are let go.
    void watch_files(const std::set<std::filesystem::path>& files);

    enum class Wake { Changed, Signal, Interrupted };
    struct Result {
        Wake wake;
        std::set<std::filesystem::path> changed;  // identity() of each changed watched file
    };
    // Blocks until a watched file changed and then no event came for `quiet`, or until
    // SIGINT/SIGTERM (Wake::Signal).
    Result wait(std::chrono::milliseconds quiet);

    // True if SIGINT or SIGTERM arrived (non-blocking; for cancelling a render in progress).
    bool signal_pending() const { return interrupts_.requested(); }

    // From another thread: makes a wait() in progress, or the next one, return Wake::Interrupted
    // (the viewer waits for changes on a thread of its own and stops it this way).
    void interrupt();

private:
    void add_dir(const std::filesystem::path& dir);  // mutex_ held
    bool in_tree(const std::filesystem::path& path) const;  // mutex_ held

    int inotify_fd_ = -1;
    Interrupts interrupts_;
    int interrupt_fd_ = -1;  // an eventfd: interrupt() from another thread
    std::mutex mutex_;       // guards the three lists below
    std::map<int, std::filesystem::path> dirs_;  // watch descriptor -> directory
    std::map<std::filesystem::path, std::set<std::string>> trees_;  // root -> suffixes
    std::set<std::filesystem::path> files_;
};

}  // namespace lancer
