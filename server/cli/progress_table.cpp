#include "cli/progress_table.hpp"

#include <cstdio>
#include <string>

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

constexpr int narrow = 9;
constexpr int wide = 14;

}  // namespace

void ProgressTable::print_header(const IterationRecord& row) {
  out_ << column("iter", 5) << column("E tension", 12) << column("closed", narrow) << column("non-conv", narrow)
       << column("avg clos %", wide) << column("max clos %", wide) << column("yielded", narrow)
       << column("N-L non-conv", wide);
  for (const WatchedElement& e : row.watch_elements) {
    const std::string id = "el " + std::to_string(e.id);
    out_ << column(id + " s_r", wide) << column(id + " s_th", wide) << column(id + " eff", wide);
  }
  for (const WatchedGap& g : row.watch_gaps) {
    const std::string id = "gap " + std::to_string(g.id);
    out_ << column(id + " E_M", wide) << column(id + " clos %", wide) << column(id + " s_M", wide);
  }
  // Exact contact mode: pairs in contact, the complementarity residual and the active sets tried.
  exact_ = row.active_set_iterations > 0;
  if (exact_) out_ << column("pairs", narrow) << column("complement.", wide) << column("sets", 6);
  out_ << column("seconds", narrow) << '\n';
  header_done_ = true;
}

void ProgressTable::print(const IterationRecord& row) {
  if (!header_done_) print_header(row);
  // The report prints "-" for the non-converged count of iteration 1: there is nothing to compare with.
  const std::string nonconverged = row.iteration == 1 ? "-" : std::to_string(row.nonconverged_gaps);
  out_ << column(std::to_string(row.iteration) + (row.extrapolated ? "x" : ""), 5)
       << column(number("%.5g", row.tensile_modulus), 12) << column(std::to_string(row.closed_gaps), narrow)
       << column(nonconverged, narrow) << column(number("%.1f", row.average_closure), wide)
       << column(number("%.1f", row.max_closure), wide) << column(std::to_string(row.yielded_elements), narrow)
       << column(std::to_string(row.nonconverged_plastic), wide);
  for (const WatchedElement& e : row.watch_elements) {
    out_ << column(number("%.1f", e.sigma_r), wide) << column(number("%.1f", e.sigma_theta), wide)
         << column(number("%.1f", e.effective), wide);
  }
  for (const WatchedGap& g : row.watch_gaps) {
    out_ << column(number("%.5g", g.modulus), wide) << column(number("%.2f", g.closure), wide)
         << column(number("%.1f", g.sigma_m), wide);
  }
  if (exact_) {
    out_ << column(std::to_string(row.contact_pairs), narrow) << column(number("%.1e", row.complementarity), wide)
         << column(std::to_string(row.active_set_iterations), 6);
  }
  out_ << column(number("%.3f", row.seconds), narrow) << '\n';
  out_.flush();
}

}  // namespace saasgaps::cli
