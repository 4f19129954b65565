// A block region tied to a continuum interface (docs/architecture.md 5, "A
// discrete region inside the continuum"): the blocks' boundary edges that
// lie along an interface which takes tractions, on the mortar of
// interface_mortar.h. A traction tau (Pa) per tied block vertex, linear
// along each tied edge, acts on the blocks, and turned on the continuum
// (the `traction_pieces` of continuum_interface_loads: the edges cut at the
// continuum's nodes, integrated by the continuum exactly). In a step the
// traction on a tied edge is the Robin condition
//   lambda(X) + p (X + u_c(X) - x(X)),
// lambda the traction the continuum carries (turned), u_c its displacement
// at the edge point's place (its P2 trace), X the point's position at the
// start, x its position at the step's end, and p the continuum's interface
// stiffness (ContinuumInterface::impedance). After the step the blocks give
// the continuum that traction projected on the tied vertices, tau = M^-1
// int N_j (lambda + p (X + u_c - x)) ds. A fixed point has int N_j (X + u_c
// - x) ds = 0 at every tied vertex (the mortar condition, with the
// multipliers on the blocks' side), and at every pass the forces balance:
// both sides are loaded by the same traction over the same pieces (force
// and moment conserved to round-off). A uniform stress is a fixed point: its
// traction is constant along each side and both sides' displacements are
// affine. Shared by the block processes (the DDA and the DEM), which add the
// springs to their own equations.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "core/geometry/vec2.h"
#include "core/process/exchanged_values.h"
#include "core/scene/exchanged_field.h"
#include "core/state/rock_mass.h"
#include "rockmass/fields/continuum_interface.h"
#include "rockmass/fields/interface_mortar.h"
#include "rockmass/physical_quantities.h"

namespace fissure {

/// What a block process with ties exchanges in the iterated scheme: the
/// tractions it gives the continuum, as the forces they put on the tied
/// vertices (int N_j tau ds, N/m): a sliver's traction may be large while
/// its force is small, and the iteration should weigh the forces.
inline constexpr ExchangedFieldKind kTieTractions{"continuum_interface_loads.traction",
                                                  &quantity::linear_force};

/// One quadrature point of a tied block edge in a step: the force its
/// spring and the given traction put on the block there, w (lambda + p
/// (target - x)), with stiffness w p.
struct TieSpring {
  int block = -1;
  int a = -1, b = -1;    ///< the block edge's vertices
  double t = 0;          ///< the point's place on the edge, from a to b
  int edge = -1;         ///< the tied edge's index (InterfaceTies)
  double weight = 0;     ///< quadrature weight times length, m
  Vec2 target;           ///< X + u_c(X), m
  double stiffness = 0;  ///< w p, N/m per m of thickness
  Vec2 force;            ///< w lambda, N/m

  /// The point's present position (the block's vertices are affine in it).
  Vec2 position(const RockMass& state) const {
    const std::vector<Vec2>& v = state.blocks[block].polygon.vertices;
    return (1 - t) * v[a] + t * v[b];
  }
};

class InterfaceTies {
 public:
  /// The edges of free blocks that lie along an interface which takes
  /// tractions (pieces_along covers them), from the blocks' positions at
  /// the start. None without interfaces.
  static InterfaceTies find(const RockMass& state);

  bool empty() const { return mortar_.empty(); }
  /// The tied block edges.
  std::size_t size() const { return mortar_.size(); }
  /// Tied edge k: its block and the vertices it runs from and to.
  std::array<int, 3> edge(std::size_t k) const {
    return {edges_[k].block, edges_[k].a, edges_[k].b};
  }

  /// The springs of this step: the continuum's trace and the traction it
  /// carries (that of the prestressed blocks, give_first_tractions, before
  /// any).
  std::vector<TieSpring> springs(const RockMass& state) const;
  /// Gives the continuum the traction that balances each block's stress on
  /// its tied edges, -sigma n: what holds a prestressed block region at
  /// rest at the start.
  void give_first_tractions(RockMass& state) const;
  /// Gives the continuum the tractions of the springs at the blocks' present
  /// positions, projected per block edge (see above).
  void give_tractions(RockMass& state, const std::vector<TieSpring>& springs) const;
  /// The same with the springs' present positions `at` (a process whose
  /// blocks deform between their vertices: the DEM's zoned blocks).
  void give_tractions(RockMass& state, const std::vector<TieSpring>& springs,
                      const std::vector<Vec2>& at) const;

  /// The mortar: the exchanged values (kTieTractions: its resultants) and
  /// what a checkpoint holds (its values).
  const InterfaceMortar<Vec2>& mortar() const { return mortar_; }
  /// A block process's Process::exchanged_values and
  /// set_exchanged_values: the forces it gives (kTieTractions); none, and
  /// nothing set, without ties or when the layout differs (none given yet,
  /// as scatter_exchanged leaves it).
  std::vector<ExchangedField> exchanged_values(const RockMass& state) const;
  void set_exchanged_values(RockMass& state, std::span<const ExchangedField> values) const;

 private:
  struct TiedEdge {
    int block = -1, a = -1, b = -1;
  };
  InterfaceMortar<Vec2> mortar_{&ContinuumInterfaceLoad::traction_pieces};
  std::vector<TiedEdge> edges_;  ///< per segment of mortar_
};

}  // namespace fissure
