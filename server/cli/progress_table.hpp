#pragma once
/// The iteration table on stderr, with the columns of the report's Tables I-V. Compact by default,
/// at most 120 characters wide whatever the model: iteration, step/increment (stepped models only),
/// tensile modulus, closed gaps,
/// non-converged gaps, average and maximum closure, yielded and non-converged plastic elements,
/// wall time; in exact contact mode the tensile modulus and non-converged gaps (classic-mode
/// notions) give way to the pairs in contact, the complementarity residual and the active sets
/// tried. Wide adds the watched elements and gaps of the model's `output` (three columns each), and
/// keeps the classic columns in exact mode.

#include <optional>
#include <ostream>
#include <string>

#include "iteration_record.hpp"

namespace saasgaps::cli {

/// The widest line of the compact table (docs/cli.md; a test holds every compact line to it).
inline constexpr int compact_table_width = 120;

class ProgressTable {
 public:
  explicit ProgressTable(std::ostream& out, bool wide = false) : out_(out), wide_(wide) {}
  void print(const IterationRecord& row);
  /// A thermal row on a line of its own, between the table's rows (thermal_text).
  void print(const ThermalRecord& row);

  /// "thermal pass 2: 3 solves, max |dT| 1.2e-03, pass |dT| 4.5, T 70 .. 500" (steady) or
  /// "thermal t = 0.5: 10 steps, max step |dT| 12.3, T 70 .. 500" (transient), numbers to 6
  /// significant digits.
  [[nodiscard]] static std::string thermal_text(const ThermalRecord& row);

  /// The header line and a row without a line end (the live one-line display of `saasgaps watch`).
  [[nodiscard]] std::string header_text(const IterationRecord& row) const;
  [[nodiscard]] std::string row_text(const IterationRecord& row) const;

 private:
  [[nodiscard]] bool exact_row(const IterationRecord& row) const;
  [[nodiscard]] bool classic_columns(const IterationRecord& row) const;
  std::ostream& out_;
  bool wide_;
  std::optional<bool> exact_;  // set when the header is printed: exact-contact columns or not
};

}  // namespace saasgaps::cli
