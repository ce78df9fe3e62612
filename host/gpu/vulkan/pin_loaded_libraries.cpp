#include "gpu/vulkan/pin_loaded_libraries.hpp"

#ifdef LANCER_SANITIZE
#include <string>
#include <vector>

#include <dlfcn.h>
#include <link.h>
#endif

namespace lancer::gpu {

void pin_loaded_libraries() {
#ifdef LANCER_SANITIZE
    std::vector<std::string> names;
    dl_iterate_phdr(
        [](dl_phdr_info* info, std::size_t, void* out) {
            if (info->dlpi_name && info->dlpi_name[0]) static_cast<std::vector<std::string>*>(out)->push_back(info->dlpi_name);
            return 0;
        },
        &names);
    // RTLD_NOLOAD: only libraries already loaded; RTLD_NODELETE: never unmapped afterwards. The
    // handle is deliberately not closed.
    for (const std::string& name : names) dlopen(name.c_str(), RTLD_LAZY | RTLD_NOLOAD | RTLD_NODELETE);
#endif
}

}  // namespace lancer::gpu
