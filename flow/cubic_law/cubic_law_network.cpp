// CubicLawProcess::build_network: the network from the scene's source (block
// contacts, explicit traces, or the rock mass's own fracture graph), named
// regions, wells, the checks that need the network (apertures > 0, every
// condition's boundary holds nodes), and, coupled, the joint law of each
// fracture's aperture.
#include <sstream>

#include "core/base/errors.h"
#include "flow/cubic_law/cubic_law_process.h"
#include "flow/network/block_network.h"
#include "flow/network/boundary_conditions.h"
#include "flow/network/trace_network.h"
#include "rockmass/fracture_graph.h"

namespace fissure::flow {

void CubicLawProcess::build_network(RockMass& state) {
  using Source = FlowControls::NetworkSource;
  Box extent;
  for (const Block& b : state.blocks) extent.extend(bounding_box(b.polygon));
  if (c_.network == Source::Traces && c_.domain) {
    extent = Box{};
    extent.extend(c_.domain->first);
    extent.extend(c_.domain->second);
  }
  model_size_ = extent.empty() ? 1.0 : std::max(extent.size().x(), extent.size().y());
  const double tol = 1e-9 * model_size_;

  // Messages name where the scene chooses the network (a scene built in code
  // has no file: then just the process).
  const std::string where = c_.network_path.empty() ? "flow" : c_.network_path;

  // 1. The graph.
  FractureGraph& g = state.fields.get_or_add(kFractureGraph);
  switch (c_.network) {
    case Source::Blocks: {
      // Cut where the blocks were cut, from their initial vertices: after an
      // initial stage (coupling.initial_equilibrium) the settled blocks'
      // edges no longer coincide, and the walls are followed from there.
      std::vector<Block> as_cut = state.blocks;
      for (Block& b : as_cut) b.polygon.vertices = b.initial_vertices;
      g = network_from_blocks(as_cut, c_.initial_aperture, block_tolerance(as_cut));
      break;
    }
    case Source::Traces: {
      std::vector<Trace> traces;
      for (const FlowTrace& t : c_.traces)
        traces.push_back({t.from, t.to, t.aperture, static_cast<int>(traces.size()), -1});
      g = build_trace_network(traces, extent, tol);
      break;
    }
    case Source::RockMass:
      FISSURE_CHECK(g.n_segments() > 0, SceneError,
                    where << ": found source 'rock_mass', but the scene's rock mass has no "
                             "fracture (no joint set, DFN family or fracture reaches into its "
                             "domain); expected a rock mass with fractures, or source blocks or "
                             "traces");
      break;
  }
  FISSURE_CHECK(g.n_segments() > 0, SceneError,
                where << ": found an empty fracture network ("
                      << (c_.network == Source::Blocks ? "no two blocks share an edge"
                                                       : "no trace lies inside the domain")
                      << "); expected at least one fracture");
  for (int s = 0; s < g.n_segments(); ++s) {
    const double e0 = g.segments[s].aperture;
    const Vec2& a = g.nodes[g.segments[s].node_a];
    const Vec2& b = g.nodes[g.segments[s].node_b];
    FISSURE_CHECK(std::isfinite(e0) && e0 > 0, SceneError,
                  where << ": fracture segment " << s << " from (" << a.x() << ", " << a.y()
                        << ") to (" << b.x() << ", " << b.y() << ") has aperture " << e0
                        << " m; expected an aperture > 0");
  }

  // 2. Regions: the nodes inside each box.
  for (const FlowRegion& r : c_.regions) {
    std::vector<int>& nodes = g.boundary_nodes[r.name];
    nodes.clear();
    for (int v = 0; v < g.n_nodes(); ++v) {
      const Vec2& x = g.nodes[v];
      if ((x - r.min).minCoeff() >= -tol && (r.max - x).minCoeff() >= -tol) nodes.push_back(v);
    }
  }

  // 3. Wells (may split a segment), then the conditions' boundaries.
  well_nodes_.clear();
  for (const FlowWell& w : c_.wells) well_nodes_.push_back(locate_well(g, w, 1e-6 * model_size_));
  check_condition_boundaries(g, c_.conditions);
  reference_ = g.nodes;
  block_reference_ = initial_geometry(state.blocks);
  // 4. Which joint law each fracture's aperture follows.
  if (hm_) hm_->assign_joints(g, state, where);
}

}  // namespace fissure::flow
