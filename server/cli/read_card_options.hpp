#pragma once
/// The report's READ card on the command line: the three changes a resumed run may make, as the same
/// options for `saasgaps solve --resume` and `saasgaps resume` (docs/restart.md).

#include <CLI/CLI.hpp>

#include <optional>
#include <vector>

namespace saasgaps::cli {

struct ReadCardChanges {
  std::optional<int> max_iterations;                      ///< --max-iterations N
  std::optional<std::vector<double>> tensile_schedule;    ///< --schedule E1,E2,...
  std::optional<double> extrapolation_factor;             ///< --extrapolation F
};

/// Adds --max-iterations (1 to io::max_iterations_limit), --schedule (moduli > 0) and
/// --extrapolation (0 <= F < 1) to `command`. `schedule_note` ends the --schedule description.
void add_read_card_options(CLI::App& command, ReadCardChanges& changes, const std::string& schedule_note);

}  // namespace saasgaps::cli
