// Joint sets (Shi's DL step; docs/rock-mass.md section 2): parallel trace
// lines at a dip angle, spaced along their normal, each line cut into joints
// and rock bridges.
//
// Geometry of set s: direction d = (cos dip, sin dip), normal n = (-sin dip,
// cos dip). Line k passes through o + c_k n, where o is the lower-left corner
// of the domain's bounding box and c_0 = phase x spacing; c_{k+1} - c_k is the
// spacing (drawn uniform in [s - spread, s + spread] when spread > 0). Lines
// are generated for every offset that meets the bounding box. Along a line,
// with t the coordinate along d from the projection of o, joints cover
// [t_k + m P, t_k + m P + trace_length] (m integer, period P = trace_length +
// bridge_length), t_k = stagger x k x P (or uniform in [0, P) per line when the
// stagger is random). Without a trace length a line is one persistent trace.
// Traces are clipped to the bounding box grown by 1 % of its size, so that
// their ends lie outside the domain (the cutter clips them exactly).
#pragma once

#include <vector>

#include "core/geometry/polygon.h"
#include "rockmass/distributions.h"
#include "rockmass/fracture_trace.h"
#include "rockmass/rock_mass_spec.h"

namespace fissure {

/// Appends the traces of joint set `spec` (set index `set`) over `domain`
/// (its bounding box). Random choices (spacing spread, random stagger) come
/// from `rng`.
void generate_joint_set(const JointSetSpec& spec, int set, const Box& domain, Rng& rng,
                        std::vector<FractureTrace>& traces);

/// Expected number of traces of the set over `domain` (for the size check
/// before generation).
double expected_joint_traces(const JointSetSpec& spec, const Box& domain);

/// Expected trace length per unit area, P21 = persistence / spacing with
/// persistence = trace_length / (trace_length + bridge_length) (1 without
/// trace length).
double joint_set_p21(const JointSetSpec& spec);

}  // namespace fissure
