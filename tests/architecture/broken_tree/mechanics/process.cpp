// A fixture of tests/architecture: one physics module including another.
#include "flow/network/fluid.h"
