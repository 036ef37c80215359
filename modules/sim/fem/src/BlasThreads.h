#pragma once

// The BLAS threads of the sparse factorisations (CHOLMOD's supernodes call dense BLAS). OpenBLAS starts as many
// threads as the machine has cores, and on many cores that is far slower, not faster: the converged quadratic
// analysis of cli_sac's thrombus wall took 130-161 s with OpenBLAS on all 16 cores of the H200 host, against 37 s
// with 4 and 45 s with 2 (RESULTS.md, 2026-12-02).

namespace vsim::sim::fem::detail {

/// At most this many BLAS threads for the factorisations (the fastest of 1, 2, 4 and 16 measured there).
inline constexpr int kFactorisationBlasThreads = 4;

/// Caps OpenBLAS at kFactorisationBlasThreads threads, once per process; leaves it alone where the user set
/// OPENBLAS_NUM_THREADS or the BLAS is not OpenBLAS.
void capBlasThreads();

} // namespace vsim::sim::fem::detail
