// The total stress in a triangle of the continuum (theory.md 5.1):
//   sigma = sigma_0(y) + D eps(u) - (alpha (p - p_0) + 3 K alpha_T (T - T_0)) m,
// tension +, with the out-of-plane (plane strain) or hoop (axisymmetric)
// component: for the output, the monitors and the stress-dependent
// permeability.
#pragma once

#include "continuum/poroelasticity/continuum_mesh.h"
#include "continuum/poroelasticity/continuum_settings.h"
#include "continuum/poroelasticity/poroelastic_matrices.h"
#include "continuum/poroelasticity/poroelastic_solver.h"

namespace fissure::continuum {

/// sxx, syy, sxy, szz in triangle `t` at barycentric point `w` of the fields `s`.
Vector4 total_stress(const ContinuumMesh& mesh, const ContinuumControls& c,
                     const PoroelasticMatrices& m, const PoroState& s, int t,
                     const Eigen::Vector3d& w);

}  // namespace fissure::continuum
