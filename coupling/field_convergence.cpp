#include "coupling/field_convergence.h"

#include <algorithm>
#include <cmath>

#include "core/base/errors.h"

namespace fissure {

FieldConvergence::FieldConvergence(const CouplingSettings::Iteration& controls)
    : controls_(controls) {}

FieldConvergence::Tolerances FieldConvergence::tolerances(const ExchangedFieldKind& field) const {
  Tolerances t{controls_.tolerance, default_absolute_tolerance(*field.quantity)};
  if (const auto it = controls_.fields.find(std::string(field.name));
      it != controls_.fields.end()) {
    t.relative = it->second.relative.value_or(t.relative);
    t.absolute = it->second.absolute.value_or(t.absolute);
  }
  return t;
}

double FieldConvergence::tolerance(const ExchangedFieldKind& field, double size) const {
  const Tolerances t = tolerances(field);
  return std::max(t.absolute, t.relative * size);
}

std::vector<FieldChange> FieldConvergence::measure(
    const std::vector<ExchangedField>& x, const std::vector<ExchangedField>& produced) const {
  FISSURE_CHECK(x.size() == produced.size(), std::logic_error,
                "convergence test of " << produced.size() << " fields against " << x.size());
  std::vector<FieldChange> changes;
  for (std::size_t f = 0; f < x.size(); ++f) {
    const std::vector<double>& a = x[f].values;
    const std::vector<double>& b = produced[f].values;
    FISSURE_CHECK(a.size() == b.size(), std::logic_error,
                  "convergence test of " << b.size() << " values against " << a.size());
    FieldChange c;
    c.kind = produced[f].kind;
    for (std::size_t i = 0; i < a.size(); ++i) {
      // A NaN change is never within a tolerance.
      const double d = std::abs(b[i] - a[i]);
      c.change = std::isnan(d) ? d : std::max(c.change, d);
      c.size = std::max(c.size, std::abs(b[i]));
      if (std::isnan(c.change)) break;
    }
    c.tolerance = tolerance(*c.kind, c.size);
    changes.push_back(c);
  }
  return changes;
}

nlohmann::json& FieldConvergence::record(const ExchangedFieldKind& field) {
  nlohmann::json& r = records_[std::string(field.name)];
  if (r.is_null()) {
    const Tolerances t = tolerances(field);
    r = {{"unit", field.quantity->plain_unit},
         {"relative_tolerance", t.relative},
         {"absolute_tolerance", t.absolute},
         {"passes_over_tolerance", 0},
         {"steps_not_converged", 0},
         {"last_change", 0.0},
         {"last_magnitude", 0.0}};
  }
  return r;
}

void FieldConvergence::record_pass(const std::vector<FieldChange>& changes) {
  for (const FieldChange& c : changes) {
    nlohmann::json& r = record(*c.kind);
    if (!c.converged()) r["passes_over_tolerance"] = r["passes_over_tolerance"].get<long>() + 1;
  }
}

void FieldConvergence::record_accepted(const std::vector<FieldChange>& changes) {
  for (const FieldChange& c : changes) {
    nlohmann::json& r = record(*c.kind);
    if (!c.converged()) r["steps_not_converged"] = r["steps_not_converged"].get<long>() + 1;
    // An accepted pass is finite (a non-finite state rejects the step).
    r["last_change"] = c.change;
    r["last_magnitude"] = c.size;
  }
}

}  // namespace fissure
