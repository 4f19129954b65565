#include "core/parallel/openmp_threads.h"

#include <omp.h>

namespace fissure {

OpenMpThreadsOfThisThread::OpenMpThreadsOfThisThread(int n) : before_(omp_get_max_threads()) {
  omp_set_num_threads(n);
}

OpenMpThreadsOfThisThread::~OpenMpThreadsOfThisThread() {
  omp_set_num_threads(before_);
}

}  // namespace fissure
