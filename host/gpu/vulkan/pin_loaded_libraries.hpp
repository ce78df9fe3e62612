#pragma once

namespace lancer::gpu {

// Sanitizer builds only (LANCER_SANITIZE; elsewhere it does nothing): keeps every shared library
// loaded so far mapped for the rest of the process. The Vulkan loader unloads the driver and the
// layers when an instance is destroyed; LeakSanitizer, reporting at exit what they never freed,
// would then show their stack frames as "<unknown module>", which no suppression can name.
// Called just before vkDestroyInstance, so that tests/sanitizers/lsan.supp can name exactly the
// library each suppressed leak is in.
void pin_loaded_libraries();

}  // namespace lancer::gpu
