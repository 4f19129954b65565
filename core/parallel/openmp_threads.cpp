#include "core/parallel/openmp_threads.h"

#include <omp.h>

namespace fissure {

void set_openmp_threads_of_this_thread(int n) {
  omp_set_num_threads(n);
}

}  // namespace fissure
