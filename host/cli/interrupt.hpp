#pragma once
// Ctrl-C and SIGTERM as a flag and a file descriptor, instead of sudden death. While an
// Interrupts object lives, SIGINT and SIGTERM set a flag and make a pipe readable (so poll()
// can wait on them) in whatever thread receives them: a handler rather than a blocked signal,
// because threads started before main (OpenBLAS's pool) or by the driver may receive them.
namespace lancer {

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
