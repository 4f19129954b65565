// The permeability of materials with a stress law (permeability_law.h,
// docs/continuum.md section 9), per triangle from the
// mean effective stress at its centroid. A step of the continuum is then
// nonlinear in p: H and G are assembled again from the tensors of the last
// pass's fields until they change by less than kPermeabilityTolerance
// (continuum_process.cpp): after each pass of a staggered scheme, so that
// the split and the tensors converge together, or as Picard passes of the
// whole monolithic step.
#pragma once

#include "continuum/poroelasticity/continuum_mesh.h"
#include "continuum/poroelasticity/continuum_settings.h"
#include "continuum/poroelasticity/poroelastic_matrices.h"
#include "continuum/poroelasticity/poroelastic_solver.h"

namespace fissure::continuum {

/// The relative change of the tensors below which a step's passes stop:
/// that of the split's passes (continuum.tolerance's default), so that the
/// fields are as converged as with a constant permeability and runs agree
/// across builds to the same 1e-8 (1e-8 left 1e-8 differences from a pass
/// more or less, as large as a +0.1 % change of a heat capacity 50 years
/// into the Sellafield far field). A few passes more per step.
inline constexpr double kPermeabilityTolerance = 1e-10;
/// Passes beyond which a step whose tensors still change is refused (a
/// contraction would have settled long before; a smaller step helps).
inline constexpr int kMostPermeabilityPasses = 50;

/// Sets m.permeability of the triangles whose material has a law to the
/// law at the fields `s` (the other triangles keep theirs); returns the
/// largest change of a triangle's tensor relative to its largest component.
double update_stress_permeability(const ContinuumMesh& mesh, const ContinuumControls& c,
                                  const PoroState& s, PoroelasticMatrices& m);

}  // namespace fissure::continuum
