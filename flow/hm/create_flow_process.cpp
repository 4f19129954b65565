#include "flow/hm/create_flow_process.h"

#include "flow/hm/flow_process.h"

namespace fissure::flow {

std::unique_ptr<Process> create_flow_process(const Scene& scene) {
  return std::make_unique<FlowProcess>(scene);
}

}  // namespace fissure::flow
