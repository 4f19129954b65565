// Values linear along segments tied to a continuum interface, given to the
// continuum on the segments' pieces between its nodes: the mortar shared by
// the block mechanics' ties (tractions, interface_ties.h) and the heat's
// (heat fluxes, thermal/conduction/thermal_ties.h). Per segment (a block
// edge, a thermal mesh's boundary edge) its pieces along the interface's
// edges and its two end nodes (a block's vertices, a mesh's nodes: two
// segments along one line that share one are continuous there), and the
// conversions
// between
//  * tau, the value per node on the discrete side (the traction on a block,
//    the heat flux into it), linear along each segment: the discrete side's
//    own trace space, so that no mode of tau is felt by neither side (a
//    value per segment end would let the jumps between two segments of one
//    block drift, unfelt, through the passes);
//  * the pieces the continuum is given, -tau (continuum_interface_loads);
//  * the resultants per node, f_j = int N_j tau ds = M tau, M the segments'
//    mass matrix: what the iterated scheme tests and relaxes (a sliver's
//    value may be large while its resultant is small).
#pragma once

#include <Eigen/SparseCholesky>
#include <array>
#include <cmath>
#include <map>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "core/base/errors.h"
#include "core/state/rock_mass.h"
#include "rockmass/fields/continuum_interface.h"

namespace fissure {

namespace mortar_detail {
inline int components(const Vec2&) {
  return 2;
}
inline int components(double) {
  return 1;
}
inline double& component(Vec2& v, int c) {
  return v(c);
}
inline double& component(double& v, int) {
  return v;
}
inline double value_of(const Vec2& v, int c) {
  return v(c);
}
inline double value_of(double v, int) {
  return v;
}
inline const double& component(const Vec2& v, int c) {
  return v(c);
}
inline const double& component(const double& v, int) {
  return v;
}
template <class T>
T zero() {
  if constexpr (std::is_same_v<T, double>)
    return 0.0;
  else
    return T::Zero();
}
}  // namespace mortar_detail

template <class T>
class InterfaceMortar {
 public:
  /// The member of ContinuumInterfaceLoad that carries the pieces.
  using Member = std::vector<InterfacePiece<T>> ContinuumInterfaceLoad::*;
  struct Segment {
    int interface = -1;            ///< index into names()
    Vec2 a, b;                     ///< its ends at the start
    int node_a = -1, node_b = -1;  ///< its ends' nodes (index into the values per node)
    std::vector<SegmentPiece> pieces;
    double length() const { return (b - a).norm(); }
  };

  explicit InterfaceMortar(Member member) : member_(member) {}

  /// Adds the segment [a, b] of interface `i` between the discrete side's
  /// nodes `key_a` and `key_b` (any numbers naming them) when it lies along
  /// it (pieces_along covers it); whether it was added. Call finish() after
  /// the last.
  bool add(const ContinuumInterface& i, const Vec2& a, const Vec2& b, long key_a, long key_b) {
    std::vector<SegmentPiece> pieces = pieces_along(i, a, b);
    if (pieces.empty()) return false;
    int k = 0;
    while (k < static_cast<int>(names_.size()) && names_[k] != i.name) ++k;
    if (k == static_cast<int>(names_.size())) names_.push_back(i.name);
    // A node is shared by the segments along one straight line only: where
    // the line turns (a corner of the interface) tau may jump, as sigma n
    // and q . n of a uniform field do.
    const Vec2 d = (b - a).normalized();
    const double angle =
        std::atan2(d.y(), d.x()) + (d.y() < 0 || (d.y() == 0 && d.x() < 0) ? M_PI : 0);
    const long line = std::lround(angle * 1e6);
    auto node = [&](long key) {
      return nodes_.try_emplace({key, line}, static_cast<int>(nodes_.size())).first->second;
    };
    segments_.push_back({k, a, b, node(key_a), node(key_b), std::move(pieces)});
    return true;
  }
  /// The mass matrix of the values per node, int N_i N_j ds, factorized.
  void finish() {
    std::vector<Eigen::Triplet<double>> entries;
    for (const Segment& s : segments_) {
      const double l = s.length();
      entries.emplace_back(s.node_a, s.node_a, l / 3);
      entries.emplace_back(s.node_b, s.node_b, l / 3);
      entries.emplace_back(s.node_a, s.node_b, l / 6);
      entries.emplace_back(s.node_b, s.node_a, l / 6);
    }
    Eigen::SparseMatrix<double> m(n_nodes(), n_nodes());
    m.setFromTriplets(entries.begin(), entries.end());
    mass_ = std::make_shared<Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>>>(m);
    FISSURE_CHECK(mass_->info() == Eigen::Success, std::logic_error,
                  "the tied segments' mass matrix is singular");
  }
  bool empty() const { return segments_.empty(); }
  std::size_t size() const { return segments_.size(); }
  int n_nodes() const { return static_cast<int>(nodes_.size()); }
  const Segment& segment(std::size_t k) const { return segments_[k]; }
  const std::vector<std::string>& names() const { return names_; }

  /// tau per node as the continuum carries it now (its pieces, turned);
  /// zero where nothing is given. A segment's pieces follow one another as
  /// give() writes them; its longest fixes its ends' values.
  std::vector<T> carried(const RockMass& state) const {
    std::vector<T> tau(n_nodes(), zero());
    const auto* loads = state.fields.find(kContinuumInterfaceLoads);
    if (!loads) return tau;
    std::vector<const std::vector<InterfacePiece<T>>*> given(names_.size(), nullptr);
    std::vector<std::size_t> expected(names_.size(), 0), next(names_.size(), 0);
    for (const Segment& s : segments_) expected[s.interface] += s.pieces.size();
    for (std::size_t k = 0; k < names_.size(); ++k)
      if (const ContinuumInterfaceLoad* l = find_interface(*loads, names_[k]))
        if ((l->*member_).size() == expected[k]) given[k] = &(l->*member_);
    for (const Segment& s : segments_) {
      std::size_t& n = next[s.interface];
      if (!given[s.interface]) continue;
      std::size_t best = 0;
      for (std::size_t q = 1; q < s.pieces.size(); ++q)
        if (std::abs(s.pieces[q].t1 - s.pieces[q].t0) >
            std::abs(s.pieces[best].t1 - s.pieces[best].t0))
          best = q;
      const InterfacePiece<T>& piece = (*given[s.interface])[n + best];
      const double t0 = s.pieces[best].t0, t1 = s.pieces[best].t1;
      const T slope = (piece.t1 - piece.t0) / (t1 - t0);
      tau[s.node_a] = -(piece.t0 - t0 * slope);
      tau[s.node_b] = -(piece.t0 + (1 - t0) * slope);
      n += s.pieces.size();
    }
    return tau;
  }

  /// Gives the continuum -tau (per node) on every segment's pieces.
  void give(RockMass& state, const std::vector<T>& tau) const {
    FISSURE_CHECK(tau.size() == nodes_.size(), std::logic_error,
                  tau.size() << " values for " << nodes_.size() << " tied nodes");
    auto& loads = state.fields.get_or_add(kContinuumInterfaceLoads);
    for (const std::string& name : names_) (interface_load(loads, name).*member_).clear();
    for (const Segment& s : segments_) {
      auto& pieces = find_interface(loads, names_[s.interface])->*member_;
      const T &ta = tau[s.node_a], &tb = tau[s.node_b];
      for (const SegmentPiece& p : s.pieces)
        pieces.push_back(
            {p.edge, p.s0, p.s1, -((1 - p.t0) * ta + p.t0 * tb), -((1 - p.t1) * ta + p.t1 * tb)});
    }
  }

  /// tau = M^-1 g, g the resultants per node.
  std::vector<T> project(const std::vector<T>& g) const {
    const int n = mortar_detail::components(zero());
    std::vector<T> tau(g.size(), zero());
    Eigen::VectorXd rhs(g.size());
    for (int c = 0; c < n; ++c) {
      for (std::size_t j = 0; j < g.size(); ++j) rhs(j) = mortar_detail::value_of(g[j], c);
      const Eigen::VectorXd x = mass_->solve(rhs);
      for (std::size_t j = 0; j < g.size(); ++j) mortar_detail::component(tau[j], c) = x(j);
    }
    return tau;
  }

  /// The resultants per node of what the continuum carries (f = -M tau),
  /// flattened by component: the exchanged values.
  std::vector<double> given_resultants(const RockMass& state) const {
    const std::vector<T> tau = carried(state);
    std::vector<T> f(tau.size(), zero());
    for (const Segment& s : segments_) {
      const double l = s.length();
      f[s.node_a] -= l / 6 * (2 * tau[s.node_a] + tau[s.node_b]);
      f[s.node_b] -= l / 6 * (tau[s.node_a] + 2 * tau[s.node_b]);
    }
    std::vector<double> out;
    for (const T& v : f)
      for (int c = 0; c < mortar_detail::components(v); ++c)
        out.push_back(mortar_detail::value_of(v, c));
    return out;
  }
  /// And back: the continuum given -M^-1 f.
  void set_given_resultants(RockMass& state, std::span<const double> f) const {
    const int n = mortar_detail::components(zero());
    FISSURE_CHECK(f.size() == n * nodes_.size(), std::logic_error,
                  f.size() << " resultants for " << nodes_.size() << " tied nodes");
    std::vector<T> g(nodes_.size(), zero());
    std::size_t i = 0;
    for (T& v : g)
      for (int c = 0; c < n; ++c) mortar_detail::component(v, c) = -f[i++];
    give(state, project(g));
  }

  /// The number of exchanged values (given_resultants' size).
  std::size_t n_values() const {
    return nodes_.size() * static_cast<std::size_t>(mortar_detail::components(zero()));
  }

  /// Every value of the pieces given, in order: what a checkpoint holds.
  std::vector<double> values(const RockMass& state) const {
    std::vector<double> out;
    for_each_value(state, [&](double v) { out.push_back(v); });
    return out;
  }
  /// And back, from a checkpoint: its values must be as many.
  void set_values(RockMass& state, const std::vector<double>& values) const {
    std::size_t n = 0;
    for_each_value(state, [&](double) { ++n; });
    FISSURE_CHECK(
        n == values.size(), IoError,
        "the checkpoint holds " << values.size() << " interface values; the ties give " << n);
    std::size_t k = 0;
    for_each_value(state, [&](double& v) { v = values[k++]; });
  }

  /// The published interface of names()[interface].
  const ContinuumInterface& published(const RockMass& state, int interface) const {
    const ContinuumInterface* i =
        find_interface(state.fields.get(kContinuumInterfaces), names_[interface]);
    FISSURE_CHECK(i, std::logic_error, "no interface '" << names_[interface] << "' published");
    return *i;
  }

 private:
  static T zero() { return mortar_detail::zero<T>(); }
  template <class State, class Visit>
  void for_each_value(State& state, Visit&& visit) const {
    auto* loads = state.fields.find(kContinuumInterfaceLoads);
    if (!loads) return;
    for (const std::string& name : names_)
      for (auto& l : *loads) {
        if (l.name != name) continue;
        for (auto& p : l.*member_)
          for (auto* v : {&p.t0, &p.t1})
            for (int c = 0; c < mortar_detail::components(*v); ++c)
              visit(mortar_detail::component(*v, c));
      }
  }

  Member member_;
  std::vector<std::string> names_;
  std::vector<Segment> segments_;
  /// The discrete side's keys and the line's direction -> node index.
  std::map<std::pair<long, long>, int> nodes_;
  std::shared_ptr<Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>>> mass_;
};

}  // namespace fissure
