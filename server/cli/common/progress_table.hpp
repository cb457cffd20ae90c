#pragma once
/// The iteration table on stderr, with the columns of the report's Tables I-V. Compact by default,
/// at most 120 characters wide whatever the model: iteration, step/increment (stepped models only),
/// tensile modulus, closed gaps,
/// non-converged gaps, average and maximum closure, yielded and non-converged plastic elements,
/// wall time; in exact contact mode the tensile modulus and non-converged gaps (classic-mode
/// notions) give way to the pairs in contact, the complementarity residual and the active sets
/// tried. A run with friction (contact pairs with friction > 0) adds the points that stick and that
/// slip and the residual of Coulomb's law; a frictionless run's table is unchanged. Wide adds the
/// watched elements and gaps of the model's `output` (three columns each), and keeps the classic
/// columns in exact mode.

#include <optional>
#include <ostream>
#include <string>

#include "solver/state/iteration_record.hpp"

namespace saasgaps::cli {

/// The widest line of the compact table (docs/cli.md; a test holds every compact line to it).
inline constexpr int compact_table_width = 120;

class ProgressTable {
 public:
  /// friction: the model has friction, so the friction columns show from the first row on (its
  /// points may all be open). Without it they appear with the first row that carries them
  /// (io::has_friction_columns), under a header printed again.
  explicit ProgressTable(std::ostream& out, bool wide = false, bool friction = false)
      : out_(out), wide_(wide), friction_(friction) {}
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
  [[nodiscard]] bool friction_row(const IterationRecord& row) const;
  /// The gap columns (closed, average and maximum closure; classic: E tension, non-conv): models
  /// with gap elements or contact only (has_gap_values), fixed with the header.
  [[nodiscard]] bool gap_columns(const IterationRecord& row) const;
  std::ostream& out_;
  bool wide_;
  bool friction_;  // friction columns: set by the model, or by the first row that has them
  std::optional<bool> exact_;  // set when the header is printed: exact-contact columns or not
  std::optional<bool> gaps_;   // set when the header is printed: gap columns or not
};

/// The key columns of a row on one line, for the live display of `saasgaps watch` (after "job 3
/// running  iteration 7"): "  E tension 20  closed 92  non-conv 3  max clos 486.5 %  0.12 s"; exact
/// rows "  closed 4  pairs 17  complement. 2.5e-15  max clos 100.0 %  0.12 s"; stepped rows begin
/// with "  step 2 increment 3"; rows with friction end with "  stick 11  slip 6  friction 3.0e-13".
std::string live_summary(const IterationRecord& row);

/// Whether a row has gap values to show: gap closures, a tensile modulus, closed gaps or exact
/// contact. A model without gap elements or contact has none, and its table no gap columns.
bool has_gap_values(const IterationRecord& row);

}  // namespace saasgaps::cli
