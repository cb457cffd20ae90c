#pragma once
/// The names of an enumeration's values, as one table: each entry pairs a value with its name, so
/// a name never follows from its position in a list. A table is checked when it is built, at compile
/// time: every name and every value appears once, and the values are 0, 1, .., N-1 in some order
/// (no enumerator of a dense enum is left without a name).
///
///   inline constexpr NameTable<AnalysisType, 3> analysis_type_names{{{
///       {AnalysisType::plane_stress, "plane_stress"}, ...}}};
///   analysis_type_names.name(AnalysisType::axisymmetric)   // "axisymmetric"
///   analysis_type_names.value("plane_strain")              // AnalysisType::plane_strain

#include <array>
#include <cstddef>
#include <optional>
#include <string_view>

namespace saasgaps {

template <class E>
struct NamedValue {
  E value;
  std::string_view name;
};

template <class E, std::size_t N>
class NameTable {
 public:
  /// consteval: a table that breaks a rule does not compile.
  consteval explicit NameTable(std::array<NamedValue<E>, N> entries) : entries_(entries) {
    std::array<bool, N> seen{};
    for (std::size_t i = 0; i < N; ++i) {
      const auto v = static_cast<std::size_t>(entries_[i].value);
      if (v >= N || seen[v]) throw "NameTable: values must be 0..N-1, each once";
      seen[v] = true;
      if (entries_[i].name.empty()) throw "NameTable: empty name";
      for (std::size_t j = 0; j < i; ++j) {
        if (entries_[j].name == entries_[i].name) throw "NameTable: a name appears twice";
      }
    }
  }

  /// The name of `value` ("?" for a value outside the enumeration, which a cast can make).
  [[nodiscard]] constexpr std::string_view name(E value) const {
    for (const NamedValue<E>& e : entries_) {
      if (e.value == value) return e.name;
    }
    return "?";
  }

  /// The value named `name`, or nullopt.
  [[nodiscard]] constexpr std::optional<E> value(std::string_view name) const {
    for (const NamedValue<E>& e : entries_) {
      if (e.name == name) return e.value;
    }
    return std::nullopt;
  }

  /// Every name, in the table's order (for messages that list the choices).
  [[nodiscard]] constexpr std::array<std::string_view, N> names() const {
    std::array<std::string_view, N> out{};
    for (std::size_t i = 0; i < N; ++i) out[i] = entries_[i].name;
    return out;
  }

  [[nodiscard]] constexpr const std::array<NamedValue<E>, N>& entries() const { return entries_; }
  [[nodiscard]] static constexpr std::size_t size() { return N; }

 private:
  std::array<NamedValue<E>, N> entries_;
};

}  // namespace saasgaps
