#pragma once
/// `saasgaps solve MODEL.json [-o RESULT.json]`: runs the solver in-process, one progress line per
/// iteration on stderr, the result document to a file or stdout, written as a stream (never held as
/// a tree), compact unless --pretty.

#include <optional>
#include <string>
#include <vector>

namespace saasgaps::cli {

struct SolveOptions {
  std::string model_path;
  std::string result_path;  ///< empty: stdout
  std::string state_out;    ///< write the restart state after every iteration
  std::string resume_from;  ///< continue from this restart state
  std::optional<int> max_iterations;
  std::optional<std::vector<double>> tensile_schedule;
  std::optional<double> extrapolation_factor;
  std::optional<int> stop_after;  ///< stop at the boundary after this iteration
  bool quiet = false;
  bool pretty = false;   ///< indent the result document (two spaces); compact by default
  std::string vtu_path;  ///< also write the result as a VTU file (io/vtu_writer.hpp)
  std::string cache_dir;  ///< keep fill-reducing orderings here between runs (empty: none)
};

/// Exit code: 0 converged, 3 not converged (or stopped). Throws for bad input and failures; main()
/// maps those to exit codes.
int run_solve(const SolveOptions& options);

}  // namespace saasgaps::cli
