#pragma once
/// The rules every value of a JSON document obeys, in one wording: the model reader
/// (SectionReader) and the assembly importer both check shapes and numbers through these, so a
/// wrong value reads the same whichever document held it ("E = -1 is out of range: need
/// 1e-30 <= E <= 1e30 (...)", "expected an object, got the string \"x\"").
///
/// Each check reports every rule it finds broken through `report(pointer, detail)` and returns what
/// it accepted. `pointer` is whatever the caller's report() takes: a spelled JSON Pointer, or the
/// reader's lazy Where, which builds no text for a valid value.

#include <cmath>
#include <cstddef>
#include <optional>
#include <algorithm>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "io/json/json_pointer.hpp"
#include "io/json/value_quote.hpp"

namespace saasgaps::io {

/// Ranges of numbers, with the wording of the rule they state.
struct Bound {
  double value = 0.0;
  bool inclusive = false;
};

struct Range {
  std::optional<Bound> lower;
  std::optional<Bound> upper;
  const char* reason = nullptr;  ///< why the range holds, when it is not obvious
};

constexpr Range any_number{};
constexpr Range positive{Bound{0.0, false}, std::nullopt};
constexpr Range non_negative{Bound{0.0, true}, std::nullopt};
/// Elastic moduli (E, E1..E3, G12). The material law inverts the 4x4 compliance, whose determinant
/// is of the order of 1 / E^4: it underflows to 0 beyond E ~ 1e77 and overflows below 1e-77, and the
/// element condensation squares the stiffness (overflow beyond ~1e150). Far inside both, 1e-30 ..
/// 1e30 holds every unit system (2e11 Pa, 3e7 psi, 200 GPa) and keeps products of moduli finite.
constexpr Range modulus{Bound{1e-30, true}, Bound{1e30, true},
                        "moduli beyond this range overflow or underflow the material law's arithmetic"};
constexpr Range poisson_ratio{Bound{-1.0, false}, Bound{0.5, false},
                              "an isotropic material is stable only for -1 < nu < 0.5"};
constexpr Range hardening{Bound{0.0, true}, Bound{1.0, false}, "the secondary slope is a fraction of E"};
constexpr Range extrapolation{Bound{0.0, true}, Bound{1.0, false}};
constexpr Range tolerance_fraction{Bound{0.0, false}, Bound{1.0, false}};
constexpr Range axisymmetric_radius{Bound{0.0, true}, std::nullopt,
                                    "an axisymmetric model lies in the half plane r >= 0"};

bool contains(const Range& range, double v);

/// "E > 0", "0 <= hardening_ratio < 1": the rule a value broke.
std::string requirement(const Range& range, std::string_view name);

/// An object whose keys are all in `required` or `optional`, with every required key present.
/// False (reported) when the value is not an object; an unknown or missing key is reported and the
/// object still returned as checked (true), so the rest of it is judged in the same pass.
template <class Report>
bool check_object(const nlohmann::json& value, const std::string& pointer, std::span<const std::string_view> required,
                  std::span<const std::string_view> optional, Report&& report) {
  if (!value.is_object()) {
    report(pointer, "expected an object, got " + describe(value));
    return false;
  }
  const auto allowed = [&](const std::string& key) {
    return std::ranges::find(required, key) != required.end() || std::ranges::find(optional, key) != optional.end();
  };
  for (auto it = value.begin(); it != value.end(); ++it) {
    if (allowed(it.key())) continue;
    std::vector<std::string_view> names(required.begin(), required.end());
    names.insert(names.end(), optional.begin(), optional.end());
    report(pointer_append(pointer, it.key()), "unknown key " + quote_string(it.key()) + " (allowed here: " +
                                                  (names.empty() ? std::string("none") : join(names)) + ")");
  }
  for (const std::string_view key : required) {
    if (!value.contains(key)) report(pointer, "missing required key " + quote_string(key));
  }
  return true;
}

/// An array of at least `min_items` items; nullptr (reported) otherwise.
template <class Pointer, class Report>
const nlohmann::json* check_array(const nlohmann::json& value, const Pointer& pointer, std::string_view name,
                                  std::size_t min_items, Report&& report) {
  if (!value.is_array()) {
    report(pointer, std::string(name) + " must be an array, got " + describe(value));
    return nullptr;
  }
  if (value.size() < min_items) {
    report(pointer, std::string(name) + " must not be empty");
    return nullptr;
  }
  return &value;
}

/// A finite number inside `range`.
template <class Pointer, class Report>
std::optional<double> check_number(const nlohmann::json& value, const Pointer& pointer, std::string_view name,
                                   const Range& range, Report&& report) {
  // is_number() is false for booleans, so true is not silently 1.
  if (!value.is_number()) {
    report(pointer, std::string(name) + " must be a number, got " + describe(value));
    return std::nullopt;
  }
  const double v = value.get<double>();
  if (!std::isfinite(v)) {
    report(pointer, std::string(name) + " = " + format_number(v) + " is not a finite number");
    return std::nullopt;
  }
  if (!contains(range, v)) {
    report(pointer, std::string(name) + " = " + quote(value) + " is out of range: need " + requirement(range, name));
    return std::nullopt;
  }
  return v;
}

/// A string.
template <class Pointer, class Report>
std::optional<std::string> check_string(const nlohmann::json& value, const Pointer& pointer, std::string_view name,
                                        Report&& report) {
  if (!value.is_string()) {
    report(pointer, std::string(name) + " must be a string, got " + describe(value));
    return std::nullopt;
  }
  return value.get<std::string>();
}

/// schema_version is the integer 1, in models and assemblies alike.
template <class Pointer, class Report>
void check_schema_version(const nlohmann::json& version, const Pointer& pointer, Report&& report) {
  if (!(version.is_number_integer() && version == 1)) {
    report(pointer, "schema_version must be the integer 1 (the only version this reader knows), got " + describe(version));
  }
}

}  // namespace saasgaps::io
