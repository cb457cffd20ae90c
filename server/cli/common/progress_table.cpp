#include "cli/common/progress_table.hpp"

#include <cmath>
#include <cstdio>
#include <string>

#include "io/results/history_json.hpp"

namespace saasgaps::cli {

namespace {

/// Right-aligns text in a column of the given width (at least one space before it).
std::string column(const std::string& text, int width) {
  const int pad = width - static_cast<int>(text.size());
  return std::string(static_cast<std::size_t>(pad > 1 ? pad : 1), ' ') + text;
}

std::string number(const char* format, double value) {
  char text[64];
  std::snprintf(text, sizeof text, format, value);
  return text;
}

// Column widths. The compact line is at most 5+9+11+8+9+12+12+8+13+7+12+5+9 = 120 characters with
// every column a run can show (exact mode drops the tensile modulus and non-converged gaps; only
// stepped models show step/increment), which leaves room for numbers wider than their header. The
// friction columns (6+5+9) come only with exact rows (friction is solved by the contact surfaces'
// active sets), in the 11+9 the classic columns leave.
constexpr int iteration_width = 5;
constexpr int step_width = 9;
constexpr int modulus_width = 11;
constexpr int count_width = 8;
constexpr int nonconverged_width = 9;
constexpr int closure_width = 12;
constexpr int plastic_width = 13;
constexpr int pairs_width = 7;
constexpr int residual_width = 12;
constexpr int sets_width = 5;
constexpr int seconds_width = 9;
constexpr int watched_width = 14;
constexpr int stick_width = 6;
constexpr int slip_width = 5;
constexpr int friction_width = 9;

/// A closure in percent: one decimal, fewer digits when huge (a body that flew off) so the column holds.
std::string closure(double percent) { return number(std::fabs(percent) < 1e7 ? "%.1f" : "%.3g", percent); }

/// The words of the gap counts (docs/results.md, "Gap words"): "closed" is a gap state, the faces
/// touching (closure within the tolerance of 100 %), and the exact mode counts those; the classic
/// mode counts the report's gaps past 100 % (Table III's "closed gaps"), which are not the same set.
/// The average is over the gaps counted, "-" when none is (no mean of nothing).
const char* count_heading(bool exact) { return exact ? "closed" : "> 100 %"; }
const char* average_heading(bool exact) { return exact ? "avg clos %" : "avg > 100 %"; }
std::string average(const IterationRecord& row) { return row.closed_gaps > 0 ? closure(row.average_closure) : "-"; }

}  // namespace

bool ProgressTable::exact_row(const IterationRecord& row) const {
  return exact_.value_or(row.active_set_iterations > 0);
}

bool ProgressTable::classic_columns(const IterationRecord& row) const {
  return gap_columns(row) && (wide_ || !exact_row(row));
}

bool has_gap_values(const IterationRecord& row) {
  // A model without gap elements or contact pairs: no closures, no modulus, nothing closed (its 0s
  // would read as measurements).
  return row.active_set_iterations > 0 || !row.gap_closures.empty() || row.tensile_modulus != 0.0 ||
         row.closed_gaps != 0 || row.max_closure != 0.0;
}

bool ProgressTable::gap_columns(const IterationRecord& row) const { return gaps_.value_or(has_gap_values(row)); }

bool ProgressTable::friction_row(const IterationRecord& row) const { return friction_ || io::has_friction_columns(row); }

std::string ProgressTable::header_text(const IterationRecord& row) const {
  std::string line = column("iter", iteration_width);
  if (row.step > 0) line += column("step/inc", step_width);
  if (classic_columns(row)) line += column("E tension", modulus_width);
  if (gap_columns(row)) line += column(count_heading(exact_row(row)), count_width);
  if (classic_columns(row)) line += column("non-conv", nonconverged_width);
  if (gap_columns(row)) line += column(average_heading(exact_row(row)), closure_width) + column("max clos %", closure_width);
  line += column("yielded", count_width) + column("N-L non-conv", plastic_width);
  if (wide_) {
    for (const WatchedElement& e : row.watch_elements) {
      const std::string id = "el " + std::to_string(e.id);
      line += column(id + " s_r", watched_width) + column(id + " s_th", watched_width) + column(id + " eff", watched_width);
    }
    for (const WatchedGap& g : row.watch_gaps) {
      const std::string id = "gap " + std::to_string(g.id);
      line += column(id + " E_M", watched_width) + column(id + " clos %", watched_width) +
              column(id + " s_M", watched_width);
    }
  }
  if (exact_row(row)) line += column("pairs", pairs_width) + column("complement.", residual_width) + column("sets", sets_width);
  if (friction_row(row)) line += column("stick", stick_width) + column("slip", slip_width) + column("friction", friction_width);
  return line + column("seconds", seconds_width);
}

std::string ProgressTable::row_text(const IterationRecord& row) const {
  // The report prints "-" for the non-converged count of iteration 1: there is nothing to compare with.
  const std::string nonconverged = row.iteration == 1 ? "-" : std::to_string(row.nonconverged_gaps);
  std::string line = column(std::to_string(row.iteration) + (row.extrapolated ? "x" : ""), iteration_width);
  if (row.step > 0) line += column(std::to_string(row.step) + "/" + std::to_string(row.increment), step_width);
  if (classic_columns(row)) line += column(number("%.5g", row.tensile_modulus), modulus_width);
  if (gap_columns(row)) line += column(std::to_string(row.closed_gaps), count_width);
  if (classic_columns(row)) line += column(nonconverged, nonconverged_width);
  if (gap_columns(row)) line += column(average(row), closure_width) + column(closure(row.max_closure), closure_width);
  line += column(std::to_string(row.yielded_elements), count_width) +
          column(std::to_string(row.nonconverged_plastic), plastic_width);
  if (wide_) {
    for (const WatchedElement& e : row.watch_elements) {
      line += column(number("%.1f", e.sigma_r), watched_width) + column(number("%.1f", e.sigma_theta), watched_width) +
              column(number("%.1f", e.effective), watched_width);
    }
    for (const WatchedGap& g : row.watch_gaps) {
      line += column(number("%.5g", g.modulus), watched_width) + column(number("%.2f", g.closure), watched_width) +
              column(number("%.1f", g.sigma_m), watched_width);
    }
  }
  if (exact_row(row)) {
    line += column(std::to_string(row.contact_pairs), pairs_width) +
            column(number("%.1e", row.complementarity), residual_width) +
            column(std::to_string(row.active_set_iterations), sets_width);
  }
  if (friction_row(row)) {
    line += column(std::to_string(row.stick_points), stick_width) + column(std::to_string(row.slip_points), slip_width) +
            column(number("%.1e", row.friction_residual), friction_width);
  }
  return line + column(number("%.3f", row.seconds), seconds_width);
}

std::string live_summary(const IterationRecord& r) {
  std::string line;
  if (r.step > 0) line += "  step " + std::to_string(r.step) + " increment " + std::to_string(r.increment);
  char text[200];
  if (!has_gap_values(r)) {
    std::snprintf(text, sizeof text, "  yielded %d  %.2f s", r.yielded_elements, r.seconds);
  } else if (r.active_set_iterations > 0) {
    std::snprintf(text, sizeof text, "  closed %d  pairs %d  complement. %.1e  max clos %.1f %%  %.2f s", r.closed_gaps,
                  r.contact_pairs, r.complementarity, r.max_closure, r.seconds);
  } else {
    std::snprintf(text, sizeof text, "  E tension %.5g  closed %d  non-conv %s  max clos %.1f %%  %.2f s",
                  r.tensile_modulus, r.closed_gaps, r.iteration == 1 ? "-" : std::to_string(r.nonconverged_gaps).c_str(),
                  r.max_closure, r.seconds);
  }
  line += text;
  // Runs with friction only: the points that stick and slip, and the residual of Coulomb's law.
  if (io::has_friction_columns(r)) {
    std::snprintf(text, sizeof text, "  stick %d  slip %d  friction %.1e", r.stick_points, r.slip_points,
                  r.friction_residual);
    line += text;
  }
  return line;
}

std::string ProgressTable::thermal_text(const ThermalRecord& r) {
  char text[240];
  if (r.kind == ThermalRowKind::steady) {
    std::snprintf(text, sizeof text, "thermal pass %d: %d solve%s, max |dT| %.6g, pass |dT| %.6g, T %.6g .. %.6g", r.pass,
                  r.iterations, r.iterations == 1 ? "" : "s", r.max_change, r.pass_change, r.min_T, r.max_T);
  } else {
    std::snprintf(text, sizeof text, "thermal t = %.6g: %d step%s, max step |dT| %.6g, T %.6g .. %.6g", r.time,
                  r.time_steps, r.time_steps == 1 ? "" : "s", r.max_change, r.min_T, r.max_T);
  }
  return text;
}

void ProgressTable::print(const ThermalRecord& row) {
  out_ << thermal_text(row) << '\n';
  out_.flush();
}

void ProgressTable::print(const IterationRecord& row) {
  // A row that first shows friction (a watched job: the model is not known) brings the friction
  // columns, under a header of its own.
  const bool friction_appears = !friction_ && io::has_friction_columns(row);
  if (!exact_ || friction_appears) {
    if (friction_appears) friction_ = true;
    out_ << header_text(row) << '\n';
    // Exact-mode rows carry their active sets; the header fixes the columns for every later row.
    if (!exact_) exact_ = row.active_set_iterations > 0;
    if (!gaps_) gaps_ = has_gap_values(row);
  }
  out_ << row_text(row) << '\n';
  out_.flush();
}

}  // namespace saasgaps::cli
