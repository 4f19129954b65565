// CHOLMOD's supernodal kernels run on the calling thread only.
//
// Debian's SuiteSparse 5 compiles CHOLMOD_OMP_NUM_THREADS = 4 into the
// supernodal factorization, ignoring OMP_NUM_THREADS: every supernode opens a
// 4-thread OpenMP region. The supernodes of DDA and fracture-network matrices
// are small (tens of columns), so the fork/join and futex wake-ups cost far
// more than the parallel work saves: on the 1,000-brick wall a factorization
// took 47 ms of CPU with the threads and 11 ms without (docs/performance-history.md).
// Fissure parallelises across processes (MPI) and REV samples instead.
#pragma once

namespace fissure {

/// Makes every later OpenMP parallel region run on one thread (OpenMP
/// max-active-levels = 0). Idempotent; cheap enough to call per solver.
void keep_cholmod_serial();

}  // namespace fissure
