#include "coupling/rev_sources.h"

namespace fissure {

flow::DfnSourceFactory rev_dfn_source_factory() {
  // mechanics/blocks (the DFN generator of the rock-mass geometry issue) is
  // not in the tree yet; studies use flow's own `type: poisson` DFN meanwhile.
  return {};
}

}  // namespace fissure
