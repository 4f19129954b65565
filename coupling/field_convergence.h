// The iterated staggered scheme's convergence test, field by field (docs/
// architecture.md 5; OpenGeoSys's per-component criteria): a pass has
// converged when every exchanged field's largest change is within its
// absolute tolerance or its relative one times its largest magnitude,
//   max_i |x~_i - x_i| <= max(absolute, relative max_i |x~_i|),
// so that a field of small numbers (an aperture, a thermal strain) is
// judged on its own scale, never against a field of large ones (a pressure
// in Pa). Tolerances: `coupling.iteration.fields.<field>` where given, else
// `iteration.tolerance` and the default absolute tolerance of the field's
// kind (core/scene/exchanged_field.h).
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "core/process/exchanged_values.h"
#include "core/scene/scene.h"

namespace fissure {

/// One field's change in a pass.
struct FieldChange {
  const ExchangedFieldKind* kind = nullptr;
  double change = 0;     ///< max |x~ - x|, in the field's unit
  double size = 0;       ///< max |x~|
  double tolerance = 0;  ///< max(absolute, relative size)
  bool converged() const { return change <= tolerance; }
};

class FieldConvergence {
 public:
  explicit FieldConvergence(const CouplingSettings::Iteration& controls);

  /// What a field's change is measured against when its values reach `size`.
  double tolerance(const ExchangedFieldKind& field, double size) const;

  /// The change of each field from `x` to `produced` (the same fields, each
  /// of the same size).
  std::vector<FieldChange> measure(const std::vector<ExchangedField>& x,
                                   const std::vector<ExchangedField>& produced) const;

  /// Counts a pass (summary.json): the fields still over their tolerance.
  void record_pass(const std::vector<FieldChange>& changes);
  /// Keeps the last pass of an accepted step.
  void record_accepted(const std::vector<FieldChange>& changes);

  /// Per field (summary.json's coupling.iteration.fields): its unit and
  /// tolerances, the passes in which it was over them, the steps accepted
  /// with it over them, its change and magnitude in the last accepted pass.
  const nlohmann::json& statistics() const { return records_; }
  /// The same as text, for a checkpoint (doubles round-trip exactly).
  template <class Archive>
  void checkpoint(Archive& a) {
    std::string text = records_.dump();
    a("fields", text);
    records_ = nlohmann::json::parse(text);
  }

 private:
  struct Tolerances {
    double relative, absolute;
  };
  Tolerances tolerances(const ExchangedFieldKind& field) const;
  nlohmann::json& record(const ExchangedFieldKind& field);

  CouplingSettings::Iteration controls_;
  nlohmann::json records_ = nlohmann::json::object();
};

}  // namespace fissure
