#include "BlasThreads.h"

#include <dlfcn.h>

#include <cstdlib>
#include <mutex>

namespace vsim::sim::fem::detail {

void capBlasThreads()
{
    static std::once_flag once;
    std::call_once(once, [] {
        if (std::getenv("OPENBLAS_NUM_THREADS") || std::getenv("GOTO_NUM_THREADS"))
            return; // the user's choice
        // Looked up at run time: Debian's libblas.so.3 may be OpenBLAS or the reference BLAS (no threads).
        using GetThreads = int (*)();
        using SetThreads = void (*)(int);
        const auto get = reinterpret_cast<GetThreads>(dlsym(RTLD_DEFAULT, "openblas_get_num_threads"));
        const auto set = reinterpret_cast<SetThreads>(dlsym(RTLD_DEFAULT, "openblas_set_num_threads"));
        if (get && set && get() > kFactorisationBlasThreads)
            set(kFactorisationBlasThreads);
    });
}

} // namespace vsim::sim::fem::detail
