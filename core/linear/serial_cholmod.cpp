#include "core/linear/serial_cholmod.h"

#include <omp.h>

namespace fissure {

void keep_cholmod_serial() {
  omp_set_max_active_levels(0);
}

}  // namespace fissure
