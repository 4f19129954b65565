#include "coupling/upscaling/scene_rock_mass_source.h"

#include <fmt/format.h>

#include <cmath>
#include <numbers>

#include "core/base/errors.h"
#include "rockmass/block_estimate.h"
#include "rockmass/generate_rock_mass.h"

namespace fissure {

SceneRockMassSource::SceneRockMassSource(std::shared_ptr<const Scene> scene,
                                         std::optional<Vec2> centre)
    : scene_(std::move(scene)) {
  spec_ = scene_->sections.find(kRockMassSpec);
  FISSURE_CHECK(spec_, SceneError,
                scene_->source.string() << ": found no rock_mass section; expected a scene whose "
                                           "rock_mass the REV study's domains are cut from");
  Box box;
  for (const Vec2& p : spec_->domain) box.extend(p);
  centre_ = centre ? *centre : Vec2(0.5 * (box.lo + box.hi));
  const RockMassEstimate e = estimate_rock_mass(*spec_);
  const double area = std::abs(signed_area(spec_->domain));
  nodes_per_area_ = area > 0 ? (2 * e.fractures + e.intersections) / area : 0;
}

const std::vector<FractureTrace>& SceneRockMassSource::traces(int realization) const {
  std::lock_guard lock(mutex_);
  if (static_cast<int>(cache_.size()) <= realization) cache_.resize(realization + 1);
  if (!cache_[realization])
    cache_[realization] =
        std::make_unique<std::vector<FractureTrace>>(generate_traces(*spec_, realization));
  return *cache_[realization];
}

std::vector<FractureTrace> SceneRockMassSource::square_traces(int realization, double size,
                                                              double angle) const {
  const flow::SquareFrame local(centre_, size, angle);
  std::vector<FractureTrace> near;
  for (const FractureTrace& t : traces(realization)) {
    if (!local.may_reach(t.a, t.b)) continue;
    FractureTrace l = t;
    l.a = local(t.a);
    l.b = local(t.b);
    near.push_back(l);
  }
  return near;
}

FractureGraph SceneRockMassSource::domain(int realization, double size, double angle) const {
  std::vector<flow::Trace> traces;
  for (const FractureTrace& t : square_traces(realization, size, angle))
    traces.push_back(flow::Trace{t.a, t.b, t.aperture, static_cast<int>(traces.size()), t.set});
  return flow::domain_from_traces(traces, Vec2::Zero(), size, 0);
}

std::string SceneRockMassSource::describe() const {
  return fmt::format("rock mass of {} ({} joint sets, {} DFN families, {} fractures; seed {})",
                     scene_->source.filename().string(), spec_->joint_sets.size(),
                     spec_->dfn.size(), spec_->fractures.size(), spec_->seed);
}

double SceneRockMassSource::expected_nodes(double size) const {
  return nodes_per_area_ * size * size;
}

}  // namespace fissure
