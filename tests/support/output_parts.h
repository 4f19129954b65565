// The output parts of a run with the mechanics and the flow, for tests that
// drive the writers directly (core/io): what the coordinator collects from
// the processes (Process::results, Process::monitors) and from the shared
// fields (the fracture graph).
#pragma once

#include <vector>

#include "core/io/block_monitors.h"
#include "flow/cubic_law/flow_results.h"
#include "rockmass/fields/contact_results.h"
#include "rockmass/fracture_graph_results.h"

namespace fissure::test {

struct OutputParts {
  /// `head`: the flow's heads (off by default).
  explicit OutputParts(HeadDefinition head = {}) : flow_results(head) {}

  ContactResults contacts;
  flow::FlowResults flow_results;
  FractureGraphResults graph;
  BlockMonitors block_monitors;
  flow::PressureMonitors pressure_monitors;

  /// The results parts: contacts, the flow state, the fracture graph.
  std::vector<ResultsPart*> results() { return {&contacts, &flow_results, &graph}; }
  /// The monitor columns of the mechanics and/or of the flow.
  std::vector<const MonitorSource*> monitors(bool mechanics, bool flow = false) const {
    std::vector<const MonitorSource*> sources;
    if (mechanics) sources.push_back(&block_monitors);
    if (flow) sources.push_back(&pressure_monitors);
    return sources;
  }
};

}  // namespace fissure::test
