#include "cpu/lapack.hpp"

#include <cstdlib>
#include <mutex>
#include <stdexcept>
#include <string>

#include <dlfcn.h>

namespace lancer::cpu {

namespace {

struct Lapack {
    DggevWork dggev = nullptr;
    DgebalWork dgebal = nullptr;
    DhseqrWork dhseqr = nullptr;
};

const Lapack& lapack() {
    static Lapack functions;
    static std::once_flag once;
    std::call_once(once, [] {
        ::setenv("OPENBLAS_NUM_THREADS", "1", 1);  // before OpenBLAS's constructor reads it: see lapack.hpp
        void* library = ::dlopen("liblapacke.so.3", RTLD_NOW | RTLD_LOCAL);
        if (!library) throw std::runtime_error(std::string("cannot load LAPACK (liblapacke.so.3): ") + ::dlerror());
        auto find = [library](const char* name) {
            void* symbol = ::dlsym(library, name);
            if (!symbol) throw std::runtime_error(std::string("liblapacke.so.3 has no ") + name);
            return symbol;
        };
        functions.dggev = reinterpret_cast<DggevWork>(find("LAPACKE_dggev_work"));
        functions.dgebal = reinterpret_cast<DgebalWork>(find("LAPACKE_dgebal_work"));
        functions.dhseqr = reinterpret_cast<DhseqrWork>(find("LAPACKE_dhseqr_work"));
        // The library stays loaded for the life of the process.
    });
    return functions;
}

}  // namespace

DggevWork lapack_dggev_work() { return lapack().dggev; }
DgebalWork lapack_dgebal_work() { return lapack().dgebal; }
DhseqrWork lapack_dhseqr_work() { return lapack().dhseqr; }

}  // namespace lancer::cpu
