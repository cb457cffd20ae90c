#include <cmath>
#include <cstdint>
#include <limits>

#include "io/json/value_quote.hpp"
#include "io/sections/section_reader.hpp"
#include "solver/materials/material.hpp"

namespace saasgaps::io {

namespace {

// k and c are optional in every row: section_thermal.cpp judges whether a thermal run has them.
constexpr std::array<Field<PropertyRow>, 6> isotropic_fields{{
    {"T", &PropertyRow::T, &any_number},
    {"E", &PropertyRow::E1, &modulus},
    {"nu", &PropertyRow::nu12, &poisson_ratio},
    {"alpha", &PropertyRow::alpha1, &any_number},
    {"k", &PropertyRow::k1, &positive, true},
    {"c", &PropertyRow::c, &positive, true},
}};

constexpr std::array<Field<PropertyRow>, 15> orthotropic_fields{{
    {"T", &PropertyRow::T, &any_number},
    {"E1", &PropertyRow::E1, &modulus},
    {"E2", &PropertyRow::E2, &modulus},
    {"E3", &PropertyRow::E3, &modulus},
    {"nu12", &PropertyRow::nu12, &any_number},
    {"nu13", &PropertyRow::nu13, &any_number},
    {"nu23", &PropertyRow::nu23, &any_number},
    {"G12", &PropertyRow::G12, &modulus},
    {"alpha1", &PropertyRow::alpha1, &any_number},
    {"alpha2", &PropertyRow::alpha2, &any_number},
    {"alpha3", &PropertyRow::alpha3, &any_number},
    {"k1", &PropertyRow::k1, &positive, true},
    {"k2", &PropertyRow::k2, &positive, true},
    {"k3", &PropertyRow::k3, &positive, true},
    {"c", &PropertyRow::c, &positive, true},
}};

/// The object form of plasticity: one curve for every temperature (T stays 0).
constexpr std::array<Field<PlasticityRow>, 2> plasticity_curve_fields{{
    {"yield_stress", &PlasticityRow::yield_stress, &positive},
    {"hardening_ratio", &PlasticityRow::hardening_ratio, &hardening},
}};

constexpr std::array<Field<PlasticityRow>, 3> plasticity_row_fields{{
    {"T", &PlasticityRow::T, &any_number},
    {"yield_stress", &PlasticityRow::yield_stress, &positive},
    {"hardening_ratio", &PlasticityRow::hardening_ratio, &hardening},
}};

ElasticConstants constants_of(const PropertyRow& row) {
  return {row.E1, row.E2, row.E3, row.nu12, row.nu13, row.nu23, row.G12, row.alpha1, row.alpha2, row.alpha3};
}

}  // namespace

// ---- generic checks

bool SectionReader::check_object(const json& value, const std::string& pointer, std::span<const std::string_view> required,
                          std::span<const std::string_view> optional) {
  return io::check_object(value, pointer, required, optional, reporter());
}

const json* SectionReader::array(const json& value, const std::string& pointer, std::string_view name,
                          std::size_t min_items) {
  return check_array(value, pointer, name, min_items, reporter());
}

std::optional<double> SectionReader::number(const json& value, const Where& pointer, std::string_view name,
                                     const Range& range) {
  return check_number(value, pointer, name, range, reporter());
}

std::optional<int> SectionReader::integer(const json& value, const Where& pointer, std::string_view name,
                                   int minimum, int maximum) {
  if (!value.is_number_integer()) {
    std::string detail = std::string(name) + " must be an integer, got " + describe(value);
    // JSON Schema calls 1.0 an integer; this reader does not, so say what to write instead.
    if (value.is_number_float() && std::isfinite(value.get<double>()) &&
        value.get<double>() == std::floor(value.get<double>()) && std::fabs(value.get<double>()) < 1e15) {
      detail += " (write " + std::to_string(static_cast<long long>(value.get<double>())) + " without a fraction)";
    }
    report(pointer, std::move(detail));
    return std::nullopt;
  }
  // Unsigned values above INT64_MAX would wrap in get<int64_t>(); compare in the value's own type.
  const bool in_range = value.is_number_unsigned()
                            ? value.get<std::uint64_t>() <= static_cast<std::uint64_t>(maximum) &&
                                  (minimum <= 0 || value.get<std::uint64_t>() >= static_cast<std::uint64_t>(minimum))
                            : value.get<std::int64_t>() >= minimum && value.get<std::int64_t>() <= maximum;
  if (!in_range) {
    report(pointer, std::string(name) + " = " + quote(value) + " is out of range: need " + std::to_string(minimum) +
                        " <= " + std::string(name) + " <= " + std::to_string(maximum));
    return std::nullopt;
  }
  return static_cast<int>(value.get<std::int64_t>());
}

std::optional<double> SectionReader::number_field(const Obj& o, std::string_view key, const Range& range) {
  const json* v = o.find(key);
  if (v == nullptr) return std::nullopt;
  return number(*v, Where(o.pointer, key), key, range);
}

std::optional<int> SectionReader::integer_field(const Obj& o, std::string_view key, int minimum, int maximum) {
  const json* v = o.find(key);
  if (v == nullptr) return std::nullopt;
  return integer(*v, Where(o.pointer, key), key, minimum, maximum);
}

std::optional<std::string> SectionReader::string_field(const Obj& o, std::string_view key) {
  const json* v = o.find(key);
  if (v == nullptr) return std::nullopt;
  return check_string(*v, Where(o.pointer, key), key, reporter());
}

std::optional<std::size_t> SectionReader::choice_index(const Obj& o, std::string_view key,
                                                std::span<const std::string_view> choices) {
  const json* v = o.find(key);
  if (v == nullptr) return std::nullopt;
  if (v->is_string()) {
    const auto it = std::ranges::find(choices, v->get_ref<const std::string&>());
    if (it != choices.end()) return static_cast<std::size_t>(it - choices.begin());
  }
  report(o.at(key), std::string(key) + " must be one of " + join(choices) + ", got " + describe(*v));
  return std::nullopt;
}

const json* SectionReader::array_field(const Obj& o, std::string_view key, std::size_t min_items) {
  const json* v = o.find(key);
  if (v == nullptr) return nullptr;
  return array(*v, o.at(key), key, min_items);
}

// ---- tables

template <class Row>
std::optional<Row> SectionReader::read_row(const json& value, const std::string& pointer,
                                    std::span<const Field<Row>> fields) {
  std::vector<std::string_view> keys;
  std::vector<std::string_view> optional_keys;
  for (const Field<Row>& f : fields) (f.optional ? optional_keys : keys).push_back(f.key);
  if (!check_object(value, pointer, keys, optional_keys)) return std::nullopt;
  const Obj o{&value, pointer};
  Row row{};
  bool complete = true;
  for (const Field<Row>& f : fields) {
    if (f.optional && o.find(f.key) == nullptr) continue;
    const auto v = number_field(o, f.key, *f.range);
    if (v) {
      row.*f.member = *v;
    } else {
      complete = false;
    }
  }
  if (!complete) return std::nullopt;
  return row;
}

/// Rows must be in strictly increasing T: interpolation needs a function of T. The order is judged
/// on every row whose T is a valid number, even when another value of the row is bad. `finish`
/// completes and checks a valid row at its pointer.
template <class Row, class Finish>
std::vector<Row> SectionReader::read_table(const json& rows, const std::string& pointer,
                                    std::span<const Field<Row>> fields, Finish finish) {
  std::vector<Row> table;
  const json* previous_T = nullptr;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const std::string row_pointer = pointer_append(pointer, i);
    auto row = read_row(rows[i], row_pointer, fields);
    // read_row has reported a missing or bad T; here only the order matters.
    const auto found = rows[i].is_object() ? rows[i].find("T") : rows[i].end();
    const json* T = found != rows[i].end() ? &*found : nullptr;
    if (T != nullptr && T->is_number() && std::isfinite(T->get<double>())) {
      if (previous_T != nullptr && !(T->get<double>() > previous_T->get<double>())) {
        report(pointer_append(row_pointer, "T"), "T = " + quote(*T) + " does not follow T = " + quote(*previous_T) +
                                                     " of an earlier row; rows must be in strictly increasing T");
      }
      previous_T = T;
    }
    if (!row) continue;
    finish(*row, row_pointer);
    table.push_back(*row);
  }
  return table;
}

std::vector<PropertyRow> SectionReader::read_property_table(const Obj& o, std::string_view key, bool isotropic,
                                                     std::size_t min_rows) {
  const json* rows = array_field(o, key, min_rows);
  if (rows == nullptr) return {};
  const auto finish = [&](PropertyRow& row, const std::string& row_pointer) {
    if (isotropic) {
      row.k2 = row.k3 = row.k1;
      row.E2 = row.E3 = row.E1;
      row.nu13 = row.nu23 = row.nu12;
      row.alpha2 = row.alpha3 = row.alpha1;
      row.G12 = row.E1 / (2.0 * (1.0 + row.nu12));
      return;  // -1 < nu < 0.5 and E > 0 already make it positive definite
    }
    if (!positive_definite(constants_of(row))) {
      report(row_pointer,
             "these orthotropic constants are not admissible: their compliance matrix is not positive definite "
             "(E1 = " + format_number(row.E1) + ", E2 = " + format_number(row.E2) + ", E3 = " +
                 format_number(row.E3) + ", nu12 = " + format_number(row.nu12) + ", nu13 = " +
                 format_number(row.nu13) + ", nu23 = " + format_number(row.nu23) + ", G12 = " +
                 format_number(row.G12) + "); the Poisson ratios are too large for the moduli (each nu_ij^2 must be "
                 "below E_i/E_j, and the compliance determinant must be positive)");
    }
  };
  if (isotropic) return read_table<PropertyRow>(*rows, o.at(key), isotropic_fields, finish);
  return read_table<PropertyRow>(*rows, o.at(key), orthotropic_fields, finish);
}

std::vector<PlasticityRow> SectionReader::read_plasticity(const Obj& o) {
  const json* v = o.find("plasticity");
  if (v == nullptr) return {};
  const std::string pointer = o.at("plasticity");
  if (v->is_object()) {
    const auto curve = read_row<PlasticityRow>(*v, pointer, plasticity_curve_fields);
    if (!curve) return {};
    return {*curve};
  }
  if (!v->is_array()) {
    report(pointer, "plasticity must be an object {yield_stress, hardening_ratio} or an array of rows {T, "
                    "yield_stress, hardening_ratio}, got " + describe(*v));
    return {};
  }
  if (array(*v, pointer, "plasticity", 1) == nullptr) return {};
  return read_table<PlasticityRow>(*v, pointer, plasticity_row_fields, [](PlasticityRow&, const std::string&) {});
}

}  // namespace saasgaps::io
