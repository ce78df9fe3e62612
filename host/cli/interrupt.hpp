#pragma once
// Ctrl-C and SIGTERM as a flag and a file descriptor, instead of sudden death. While an
// Interrupts object lives, SIGINT and SIGTERM set a flag and make a pipe readable (so poll()
// can wait on them) in whatever thread receives them: a handler rather than a blocked signal,
// because threads started before main (OpenBLAS's pool) or by the driver may receive them.
// The handler is one-shot: a second Ctrl-C, if the first is not answered, ends the program at once.
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
    Interrupts();   // installs the handlers
    ~Interrupts();  // restores the previous ones
    Interrupts(const Interrupts&) = delete;
    Interrupts& operator=(const Interrupts&) = delete;

    bool requested() const;
    int fd() const;  // readable once an interrupt arrived
    int signal_number() const;  // the last signal received, 0 if none
};

}  // namespace lancer
