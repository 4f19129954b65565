// The OpenMP threads of the calling thread's parallel regions (the DEM's
// cycle): a driver that already spreads its work over threads of its own
// (the REV study's domains) gives each of them one, so that two levels of
// threads do not compete for the cores.
#pragma once

namespace fissure {

/// omp_set_num_threads(n) for the calling thread (its own ICV).
void set_openmp_threads_of_this_thread(int n);

}  // namespace fissure
