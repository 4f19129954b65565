#include "flow/rev/domain_source.h"

#include <cmath>
#include <numbers>
#include <sstream>

namespace fissure::flow {

namespace {

Box square(double size) {
  Box b;
  b.lo = Vec2(-size / 2, -size / 2);
  b.hi = Vec2(size / 2, size / 2);
  return b;
}

}  // namespace

FractureGraph domain_from_traces(const std::vector<Trace>& traces, const Vec2& centre, double size,
                                 double angle) {
  const SquareFrame local(centre, size, angle);
  std::vector<Trace> near;
  for (const Trace& t : traces) {
    if (!local.may_reach(t.a, t.b)) continue;
    Trace l = t;
    l.a = local(t.a);
    l.b = local(t.b);
    near.push_back(l);
  }
  return build_trace_network(near, square(size), 1e-9 * size);
}

FractureGraph ParallelSetsSource::domain(int, double size, double angle) const {
  std::vector<Trace> traces;
  const double reach = size * std::numbers::sqrt2 / 2;
  for (std::size_t k = 0; k < sets_.size(); ++k) {
    const ParallelSet& set = sets_[k];
    // In the square's frame the set is at set.angle - angle; distances along
    // its normal are unchanged by the rotation about the centre.
    const double a = set.angle - angle;
    const Vec2 t(std::cos(a), std::sin(a)), n(-std::sin(a), std::cos(a));
    const long first = static_cast<long>(std::ceil((-reach - set.offset) / set.spacing));
    const long last = static_cast<long>(std::floor((reach - set.offset) / set.spacing));
    for (long i = first; i <= last; ++i) {
      const double d = set.offset + static_cast<double>(i) * set.spacing;
      Trace tr;
      tr.a = d * n - 2 * reach * t;
      tr.b = d * n + 2 * reach * t;
      tr.aperture = set.aperture;
      tr.joint_set = static_cast<int>(k);
      tr.fracture = static_cast<int>(traces.size());
      traces.push_back(tr);
    }
  }
  return build_trace_network(traces, square(size), 1e-9 * size);
}

std::string ParallelSetsSource::describe() const {
  std::ostringstream s;
  s << "regular network of " << sets_.size() << " parallel sets:";
  for (const ParallelSet& set : sets_)
    s << " [angle " << set.angle * 180 / std::numbers::pi << " deg, spacing " << set.spacing
      << " m, aperture " << set.aperture << " m]";
  return s.str();
}

double ParallelSetsSource::expected_nodes(double size) const {
  // A set crosses the square in at most sqrt2 size / spacing traces, two ends
  // each; two sets at angle phi cross size^2 |sin phi| / (s_a s_b) times.
  double nodes = 0;
  for (std::size_t a = 0; a < sets_.size(); ++a) {
    nodes += 2 * std::numbers::sqrt2 * size / sets_[a].spacing;
    for (std::size_t b = a + 1; b < sets_.size(); ++b)
      nodes += size * size * std::abs(std::sin(sets_[a].angle - sets_[b].angle)) /
               (sets_[a].spacing * sets_[b].spacing);
  }
  return nodes;
}

double TraceSource::expected_nodes(double size) const {
  if (density_.fixed_traces > 0) return 2 * density_.fixed_traces;
  return size * size * (2 * density_.traces_per_area + density_.crossings_per_area);
}

const std::vector<Trace>& TraceSource::traces(int realization) const {
  std::lock_guard<std::mutex> lock(mutex_);
  if (static_cast<int>(cache_.size()) <= realization) cache_.resize(realization + 1);
  if (!cache_[realization])
    cache_[realization] = std::make_unique<std::vector<Trace>>(generator_(realization));
  return *cache_[realization];
}

FractureGraph TraceSource::domain(int realization, double size, double angle) const {
  return domain_from_traces(traces(realization), centre_, size, angle);
}

}  // namespace fissure::flow
