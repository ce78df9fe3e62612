#include "cpu/lapack.hpp"

#include <cstdlib>
#include <mutex>
#include <stdexcept>
#include <string>

#include <dlfcn.h>

namespace lancer::cpu {

DggevWork lapack_dggev_work() {
    static DggevWork function = nullptr;
    static std::once_flag once;
    std::call_once(once, [] {
        ::setenv("OPENBLAS_NUM_THREADS", "1", 1);  // before OpenBLAS's constructor reads it: see lapack.hpp
        void* library = ::dlopen("liblapacke.so.3", RTLD_NOW | RTLD_LOCAL);
        if (!library) throw std::runtime_error(std::string("cannot load LAPACK (liblapacke.so.3): ") + ::dlerror());
        function = reinterpret_cast<DggevWork>(::dlsym(library, "LAPACKE_dggev_work"));
        if (!function) throw std::runtime_error("liblapacke.so.3 has no LAPACKE_dggev_work");
        // The library stays loaded for the life of the process.
    });
    return function;
}

}  // namespace lancer::cpu
