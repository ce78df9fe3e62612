#include "core/cancel.hpp"

#include <atomic>

namespace lancer {
namespace {

// Written by a signal handler and read by any thread: a lock-free atomic is both
// async-signal-safe and free of data races.
std::atomic<int> g_signal{0};
static_assert(std::atomic<int>::is_always_lock_free);

}  // namespace

void request_cancellation(int signal_number) noexcept { g_signal.store(signal_number, std::memory_order_relaxed); }
void clear_cancellation() noexcept { g_signal.store(0, std::memory_order_relaxed); }
bool cancellation_requested() noexcept { return g_signal.load(std::memory_order_relaxed) != 0; }
int cancellation_signal() noexcept { return g_signal.load(std::memory_order_relaxed); }

}  // namespace lancer
