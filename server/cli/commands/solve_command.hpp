#pragma once
/// `saasgaps solve MODEL.json [-o RESULT.json]`: runs the solver in-process, one progress line per
/// iteration on stderr, the result document to a file or stdout, written as a stream (never held as
/// a tree), compact unless --pretty. Without -o the result goes to stdout when that is a pipe or a
/// file, and next to the model (MODEL.result.json) when it is a terminal: a result document is not
/// for reading on a screen. `-o -` is stdout whatever it is.

#include <optional>
#include <string>
#include <vector>

#include "cli/common/read_card_options.hpp"

namespace saasgaps::cli {

struct SolveOptions {
  std::string model_path;
  std::string result_path;  ///< "-": stdout; empty: stdout, or next to the model on a terminal
  std::string state_out;    ///< write the restart state after every iteration
  std::string resume_from;  ///< continue from this restart state
  ResumeOptions changes;  ///< --max-iterations, --schedule, --extrapolation (with --resume)
  std::optional<int> stop_after;  ///< stop at the boundary after this iteration
  bool quiet = false;
  bool wide = false;     ///< every column of the progress table (cli/common/progress_table.hpp)
  bool pretty = false;   ///< indent the result document (two spaces); compact by default
  std::string vtu_path;  ///< also write the result as a VTU file (io/vtu_writer.hpp)
  std::string cache_dir;  ///< keep fill-reducing orderings here between runs (empty: none)
};

/// Exit code: 0 converged, 3 not converged (or stopped). Throws for bad input and failures; main()
/// maps those to exit codes.
int run_solve(const SolveOptions& options);

/// Where a result goes when -o is not given and stdout is a terminal: "dir/name.json" ->
/// "dir/name.result.json" (any other name gets ".result.json" appended).
std::string result_path_next_to(const std::string& model_path);

}  // namespace saasgaps::cli
