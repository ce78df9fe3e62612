#pragma once
// Waits for files to change, the way editors change them: in several steps (truncate, write,
// rename over, touch). Directories are watched rather than files, so a file replaced by rename
// is still seen; bursts of events are merged into one change after a quiet period.
#include <chrono>
#include <filesystem>
#include <map>
#include <mutex>
#include <set>
#include <string>
#include <vector>

#include "cli/interrupt.hpp"

namespace lancer {

class FileWatcher {
public:
    FileWatcher();
    ~FileWatcher();
    FileWatcher(const FileWatcher&) = delete;
    FileWatcher& operator=(const FileWatcher&) = delete;

    // Every file under `dir` (recursively) whose name ends with one of `suffixes`.
    void watch_tree(const std::filesystem::path& dir, const std::set<std::string>& suffixes);
    // One file (its directory is watched, events for other names ignored).
    void watch_file(const std::filesystem::path& file);
    // Forget the single files (the set a scene references changes when the scene does).
    void clear_files();
    // Watch exactly these single files from now on (a scene and the files it reads). Safe to
    // call while another thread is in wait().
    void set_files(const std::vector<std::filesystem::path>& files);
    // True for a path watched as a single file, false for one found in a tree.
    bool is_watched_file(const std::filesystem::path& path) const;

    enum class Wake { Changed, Signal, Interrupted };
    struct Result {
        Wake wake;
        std::set<std::filesystem::path> changed;  // paths of changed watched files
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
    void add_dir(const std::filesystem::path& dir);  // with mutex_ held
    void add_file(const std::filesystem::path& file);  // with mutex_ held

    int inotify_fd_ = -1;
    Interrupts interrupts_;
    int interrupt_fd_ = -1;  // an eventfd: interrupt() from another thread
    std::map<int, std::filesystem::path> dirs_;  // watch descriptor -> directory
    std::map<std::filesystem::path, std::set<std::string>> trees_;  // root -> suffixes
    std::set<std::filesystem::path> files_;
    mutable std::mutex mutex_;  // guards dirs_, trees_ and files_: wait() may run on another thread
};

}  // namespace lancer
