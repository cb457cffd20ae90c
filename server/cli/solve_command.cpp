#include "cli/solve_command.hpp"

#include <iostream>

#include "analysis.hpp"
#include "errors.hpp"
#include "cli/file_io.hpp"
#include "io/model_reader.hpp"
#include "cli/progress_table.hpp"
#include "io/result_writer.hpp"
#include "io/state_codec.hpp"
#include "io/vtu_writer.hpp"

namespace saasgaps::cli {

namespace {

/// Prints each iteration, saves its restart state, and stops after --stop-after iterations.
class CommandLineObserver final : public IterationObserver {
 public:
  CommandLineObserver(const SolveOptions& options, std::string digest)
      : options_(options), digest_(std::move(digest)), table_(std::cerr) {}

  void on_iteration(const IterationRecord& row, const RestartState& state) override {
    if (!options_.quiet) table_.print(row);
    if (!options_.state_out.empty()) {
      write_file_atomically(options_.state_out, io::state_to_json(state, digest_).dump() + "\n");
    }
    last_iteration_ = state.iteration;
  }

  bool stop_requested() override { return options_.stop_after && last_iteration_ >= *options_.stop_after; }

 private:
  const SolveOptions& options_;
  std::string digest_;
  ProgressTable table_;
  int last_iteration_ = 0;
};

void write_result(const SolveOptions& options, const nlohmann::json& document) {
  const std::string text = document.dump(2) + "\n";
  if (options.result_path.empty()) {
    std::cout << text;
  } else {
    write_file_atomically(options.result_path, text);
  }
}

}  // namespace

int run_solve(const SolveOptions& options) {
  const nlohmann::json document = io::parse_document(read_file(options.model_path));
  const Model model = io::read_model(document);
  const std::string digest = io::model_digest(document);

  std::optional<RestartState> resume;
  if (!options.resume_from.empty()) {
    nlohmann::json saved;
    try {
      saved = nlohmann::json::parse(read_file(options.resume_from));
    } catch (const nlohmann::json::parse_error& e) {
      throw SolverError("cannot read the restart state " + options.resume_from + ": " + e.what());
    }
    resume = io::state_from_json(saved, digest);
  }
  ResumeOptions changes;
  changes.max_iterations = options.max_iterations;
  changes.tensile_schedule = options.tensile_schedule;
  changes.extrapolation_factor = options.extrapolation_factor;

  CommandLineObserver observer(options, digest);
  nlohmann::json result;
  int exit_code = 0;
  try {
    const Solution solution = solve(model, &observer, resume ? &*resume : nullptr, changes);
    std::cerr << solution.message << '\n';
    result = io::result_document(model, solution);
    write_result(options, result);
    exit_code = solution.status == RunStatus::converged ? 0 : 3;
  } catch (const std::exception& e) {
    // The failure is reported by main(); the result document records it too.
    if (!options.result_path.empty()) write_result(options, io::failed_result_document(e.what()));
    throw;
  }
  // Outside the try: a VTU that cannot be written must not turn a good result into a failed one.
  if (!options.vtu_path.empty()) write_file_atomically(options.vtu_path, io::result_to_vtu(result));
  return exit_code;
}

}  // namespace saasgaps::cli
