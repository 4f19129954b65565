// The generators of a rock mass: `rock_mass.joint_sets[]` (Shi's DL: dip,
// spacing, trace and bridge lengths) and `rock_mass.dfn[]` (Poisson DFN
// families with orientation, length and aperture distributions). The
// distributions and their parameters are in docs/rock-mass.md.
#include <fmt/format.h>

#include <cmath>

#include "rockmass/read_rock_mass.h"

namespace fissure {

namespace {

using Type = DistributionSpec::Type;
constexpr double kPi = 3.14159265358979323846;

/// An angle in [0, pi): a trace direction is an axis, not a vector.
double axis_angle(double a) {
  double r = std::fmod(a, kPi);
  if (r < 0) r += kPi;
  return r;
}

void read_name(ConfigMap& map, NameRegistry& sets, std::string& name, const char* what) {
  if (auto n = map.required("name", std::string("a ") + what + " name")) {
    if (auto s = n->string(std::string("a ") + what + " name")) {
      sets.add(*s, *n);
      name = *s;
      return;
    }
  }
  sets.add_unreadable();
}

/// `joints` is null outside a scene (a REV study), where a family has no joint.
void read_joint_reference(ConfigMap& map, const NameRegistry* joints, int& joint) {
  if (auto j = map.optional("joint")) {
    if (!joints)
      j->error("found " + j->found() +
               "; expected no joint (a REV study has no joints: the flow uses the family's "
               "apertures)");
    else if (auto i = joints->resolve(*j))
      joint = *i;
  }
}

// --- distributions -----------------------------------------------------------

/// Reads `key` of a distribution map into `out` (required).
void read_parameter(ConfigMap& map, std::string_view key, double& out, const QuantityKind& kind,
                    const Range& range) {
  map.read_required(key, out, kind, range);
}

DistributionSpec read_orientation(const ConfigNode& node) {
  DistributionSpec d;
  d.type = Type::Constant;
  if (node.is_scalar()) {  // `orientation: 30` = fixed
    if (auto v = node.quantity(quantity::angle)) d.value = axis_angle(*v);
    return d;
  }
  ConfigMap map(node, rock_mass_keys::dfn_orientation);
  constexpr std::string_view kTypes[] = {"fixed", "uniform", "von_mises"};
  std::optional<std::string> type;
  if (auto t = map.required("distribution", "one of: fixed, uniform, von_mises"))
    type = t->choice(kTypes);
  if (!type) return d;
  if (*type == "fixed") {
    read_parameter(map, "value", d.value, quantity::angle, Range::any());
    d.value = axis_angle(d.value);
  } else if (*type == "uniform") {
    d.type = Type::Uniform;
  } else {
    d.type = Type::VonMises;
    read_parameter(map, "mean", d.mean, quantity::angle, Range::any());
    d.mean = axis_angle(d.mean);
    read_parameter(map, "kappa", d.kappa, quantity::dimensionless, Range::closed(0, 1e6));
  }
  return d;
}

/// Trace lengths; `min < max` is checked where both are read.
DistributionSpec read_length(const ConfigNode& node) {
  DistributionSpec d;
  if (node.is_scalar()) {  // `length: 5 m` = constant
    if (auto v = node.quantity(quantity::length, Range::positive())) d.value = *v;
    return d;
  }
  ConfigMap map(node, rock_mass_keys::dfn_length);
  constexpr std::string_view kTypes[] = {"constant", "uniform", "exponential", "log_normal",
                                         "truncated_power_law"};
  std::optional<std::string> type;
  if (auto t = map.required("distribution",
                            "one of: constant, uniform, exponential, "
                            "log_normal, truncated_power_law"))
    type = t->choice(kTypes);
  if (!type) return d;
  const Range positive = Range::positive();
  auto read_bounds = [&]() {
    read_parameter(map, "min", d.min, quantity::length, positive);
    read_parameter(map, "max", d.max, quantity::length, positive);
    if (d.min > 0 && d.max > 0 && d.max <= d.min)
      map.node().error(
          fmt::format("found min = {} m and max = {} m; expected min < max", d.min, d.max));
  };
  if (*type == "constant") {
    read_parameter(map, "value", d.value, quantity::length, positive);
  } else if (*type == "uniform") {
    d.type = Type::Uniform;
    read_bounds();
  } else if (*type == "exponential") {
    d.type = Type::Exponential;
    read_parameter(map, "mean", d.mean, quantity::length, positive);
  } else if (*type == "log_normal") {
    d.type = Type::LogNormal;
    read_parameter(map, "mean", d.mean, quantity::length, positive);
    read_parameter(map, "std", d.std, quantity::length, positive);
  } else {
    d.type = Type::TruncatedPowerLaw;
    read_parameter(map, "exponent", d.exponent, quantity::dimensionless, Range::closed(0, 10));
    read_bounds();
  }
  return d;
}

DistributionSpec read_aperture(const ConfigNode& node) {
  DistributionSpec d;
  if (node.is_scalar()) {  // `aperture: 100 um` = constant
    if (auto v = node.quantity(quantity::length, aperture_range())) d.value = *v;
    return d;
  }
  ConfigMap map(node, rock_mass_keys::dfn_aperture);
  constexpr std::string_view kTypes[] = {"constant", "log_normal", "length_correlated"};
  std::optional<std::string> type;
  if (auto t = map.required("distribution", "one of: constant, log_normal, length_correlated"))
    type = t->choice(kTypes);
  if (!type) return d;
  const Range positive = Range::positive();
  if (*type == "constant") {
    read_parameter(map, "value", d.value, quantity::length, aperture_range());
  } else if (*type == "log_normal") {
    d.type = Type::LogNormal;
    read_parameter(map, "mean", d.mean, quantity::length, aperture_range());
    read_parameter(map, "std", d.std, quantity::length, positive);
    // Wider, ln e spreads by more than 2.1: apertures over more than 7 orders
    // of magnitude (4 standard deviations each way) and cubic-law conductances
    // over more than 20, which a flow network cannot resolve in double
    // precision (a REV study with std = 1000 m failed in CHOLMOD, issue 35).
    if (d.mean > 0 && d.std > kMaxApertureVariation * d.mean)
      map.node().error(fmt::format(
          "found std = {} m with mean = {} m; expected a standard deviation at most {} x the "
          "mean (the cubic-law conductances would span more than 20 orders of magnitude)",
          d.std, d.mean, kMaxApertureVariation));
  } else {
    d.type = Type::LengthCorrelated;
    read_parameter(map, "factor", d.factor, quantity::length, aperture_range());
    read_parameter(map, "exponent", d.exponent, quantity::dimensionless, Range::closed(0, 3));
  }
  return d;
}

void read_density(const ConfigNode& node, DfnFamilySpec& family) {
  ConfigMap map(node, rock_mass_keys::dfn_density);
  const bool p20 = map.contains("p20"), p21 = map.contains("p21");
  if (p20 && p21) {
    node.error("found both p20 and p21; expected one of them");
    map.optional("p20");
    map.optional("p21");
    return;
  }
  if (p20) {
    family.density_kind = DfnFamilySpec::Density::P20;
    map.read("p20", family.density, quantity::areal_density, Range::positive());
  } else if (p21) {
    family.density_kind = DfnFamilySpec::Density::P21;
    map.read("p21", family.density, quantity::fracture_intensity, Range::positive());
  } else {
    map.report_missing("p21", "p20 (fracture centres per m^2) or p21 (trace length per m^2)");
  }
}

}  // namespace

JointSetSpec read_joint_set(const ConfigNode& node, const NameRegistry& joints,
                            NameRegistry& sets) {
  ConfigMap map(node, rock_mass_keys::joint_set);
  JointSetSpec s;
  s.aperture = kDefaultAperture;
  read_name(map, sets, s.name, "joint set");
  map.read_required("dip", s.dip, quantity::angle);
  s.dip = axis_angle(s.dip);
  map.read_required("spacing", s.spacing, quantity::length, Range::positive());
  if (auto n = map.optional("spacing_spread")) {
    if (auto v = n->quantity(quantity::length, Range::non_negative())) {
      if (s.spacing > 0 && *v >= s.spacing)
        n->error(
            fmt::format("found {} m with spacing {} m; expected a spread smaller than the "
                        "spacing (spacings are uniform in [spacing - spread, spacing + "
                        "spread])",
                        *v, s.spacing));
      else
        s.spacing_spread = *v;
    }
  }
  if (auto n = map.optional("trace_length"))
    if (auto v = n->quantity(quantity::length, Range::positive())) s.trace_length = *v;
  if (auto n = map.optional("bridge_length")) {
    if (auto v = n->quantity(quantity::length, Range::non_negative())) {
      s.bridge_length = *v;
      if (!map.contains("trace_length"))
        n->error(
            "found a bridge length without trace_length; expected trace_length too (without "
            "it the traces are fully persistent)");
    }
  }
  map.read("phase", s.phase, quantity::dimensionless, Range::closed_open(0, 1));
  if (auto n = map.optional("stagger")) {
    if (n->is_scalar() && n->text() == "random")
      s.stagger.reset();
    else if (auto v = n->quantity(quantity::dimensionless, Range::closed_open(0, 1)))
      s.stagger = *v;
  }
  read_joint_reference(map, &joints, s.joint);
  map.read("aperture", s.aperture, quantity::length, aperture_range());
  return s;
}

namespace {

DfnFamilySpec read_family(const ConfigNode& node, const NameRegistry* joints, NameRegistry& sets) {
  ConfigMap map(node, rock_mass_keys::dfn_family);
  DfnFamilySpec f;
  f.aperture.value = kDefaultAperture;
  read_name(map, sets, f.name, "DFN family");
  if (auto d = map.required("density", "a map with p20 (1/m^2) or p21 (1/m)")) read_density(*d, f);
  if (auto o = map.required("orientation",
                            "an orientation distribution (fixed, uniform, "
                            "von_mises) or a fixed angle"))
    f.orientation = read_orientation(*o);
  if (auto l = map.required("length", "a length distribution or a constant length"))
    f.length = read_length(*l);
  if (auto a = map.optional("aperture")) f.aperture = read_aperture(*a);
  read_joint_reference(map, joints, f.joint);
  return f;
}

}  // namespace

DfnFamilySpec read_dfn_family(const ConfigNode& node, const NameRegistry& joints,
                              NameRegistry& sets) {
  return read_family(node, &joints, sets);
}

DfnFamilySpec read_dfn_family(const ConfigNode& node, NameRegistry& families) {
  return read_family(node, nullptr, families);
}

}  // namespace fissure
