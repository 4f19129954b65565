// Fracture networks and flow scenes shared by the flow tests and benchmarks
// (verification.md (e)-(g), the HM stack of docs/flow.md), built directly so
// that each test states its parameters in one place.
#pragma once

#include <string>
#include <vector>

#include "core/scene/scene.h"
#include "flow/cubic_law/flow_controls.h"
#include "rockmass/fracture_graph.h"

namespace fissure::testing {

/// A straight chain of n equal segments from `from` to `to`, aperture e, with
/// boundaries "start" (node 0) and "end" (node n).
FractureGraph chain_network(int n, const Vec2& from, const Vec2& to, double aperture);

/// Flow-only scene (physics [flow], no gravity unless set): a domain block
/// over `box` and the given traces as the network; fluid water (mu = 1e-3).
Scene trace_flow_scene(const std::vector<FlowTrace>& traces, const Vec2& lo, const Vec2& hi);

/// A random DFN of `n` traces in [0, size]^2 (two sets at 20 and 110 deg with
/// +-15 deg scatter, lengths uniform in [0.05, 0.3] x size, apertures
/// log-uniform in [20, 200] um), seeded, for benchmarks.
std::vector<FlowTrace> random_traces(int n, double size, unsigned seed);

/// The HM stack of docs/flow.md: a fixed base (width 4, height 1) and a top
/// block (width L = 2, height H) on it, the horizontal fracture between
/// them with both ends (the boundary "exterior") at pressure p(t) given by
/// `history` x p_ref, gravity g, joint normal stiffness kn, aperture e0.
struct StackParameters {
  double height = 1;                               ///< H (m)
  double density = 2700;                           ///< block density (kg/m^3)
  double g = 10;                                   ///< gravity (m/s^2)
  double e0 = 1e-4;                                ///< aperture at zero effective stress (m)
  double residual = 1e-5;                          ///< residual aperture (m)
  double kn = 1e9;                                 ///< joint normal stiffness (Pa/m)
  double p_ref = 1e4;                              ///< pressure scale (Pa)
  double dp = 0;                                   ///< pressure difference left - right end (Pa)
  std::vector<std::pair<double, double>> history;  ///< factor on p_ref over time
  double dt = 1e-3, end_time = 1;
};
Scene hm_stack_scene(const StackParameters& p);

}  // namespace fissure::testing
