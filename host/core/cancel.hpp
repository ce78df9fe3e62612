#pragma once
// A request to stop, from a signal (SIGINT, SIGTERM: cli/interrupt.cpp sets it), visible to every
// module: long work that is not a render (loading a scene, subdividing a surface, a blocking
// open of a FIFO) checks it and stops by throwing Cancelled. Renders stop through their
// progress callback instead (RenderCancelled).
#include <csignal>
#include <stdexcept>

namespace lancer {

// Async-signal-safe: only stores the number.
void request_cancellation(int signal_number) noexcept;
void clear_cancellation() noexcept;
bool cancellation_requested() noexcept;
int cancellation_signal() noexcept;  // the signal that asked, 0 if none

class Cancelled : public std::runtime_error {
public:
    Cancelled() : std::runtime_error("cancelled") {}
};

inline void throw_if_cancelled() {
    if (cancellation_requested()) throw Cancelled();
}

}  // namespace lancer
