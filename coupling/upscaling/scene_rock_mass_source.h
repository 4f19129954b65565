// The REV study's domains cut from a scene's rock mass (`network: {type:
// scene, scene: FILE}`, docs/upscaling.md): its joint sets, DFN families and
// explicit fractures, each with its joint, drawn anew per realization
// (generate_traces(spec, r): realization 0 is the scene's own rock mass).
// The geometric study sees the traces' network as any DFN source's; the
// stress stage (stressed_domain.h) takes the traces themselves and cuts them
// into blocks.
#pragma once

#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "core/scene/scene.h"
#include "flow/rev/domain_source.h"
#include "rockmass/fracture_trace.h"
#include "rockmass/rock_mass_spec.h"

namespace fissure {

class SceneRockMassSource final : public flow::DomainSource {
 public:
  /// `scene` must have a rock_mass section; the squares are centred on
  /// `centre` (the study's network.centre, else the rock mass's domain's
  /// bounding-box centre).
  SceneRockMassSource(std::shared_ptr<const Scene> scene, std::optional<Vec2> centre);

  FractureGraph domain(int realization, double size, double angle) const override;
  std::string describe() const override;
  double expected_nodes(double size) const override;

  /// Realization r's traces that may reach the square of side `size`
  /// rotated by `angle` (rad), in the square's frame (origin at its centre,
  /// x along its rotated side), with their joints and apertures; unclipped.
  std::vector<FractureTrace> square_traces(int realization, double size, double angle) const;

  const Scene& scene() const { return *scene_; }
  const RockMassSpec& spec() const { return *spec_; }
  Vec2 centre() const { return centre_; }

 private:
  const std::vector<FractureTrace>& traces(int realization) const;

  std::shared_ptr<const Scene> scene_;
  const RockMassSpec* spec_ = nullptr;
  Vec2 centre_ = Vec2::Zero();
  double nodes_per_area_ = 0;  ///< trace ends and crossings per m^2 (block_estimate.h)
  mutable std::mutex mutex_;
  mutable std::vector<std::unique_ptr<std::vector<FractureTrace>>> cache_;
};

}  // namespace fissure
