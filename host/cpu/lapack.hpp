#pragma once
// LAPACK for the CPU reference (dggev, on pencils of at most 18 x 18), loaded on first use.
//
// Debian's LAPACK is OpenBLAS's pthread build, which starts a pool of threads in its library
// constructor: linked into the program, that happens before main(), in every run, `lancer
// --version` included, and nothing said before it can ask for fewer threads
// (openblas_set_num_threads afterwards leaves them alive; setenv from the executable's
// .preinit_array is undone when libc initialises the environment). Under an address-space
// limit (prlimit --as=200MiB) the pool's thread loops in its buffer allocation and exit() waits
// for it forever. For 18 x 18 matrices, called from the reference's own pixel threads, the pool
// only costs. So LAPACK is opened here, with OPENBLAS_NUM_THREADS=1 set first (OpenBLAS reads it
// in that constructor, and then starts no thread at all), by the first caller: the CpuRenderer's
// constructor, before it starts threads of its own.
#include <lapacke.h>

namespace lancer::cpu {

using DggevWork = lapack_int (*)(int, char, char, lapack_int, double*, lapack_int, double*, lapack_int, double*,
                                 double*, double*, double*, lapack_int, double*, lapack_int, double*, lapack_int);

// LAPACKE_dggev_work from liblapacke.so.3. Throws std::runtime_error if it cannot be loaded.
DggevWork lapack_dggev_work();

}  // namespace lancer::cpu
