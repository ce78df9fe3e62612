#pragma once
// Reading input files (scenes, patch files, images) in pieces, so that a file's size is checked
// while it is read (/dev/zero, an endless pipe), and so that a SIGINT or SIGTERM stops a read that
// blocks: opening a FIFO waits for a writer, reading one waits for data. Such a call returns EINTR
// (lancer's handlers do not restart system calls), and these functions then throw Cancelled.
#include <cstddef>
#include <optional>
#include <string>

namespace lancer {

// A file descriptor open for reading, closed when it goes. Throws UserError with strerror's
// message when the file cannot be opened, and Cancelled when an interrupt stops the open.
class InputFile {
public:
    explicit InputFile(const std::string& path);
    ~InputFile();
    InputFile(const InputFile&) = delete;
    InputFile& operator=(const InputFile&) = delete;

    // Appends up to `bytes` bytes to `out`; false at the end of the file.
    bool read_some(std::string& out, std::size_t bytes);

private:
    int fd_;
};

// The whole file, or nullopt-like `false` in `complete` once more than `limit` bytes were read
// (reading stops there). Throws as InputFile does; a directory is "it is a directory".
struct FileText {
    std::string text;
    bool complete = true;  // false: the file is larger than the limit
};
FileText read_file(const std::string& path, std::size_t limit);

// Files lancer reads that are not the user's explicit input (cache entries; the names a cache
// entry asks for) may be anything someone else put there: a FIFO, whose open waits for a writer
// and whose read waits for data; a device; a symbolic link to either; a huge file. This opens
// without waiting (O_NONBLOCK), without following a link in the last component (O_NOFOLLOW,
// unless `links` is follow) and reads only a regular file (fstat) of at most `max_bytes`.
// Anything else, or any error, is nullopt: the caller treats it as a miss. Never throws but
// std::bad_alloc; never blocks (a regular file's read does not wait for a writer).
enum class Links { refuse, follow };
std::optional<std::string> read_regular_file_nonblocking(const std::string& path, std::size_t max_bytes,
                                                         Links links = Links::refuse);

}  // namespace lancer
