// A block region tied to a continuum interface (docs/architecture.md 5, "A
// discrete region inside the continuum"): the blocks' boundary edges that
// lie along an interface which takes tractions. On each tied block edge a
// traction tau (Pa), linear along the edge, acts on the block, and turned
// on the continuum (the `traction_pieces` of continuum_interface_loads: the
// edge cut at the continuum's nodes, integrated by the continuum exactly).
// The blocks' edges are held by a Robin condition: in a step the traction
// on a block edge is
//   lambda(X) + p (X + u_c(X) - x(X)),
// lambda the traction the continuum last carried (turned), u_c its
// displacement at the edge point's place (its P2 trace), X the point's
// position at the start, x its position at the step's end, and p the
// continuum's interface stiffness (ContinuumInterface::impedance). After the
// step the blocks give the continuum that traction projected on the linear
// ones of each block edge, tau = M^-1 int N_j (lambda + p (X + u_c - x)) ds
// (M the edge's 2 x 2 mass matrix). A fixed point has int N_j (X + u_c - x)
// = 0 on every block edge (the mortar condition, with the multipliers on
// the block side: the blocks' edges can follow any of them, the continuum
// follows the blocks between), and at every pass the forces balance: both
// sides are loaded by the same traction over the same pieces (force and
// moment conserved to round-off). A uniform stress is a fixed point: its
// traction is constant on each block edge and both sides' displacements are
// affine. Shared by the block processes (the DDA and the DEM), which add the
// springs to their own equations.
#pragma once

#include <array>
#include <span>
#include <string>
#include <vector>

#include "core/geometry/vec2.h"
#include "core/scene/exchanged_field.h"
#include "core/state/rock_mass.h"
#include "rockmass/fields/continuum_interface.h"
#include "rockmass/physical_quantities.h"

namespace fissure {

/// What a block process with ties exchanges in the iterated scheme: the
/// tractions it gives the continuum, as the forces they put on each tied
/// block edge's two ends (int N_j tau ds, N/m): a sliver's traction may be
/// large while its force is small, and the iteration should weigh the
/// forces.
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
  /// tractions (both ends and the middle within interface_tolerance), from
  /// the blocks' positions at the start. None without interfaces.
  static InterfaceTies find(const RockMass& state);

  bool empty() const { return edges_.empty(); }
  /// The tied block edges.
  std::size_t size() const { return edges_.size(); }

  /// The springs of this step: the continuum's trace and the traction it
  /// was last given (that of the prestressed blocks, first_tractions,
  /// before any).
  std::vector<TieSpring> springs(const RockMass& state) const;
  /// Gives the continuum the traction that balances each block's stress on
  /// its tied edges, -sigma n: what holds a prestressed block region at
  /// rest at the start.
  void give_first_tractions(RockMass& state) const;
  /// Gives the continuum the tractions of the springs at the blocks' present
  /// positions, projected per block edge (see above).
  void give_tractions(RockMass& state, const std::vector<TieSpring>& springs) const;

  /// The tractions given, as the forces at each tied edge's ends (x, y of
  /// the first end, then of the second; kTieTractions), and back.
  std::vector<double> given_forces(const RockMass& state) const;
  void set_given_forces(RockMass& state, std::span<const double> forces) const;

  /// Visits the components of the tractions given (at the pieces' ends), as
  /// visit(0, double&) or visit(0, double): what a checkpoint holds.
  template <class State, class Visit>
  void for_each_traction(State& state, Visit&& visit) const {
    auto* loads = state.fields.find(kContinuumInterfaceLoads);
    if (!loads) return;
    for (const Tied& i : interfaces_)
      for (auto& l : *loads) {
        if (l.name != i.name) continue;
        for (auto& p : l.traction_pieces)
          for (auto* t : {&p.t0, &p.t1}) {
            visit(0, t->x());
            visit(0, t->y());
          }
      }
  }

 private:
  /// A piece of a tied block edge within one continuum edge.
  struct Piece {
    int edge = -1;          ///< the continuum's
    double s0 = 0, s1 = 0;  ///< its ends on the continuum's edge
    double t0 = 0, t1 = 0;  ///< and on the block's
  };
  struct TiedEdge {
    int interface = -1;
    int block = -1, a = -1, b = -1;
    Vec2 start_a, start_b;  ///< the ends' positions at the start
    std::vector<Piece> pieces;
  };
  /// An interface with tied edges.
  struct Tied {
    std::string name;
  };
  const ContinuumInterface& published(const RockMass& state, int interface) const;
  /// Per tied edge, the traction at its two ends (on the block) that the
  /// continuum carries now: that of the loads' pieces, turned; zero where
  /// none is given.
  std::vector<std::array<Vec2, 2>> carried_tractions(const RockMass& state) const;
  /// Gives the continuum, per interface, the pieces of every tied edge
  /// with the traction -tau of its ends (on the blocks: tau).
  void give(RockMass& state, const std::vector<std::array<Vec2, 2>>& tau) const;

  std::vector<Tied> interfaces_;
  std::vector<TiedEdge> edges_;
};

}  // namespace fissure
