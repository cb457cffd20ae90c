#pragma once
/// The report's READ card: what a restart may change. Its own header, free of the numerics, so that
/// the service's store can hold it without the solver's headers.

#include <optional>
#include <vector>

namespace saasgaps {

/// What a restart may change (the report's READ card): a new tensile schedule (absolute moduli,
/// started afresh from its first value), a new iteration limit, a new extrapolation factor. The one
/// type for these settings: the command line, the HTTP API, the service's store and the run all hold
/// it. Its rules (ranges) and its JSON form are io/read_card.hpp's.
struct ResumeOptions {
  std::optional<std::vector<double>> tensile_schedule;
  std::optional<int> max_iterations;
  std::optional<double> extrapolation_factor;
  /// Start a new tensile_schedule from its first value at the next iteration (the READ card). A
  /// caller that re-applies a schedule an earlier resume already began (after a crash) sets false.
  bool restart_schedule = true;

  /// A later READ card on top of these settings: each change it makes replaces the one in force,
  /// and a new schedule starts afresh.
  void apply(const ResumeOptions& later) {
    if (later.tensile_schedule) {
      tensile_schedule = later.tensile_schedule;
      restart_schedule = true;
    }
    if (later.max_iterations) max_iterations = later.max_iterations;
    if (later.extrapolation_factor) extrapolation_factor = later.extrapolation_factor;
  }
};

}  // namespace saasgaps
