#include "core/scene/units.h"

#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <optional>
#include <vector>

#include <fmt/format.h>

#include "core/scene/closest_match.h"
#include "core/scene/diagnostics.h"

namespace fissure {

namespace {

struct UnitDef {
  std::string_view name;
  double factor;
  Dimension dimension;
};

constexpr Dimension kMass{1, 0, 0, 0, 0};
constexpr Dimension kLength{0, 1, 0, 0, 0};
constexpr Dimension kTime{0, 0, 1, 0, 0};
constexpr Dimension kKelvin{0, 0, 0, 1, 0};
constexpr Dimension kAngle{0, 0, 0, 0, 1};
constexpr Dimension kForce{1, 1, -2, 0, 0};
constexpr Dimension kPascal{1, -1, -2, 0, 0};
constexpr Dimension kEnergy{1, 2, -2, 0, 0};
constexpr Dimension kPower{1, 2, -3, 0, 0};
constexpr Dimension kFrequency{0, 0, -1, 0, 0};

constexpr double kYear = 365.25 * 86400;  // Julian year

// Every unit a scene may use; the names are matched exactly (case matters:
// "MPa" is not "mPa"). No automatic prefixes, so "min", "Pa" and "t" are never
// ambiguous.
constexpr UnitDef kUnits[] = {
    {"m", 1, kLength},        {"cm", 1e-2, kLength},      {"mm", 1e-3, kLength},
    {"um", 1e-6, kLength},    {"\u00b5m", 1e-6, kLength}, {"km", 1e3, kLength},
    {"kg", 1, kMass},         {"g", 1e-3, kMass},         {"t", 1e3, kMass},
    {"s", 1, kTime},          {"ms", 1e-3, kTime},        {"us", 1e-6, kTime},
    {"\u00b5s", 1e-6, kTime}, {"min", 60, kTime},         {"h", 3600, kTime},
    {"d", 86400, kTime},      {"yr", kYear, kTime},       {"Hz", 1, kFrequency},
    {"Pa", 1, kPascal},       {"kPa", 1e3, kPascal},      {"MPa", 1e6, kPascal},
    {"GPa", 1e9, kPascal},    {"N", 1, kForce},           {"kN", 1e3, kForce},
    {"MN", 1e6, kForce},      {"J", 1, kEnergy},          {"kJ", 1e3, kEnergy},
    {"MJ", 1e6, kEnergy},     {"W", 1, kPower},           {"kW", 1e3, kPower},
    {"MW", 1e6, kPower},      {"K", 1, kKelvin},          {"deg", quantity::kDegree, kAngle},
    {"rad", 1, kAngle},       {"degC", 1, kKelvin},       {"\u00b0C", 1, kKelvin},
};

// The units of a `celsius` kind, and where their zero lies on it (degC).
struct ScaleDef {
  std::string_view name;
  double zero;
};
constexpr ScaleDef kCelsiusScales[] = {{"degC", 0}, {"\u00b0C", 0}, {"K", kAbsoluteZeroCelsius}};

// Kinds used to name a dimension in messages.
constexpr const QuantityKind* kNamedKinds[] = {
    &quantity::dimensionless,
    &quantity::length,
    &quantity::mass,
    &quantity::time,
    &quantity::angle,
    &quantity::velocity,
    &quantity::angular_velocity,
    &quantity::acceleration,
    &quantity::force,
    &quantity::stress,
    &quantity::density,
    &quantity::stiffness,
    &quantity::energy,
    &quantity::power,
};

std::string_view trim(std::string_view s) {
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front()))) s.remove_prefix(1);
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.remove_suffix(1);
  return s;
}

std::string article(std::string_view noun) {
  const bool vowel =
      !noun.empty() && std::string_view("aeiou").find(noun.front()) != std::string_view::npos;
  return vowel ? "an" : "a";
}

bool is_name_char(char c) {
  return std::isalpha(static_cast<unsigned char>(c)) || static_cast<unsigned char>(c) >= 0x80;
}

/// Recursive-descent parser for: term (('*' | '/') term)*, term = NAME ['^' INT] | '1'.
/// Returns the unit, or sets `error` to what was found.
class UnitParser {
 public:
  explicit UnitParser(std::string_view text) : text_(text) {}

  std::optional<Unit> parse(std::string& error) {
    Unit unit;
    int sign = 1;
    for (;;) {
      skip_spaces();
      std::optional<Unit> term = parse_term(error);
      if (!term) return std::nullopt;
      unit.factor *= sign > 0 ? term->factor : 1 / term->factor;
      unit.dimension = unit.dimension * raise(term->dimension, sign);
      skip_spaces();
      if (pos_ == text_.size()) return unit;
      const char op = text_[pos_];
      if (op != '*' && op != '/') {
        error = fmt::format("unexpected '{}' in unit '{}' (join units with '*' or '/')", op, text_);
        return std::nullopt;
      }
      sign = op == '*' ? 1 : -1;
      ++pos_;
    }
  }

 private:
  void skip_spaces() {
    while (pos_ < text_.size() && text_[pos_] == ' ') ++pos_;
  }

  std::optional<Unit> parse_term(std::string& error) {
    if (pos_ < text_.size() && text_[pos_] == '1') {  // as in "1/s"
      ++pos_;
      return Unit{};
    }
    const size_t start = pos_;
    while (pos_ < text_.size() && is_name_char(text_[pos_])) ++pos_;
    const std::string_view name = text_.substr(start, pos_ - start);
    if (name.empty()) {
      error = pos_ < text_.size()
                  ? fmt::format("unexpected '{}' in unit '{}'", text_[pos_], text_)
                  : fmt::format("malformed unit '{}' (a unit is missing at the end)", text_);
      return std::nullopt;
    }
    std::optional<Unit> unit = lookup(name, error);
    if (!unit) return std::nullopt;
    skip_spaces();
    if (pos_ < text_.size() && text_[pos_] == '^') {
      ++pos_;
      skip_spaces();
      int exponent = 0;
      const char* first = text_.data() + pos_;
      const char* last = text_.data() + text_.size();
      if (first != last && *first == '+') ++first;
      const auto [ptr, ec] = std::from_chars(first, last, exponent);
      if (ec != std::errc() || exponent == 0 || std::abs(exponent) > 12) {
        error = fmt::format("malformed power in unit '{}' (expected '^' and an integer)", text_);
        return std::nullopt;
      }
      pos_ = static_cast<size_t>(ptr - text_.data());
      unit->factor = std::pow(unit->factor, exponent);
      unit->dimension = raise(unit->dimension, exponent);
    }
    return unit;
  }

  static std::optional<Unit> lookup(std::string_view name, std::string& error) {
    std::vector<std::string_view> names;
    for (const UnitDef& u : kUnits) {
      if (u.name == name) return Unit{u.factor, u.dimension};
      names.push_back(u.name);
    }
    error = fmt::format("unknown unit '{}'", name);
    // Units are short: suggest only a slip of case or of one letter.
    const std::optional<std::string> m = closest_match(name, names);
    if (m && edit_distance(name, *m) <= (name.size() > 1 ? 1 : 0))
      error += fmt::format(" (did you mean '{}'?)", *m);
    return std::nullopt;
  }

  std::string_view text_;
  size_t pos_ = 0;
};

bool is_non_finite_word(std::string_view s) {
  if (!s.empty() && (s.front() == '+' || s.front() == '-')) s.remove_prefix(1);
  if (!s.empty() && s.front() == '.') s.remove_prefix(1);
  std::string lower;
  for (char c : s) lower += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return lower == "nan" || lower == "inf" || lower == "infinity";
}

std::string base_units(const Dimension& d) {
  const std::array<std::pair<const char*, int>, 5> parts = {
      {{"kg", d.mass}, {"m", d.length}, {"s", d.time}, {"K", d.kelvin}, {"rad", d.angle}}};
  std::string num, den;
  for (const auto& [symbol, e] : parts) {
    if (e == 0) continue;
    std::string& side = e > 0 ? num : den;
    const int n = std::abs(e);
    side += fmt::format("{}{}{}", side.empty() ? "" : "*", symbol,
                        n == 1 ? std::string() : fmt::format("^{}", n));
  }
  if (den.empty()) return num;
  return fmt::format("{}/{}", num.empty() ? std::string_view("1") : std::string_view(num), den);
}

/// A value in `unit` (of the dimension of a `celsius` kind) on the Celsius
/// scale: only a scale's own unit says where its zero is ("K^1" or "K*m/m"
/// do not); `fail` throws.
template <class Fail>
double on_celsius_scale(double value, std::string_view unit, const Fail& fail) {
  for (const ScaleDef& s : kCelsiusScales) {
    if (unit != s.name) continue;
    const double celsius = value + s.zero;
    if (celsius < kAbsoluteZeroCelsius) fail(", below absolute zero (-273.15 degC, 0 K)");
    return celsius;
  }
  fail(fmt::format(", whose unit '{}' is not degC or K alone", unit));
  return 0;  // not reached: fail throws
}

}  // namespace

Unit parse_unit(std::string_view expression) {
  std::string error;
  UnitParser parser(trim(expression));
  if (std::optional<Unit> unit = parser.parse(error)) return *unit;
  throw UnitError(
      fmt::format("{}; expected a product or quotient of known units, such as 'kg/m^3'", error));
}

std::string describe(const QuantityKind& kind) {
  if (kind.examples.empty()) return fmt::format("{} {}", article(kind.name), kind.name);
  return fmt::format("{} {} ({})", article(kind.name), kind.name, kind.examples);
}

std::string describe(const Dimension& dimension) {
  for (const QuantityKind* kind : kNamedKinds)
    if (kind->dimension == dimension) return fmt::format("{} {}", article(kind->name), kind->name);
  return fmt::format("a quantity in {}", base_units(dimension));
}

namespace {

/// The number at the start of a value and the text after it (its unit).
struct SplitValue {
  double value = 0;
  std::errc error{};  ///< std::errc() when the number parsed
  std::string_view unit;
};

SplitValue split_value(std::string_view t) {
  // The number: the longest prefix that parses (std::from_chars has no '+').
  const char* first = t.data();
  const char* last = t.data() + t.size();
  double sign = 1;
  if (first != last && (*first == '+' || *first == '-')) {
    sign = *first == '-' ? -1 : 1;
    ++first;
  }
  SplitValue s;
  const auto [ptr, ec] = std::from_chars(first, last, s.value);
  s.error = ec;
  if (ec == std::errc() && first != last && (*first == '+' || *first == '-'))
    s.error = std::errc::invalid_argument;
  s.value *= sign;
  s.unit = trim(std::string_view(ptr, static_cast<size_t>(last - ptr)));
  return s;
}

}  // namespace

double to_si(std::string_view text, const QuantityKind& kind) {
  const std::string_view t = trim(text);
  // Every problem reads "found 'TEXT'<detail>; expected <kind>".
  const auto fail = [&](std::string_view detail) {
    throw UnitError(fmt::format("found '{}'{}; expected {}", shorten(t), detail, describe(kind)));
  };
  if (t.empty()) throw UnitError(fmt::format("found an empty string; expected {}", describe(kind)));
  if (is_non_finite_word(t)) fail(", which is not a finite number");

  const SplitValue split = split_value(t);
  if (split.error == std::errc::result_out_of_range) fail(", which is out of the range of numbers");
  if (split.error != std::errc())
    fail(", which is not a number (a value is a number or a string 'NUMBER UNIT')");
  const double value = split.value;
  if (!std::isfinite(value)) fail(", which is not a finite number");

  const std::string_view unit_text = split.unit;
  if (unit_text.empty()) {
    if (kind.celsius && value < kAbsoluteZeroCelsius)
      fail(", below absolute zero (-273.15 degC, 0 K)");
    return value * kind.plain_scale;
  }

  std::string error;
  UnitParser parser(unit_text);
  const std::optional<Unit> unit = parser.parse(error);
  if (!unit) fail(fmt::format(" with {}", error));
  if (!(unit->dimension == kind.dimension)) fail(fmt::format(", {}", describe(unit->dimension)));
  if (kind.celsius) return on_celsius_scale(value, unit_text, fail);
  const double si = value * unit->factor;
  if (!std::isfinite(si)) fail(", which overflows in SI units");
  return si;
}

TimeUnit time_unit_of(std::string_view text, double seconds) {
  const std::string_view unit = split_value(trim(text)).unit;
  if (!unit.empty()) {
    try {
      const Unit u = parse_unit(unit);
      if (u.dimension == quantity::time.dimension && u.factor > 0)
        return {std::string(unit), u.factor};
    } catch (const UnitError&) {
      // Not a time (the scene's reader reports it): chosen by the duration.
    }
  }
  // A plain number (seconds): the largest unit the duration holds twice.
  for (const TimeUnit& u :
       {TimeUnit{"yr", kYear}, TimeUnit{"d", 86400}, TimeUnit{"h", 3600}, TimeUnit{"min", 60}})
    if (seconds >= 2 * u.seconds) return u;
  return {};
}

}  // namespace fissure
