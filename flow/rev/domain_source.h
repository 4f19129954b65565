// Where the REV study gets its networks (theory.md 3.7): "the fracture graph
// of the DFN clipped to this square rotated by theta". Sources are pluggable:
// parallel joint sets (verification.md (g)), traces of a DFN realization (any
// generator, e.g. mechanics/blocks through coupling/), ...
#pragma once

#include <cmath>
#include <functional>
#include <memory>
#include <mutex>
#include <numbers>
#include <string>
#include <vector>

#include "flow/network/trace_network.h"
#include "rockmass/fracture_graph.h"

namespace fissure::flow {

class DomainSource {
 public:
  virtual ~DomainSource() = default;
  /// The network in the square of side `size` centred on the source's
  /// centre, rotated by `angle` (rad, counter-clockwise). The graph is in the
  /// square's own frame: origin at its centre, x along its rotated side, so
  /// the square is [-size/2, size/2]^2, with boundaries left, right, bottom,
  /// top. Must be safe to call from several threads at once.
  virtual FractureGraph domain(int realization, double size, double angle) const = 0;
  /// Realizations this source can give (a deterministic source has 1).
  virtual int max_realizations() const { return 1 << 30; }
  virtual std::string describe() const = 0;
  /// Expected nodes of the network in a square of side `size` (fracture
  /// crossings plus trace ends): the measure of a study's work and memory,
  /// checked before anything is built (rev_study.h, check_study_size).
  virtual double expected_nodes(double size) const = 0;
};

/// The frame of a square centred on `centre` and turned by `angle` (rad):
/// origin at its centre, x along its turned side.
class SquareFrame {
 public:
  SquareFrame(const Vec2& centre, double size, double angle)
      : centre_(centre),
        c_(std::cos(angle)),
        s_(std::sin(angle)),
        reach_(size * std::numbers::sqrt2 / 2) {}
  /// A point in the square's frame.
  Vec2 operator()(const Vec2& x) const {
    const Vec2 d = x - centre_;
    return Vec2(c_ * d.x() + s_ * d.y(), -s_ * d.x() + c_ * d.y());
  }
  /// Cheap rejection: false when the segment's bounding circle misses the
  /// square's.
  bool may_reach(const Vec2& a, const Vec2& b) const {
    return (0.5 * (a + b) - centre_).norm() <= reach_ + 0.5 * (b - a).norm();
  }

 private:
  Vec2 centre_;
  double c_, s_, reach_;
};

/// Rotates traces about `centre` by -angle into the square's frame and
/// builds the clipped network (trace_network.h). Tolerance 1e-9 x size.
FractureGraph domain_from_traces(const std::vector<Trace>& traces, const Vec2& centre, double size,
                                 double angle);

/// A parallel joint set: infinite straight fractures at `angle` (rad, the
/// direction of the traces), spaced `spacing` apart, one of them at distance
/// `offset` from the centre (along the set's normal).
struct ParallelSet {
  double angle = 0;
  double spacing = 1;
  double aperture = 1e-4;
  double offset = 0;
};

/// Regular network of parallel sets (deterministic: one realization).
class ParallelSetsSource final : public DomainSource {
 public:
  explicit ParallelSetsSource(std::vector<ParallelSet> sets, Vec2 centre = Vec2::Zero())
      : sets_(std::move(sets)), centre_(centre) {}
  FractureGraph domain(int realization, double size, double angle) const override;
  int max_realizations() const override { return 1; }
  std::string describe() const override;
  double expected_nodes(double size) const override;
  const std::vector<ParallelSet>& sets() const { return sets_; }

 private:
  std::vector<ParallelSet> sets_;
  Vec2 centre_;
};

/// What a trace generator is expected to draw: traces and crossings per unit
/// area (for a stochastic DFN, rockmass/block_estimate.h), or, for a fixed
/// list, its number of traces (whose crossings it bounds).
struct TraceDensity {
  double traces_per_area = 0;     ///< P20, 1/m^2
  double crossings_per_area = 0;  ///< 1/m^2
  double fixed_traces = 0;        ///< a fixed list: every domain has at most these
};

/// Realizations from a trace generator (e.g. a stochastic DFN): realization
/// r's traces are generated once, on first use, and kept.
class TraceSource final : public DomainSource {
 public:
  using Generator = std::function<std::vector<Trace>(int realization)>;
  /// `max_realizations` is 1 for a fixed set of traces (every realization
  /// would be the same network).
  TraceSource(Generator generator, Vec2 centre, std::string description, TraceDensity density,
              int max_realizations = 1 << 30)
      : generator_(std::move(generator)),
        centre_(centre),
        description_(std::move(description)),
        density_(density),
        max_realizations_(max_realizations) {}
  FractureGraph domain(int realization, double size, double angle) const override;
  int max_realizations() const override { return max_realizations_; }
  std::string describe() const override { return description_; }
  double expected_nodes(double size) const override;

 private:
  const std::vector<Trace>& traces(int realization) const;

  Generator generator_;
  Vec2 centre_;
  std::string description_;
  TraceDensity density_;
  int max_realizations_;
  mutable std::mutex mutex_;
  mutable std::vector<std::unique_ptr<std::vector<Trace>>> cache_;
};

}  // namespace fissure::flow
