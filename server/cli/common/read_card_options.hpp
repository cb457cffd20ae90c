#pragma once
/// The report's READ card on the command line: the three changes a resumed run may make, as the same
/// options for `saasgaps solve --resume` and `saasgaps resume` (docs/restart.md), mapped onto the one
/// READ-card type (ResumeOptions) here and nowhere else.

#include <CLI/CLI.hpp>

#include <string>

#include "solver/state/resume_options.hpp"

namespace saasgaps::cli {

/// Adds --max-iterations, --schedule E1,E2,... and --extrapolation F to `command`, filling `changes`
/// and checked by the rules of io/restart/read_card.hpp. `schedule_note` ends the --schedule description.
void add_read_card_options(CLI::App& command, ResumeOptions& changes, const std::string& schedule_note);

}  // namespace saasgaps::cli
