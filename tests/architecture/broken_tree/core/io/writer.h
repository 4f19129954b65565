// A fixture of tests/architecture: core including a physics module.
#include "flow/cubic_law/fracture_pressure.h"
