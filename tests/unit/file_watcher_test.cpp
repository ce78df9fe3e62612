// The file watcher as `lancer watch` and `lancer view` use it: changed files reported in one
// form (FileWatcher::identity), a scene's set of files replaced as a whole, trees matched by
// whole path components. Every wait is bounded: a watchdog interrupts a wait that sees nothing.
#include <chrono>
#include <filesystem>
#include <future>
#include <thread>

#include <gtest/gtest.h>

#include "app/file_watcher.hpp"
#include "support/test_support.hpp"

namespace lancer {
namespace {

namespace fs = std::filesystem;
using std::chrono::milliseconds;

class FileWatcherTest : public testing::Test {
protected:
    void SetUp() override {
        std::string name = testing::UnitTest::GetInstance()->current_test_info()->name();
        dir = fs::path(test::output_dir()) / ("file-watcher-" + name + "-" + std::to_string(::getpid()));
        fs::remove_all(dir);
        fs::create_directories(dir);
    }
    // The next change the watcher reports, or an empty set when none comes within 30 s.
    std::set<fs::path> next_change() {
        std::promise<void> done;
        std::thread watchdog([&, finished = done.get_future()] {
            if (finished.wait_for(std::chrono::seconds(30)) == std::future_status::timeout) watcher.interrupt();
        });
        FileWatcher::Result r = watcher.wait(milliseconds(100));
        done.set_value();
        watchdog.join();
        return r.wake == FileWatcher::Wake::Changed ? r.changed : std::set<fs::path>{};
    }

    fs::path dir;
    FileWatcher watcher;
};

TEST_F(FileWatcherTest, ASetOfFilesReplacesTheLastOne) {
    fs::create_directories(dir / "old");
    test::write_file(dir / "old/a.bpt", "1");
    test::write_file(dir / "b.bpt", "1");
    watcher.watch_files({dir / "old/a.bpt"});
    watcher.watch_files({dir / "b.bpt"});
    test::write_file(dir / "old/a.bpt", "2");  // no longer watched: a change here would come first
    test::write_file(dir / "b.bpt", "2");
    EXPECT_EQ(next_change(), std::set<fs::path>{FileWatcher::identity(dir / "b.bpt")});
}

TEST_F(FileWatcherTest, FilesInSeveralDirectoriesAreAllWatched) {
    for (const char* d : {"scenes", "data", "textures"}) fs::create_directories(dir / d);
    // "z..." sorts last but resolves to the first directory.
    fs::create_symlink("data", dir / "z-link");
    std::set<fs::path> files = {dir / "scenes/s.toml", dir / "textures/t.png", dir / "z-link/a.bpt"};
    for (const auto& f : files) test::write_file(f, "1");
    watcher.watch_files(files);
    for (const auto& f : files) {
        test::write_file(f, "2");
        EXPECT_EQ(next_change(), std::set<fs::path>{FileWatcher::identity(f)}) << f;
    }
}

TEST_F(FileWatcherTest, PathsAreReportedInOneFormHoweverTheyWereNamed) {
    fs::create_directories(dir / "real");
    fs::create_symlink("real", dir / "link");
    test::write_file(dir / "real/scene.toml", "1");
    // Named through a symbolic link and a detour: reported as the file it is.
    watcher.watch_files({dir / "link/../link/scene.toml"});
    test::write_file(dir / "real/scene.toml", "2");
    EXPECT_EQ(next_change(), std::set<fs::path>{fs::canonical(dir / "real/scene.toml")});
    EXPECT_EQ(FileWatcher::identity(dir / "link/scene.toml"), fs::canonical(dir / "real/scene.toml"));
}

TEST_F(FileWatcherTest, ATreeIsItsDirectoryNotEveryNameThatStartsLikeIt) {
    fs::create_directories(dir / "shaders");
    fs::create_directories(dir / "shaders2");
    watcher.watch_tree(dir / "shaders", {".glsl"});
    watcher.watch_files({dir / "shaders2/x.glsl"});  // its directory is watched too, for this file only
    test::write_file(dir / "shaders2/y.glsl", "1");
    test::write_file(dir / "shaders/z.glsl", "1");
    EXPECT_EQ(next_change(), std::set<fs::path>{FileWatcher::identity(dir / "shaders/z.glsl")});
}

}  // namespace
}  // namespace lancer
