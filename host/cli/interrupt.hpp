#pragma once
// Ctrl-C and SIGTERM as a request to stop (core/cancel.hpp) and a file descriptor, instead of
// sudden death. While an Interrupts object lives, SIGINT and SIGTERM set the request and make a
// pipe readable (so poll() can wait on them). main() holds one for the whole command, so that
// every phase (loading, compiling, rendering, encoding) can stop cleanly; objects made while
// another lives (the file watcher's) share it.
//
// The handlers are installed without SA_RESTART: a system call blocked when the signal arrives
// (opening a FIFO that has no writer yet, reading a pipe) returns EINTR, and the code that made
// it checks the request, instead of being restarted and blocking on. They are one-shot: a second
// Ctrl-C, if the first is not answered, ends the program at once.
#include <stdexcept>
#include <string>

namespace lancer {

// A render stopped by SIGINT or SIGTERM. main() prints the message and exits with 128 + signal,
// as a shell reports a process killed by it.
class Interrupted : public std::runtime_error {
public:
    Interrupted(int signal_number, const std::string& what_was_left);
    int signal_number() const { return signal_; }

private:
    int signal_;
};

// "SIGINT", "SIGTERM".
std::string signal_name(int signal_number);

class Interrupts {
public:
    Interrupts();   // installs the handlers (the first of nested objects)
    ~Interrupts();  // restores the previous ones (the first of nested objects)
    Interrupts(const Interrupts&) = delete;
    Interrupts& operator=(const Interrupts&) = delete;

    bool requested() const;
    int fd() const;  // readable once an interrupt arrived
    int signal_number() const;  // the last signal received, 0 if none
};

}  // namespace lancer
