// Non-reflecting (viscous) boundaries for dynamic DDA (docs/dda.md section
// 10; Lysmer and Kuhlemeyer 1969; in DDA's implicit equations after Bao,
// Hatzor and Huang 2012). Each block edge on a boundary line carries
// dashpots, the traction
//   t = -rho c_p ((v - v_ref).n) n - rho c_s ((v - v_ref).s) s
// with n the edge's outward normal, s its direction, c_p and c_s the wave
// speeds of the medium beyond (plane strain or stress as the scene), and v
// the velocity at the end of the step, v1 = T(x) (2 d / dt - v0) (Newmark
// beta = 1/2, gamma = 1, as the blocks' inertia). A plane wave of normal
// incidence leaves through it without reflection.
//
// Free-field input (Joyner and Chen 1975): a wave u_in coming up from the
// half-space the boundary replaces enters as the traction rho c (2 v_in - v):
// the dashpots act on the velocity relative to v_ref = 2 v_in, the outcrop
// motion (what a recording on rock at the surface gives). With
// `free_field`, v_ref is the ground motion's velocity.
//
// The edge's integrals of T^T C T are quadratic along it: Simpson's rule
// on its ends and midpoint is exact.
#pragma once

#include <span>
#include <vector>

#include "core/state/rock_mass.h"
#include "mechanics/dda/block_kinematics.h"
#include "mechanics/dda/dda_settings.h"

namespace fissure::dda {

/// Dashpots along the edge vertex -> next(vertex) of a free block.
struct ViscousEdge {
  int block = -1, vertex = -1;
  double normal_impedance = 0;  ///< rho c_p (Pa s/m)
  double shear_impedance = 0;   ///< rho c_s (Pa s/m)
  bool free_field = false;
};

/// The edges of free blocks that lie on each boundary's line (both ends
/// within 1e-6 of the line's length of it). Throws SceneError, naming the
/// boundary's place in the scene, for a line no free block edge lies on.
std::vector<ViscousEdge> find_viscous_edges(const RockMass& state,
                                            std::span<const ViscousBoundaryControls> boundaries,
                                            PlaneMode plane);

/// Adds the edge's dashpots for a step of length dt to its block's diagonal
/// `k` and load `rhs`: (2 / dt) int T^T C T ds and int T^T C (T v0 + v_ref) ds,
/// v0 the block's carried-over start velocity, v_ref the reference velocity
/// (zero unless free_field).
void add_viscous_edge(const ViscousEdge& edge, const Block& block, const Vector6& v0,
                      const Vec2& reference_velocity, double dt, Matrix6& k, Vector6& rhs);

/// The work the edge's dashpots did on its block over an accepted step
/// (J per unit thickness, start-of-step geometry): -int (T v1 - v_ref).C T d ds
/// for the increment d and the end velocity v1.
double viscous_work(const ViscousEdge& edge, const Block& block, const Vector6& end_velocity,
                    const Vector6& increment, const Vec2& reference_velocity);

}  // namespace fissure::dda
