#include "cli/commands/solve_command.hpp"

#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <iostream>

#include "cli/common/file_io.hpp"
#include "cli/common/progress_table.hpp"
#include "cli/common/usage.hpp"
#include "io/json/json_text.hpp"
#include "io/import/adapt_settings.hpp"
#include "io/import/adaptive_loop.hpp"
#include "io/import/assembly_reader.hpp"
#include "io/model/document_kind.hpp"
#include "io/model/model_reader.hpp"
#include "io/restart/read_card.hpp"
#include "io/restart/state_codec.hpp"
#include "io/results/result_writer.hpp"
#include "io/results/vtu_writer.hpp"
#include "solver/analysis/analysis.hpp"
#include "solver/base/errors.hpp"
#include "solver/thermal/thermal_analysis.hpp"

namespace saasgaps::cli {

namespace {

/// Prints each iteration, saves its restart state, and stops after --stop-after iterations.
class CommandLineObserver final : public IterationObserver {
 public:
  /// friction: the model has a contact pair with friction > 0 (the table's friction columns).
  CommandLineObserver(const SolveOptions& options, std::string digest, bool friction)
      : options_(options), digest_(std::move(digest)), table_(std::cerr, options.wide, friction) {}

  void on_iteration(const IterationRecord& row, const RestartState& state) override {
    if (!options_.quiet) table_.print(row);
    if (!options_.state_out.empty()) {
      write_file_atomically(options_.state_out, io::json_text(io::state_to_json(state, digest_)) + "\n");
    }
    last_iteration_ = state.iteration;
  }

  void on_thermal(const ThermalRecord& row) override {
    if (!options_.quiet) table_.print(row);
  }

  bool stop_requested() override { return options_.stop_after && last_iteration_ >= *options_.stop_after; }

 private:
  const SolveOptions& options_;
  std::string digest_;
  ProgressTable table_;
  int last_iteration_ = 0;
};

/// Where the result document goes: a file, or "-" for stdout (see the header).
std::string result_destination(const SolveOptions& options) {
  if (!options.result_path.empty()) return options.result_path;
  return ::isatty(STDOUT_FILENO) ? result_path_next_to(options.model_path) : "-";
}

/// Streams a result document (write_result or write_failed_result) to the file or stdout ("-").
template <class Write>
void write_result(const SolveOptions& options, const std::string& destination, const Write& write) {
  const auto to_stream = [&](std::ostream& out) {
    io::JsonWriter writer(io::stream_sink(out), options.pretty);
    write(writer);
    writer.flush();
    out << '\n';
  };
  if (destination == "-") {
    to_stream(std::cout);
    std::cout.flush();
  } else {
    write_file_atomically(destination, to_stream);
  }
}

int solve_model(const SolveOptions& options, const std::string& destination, const Model& model,
                const std::string& digest);
int run_assembly_solve(const SolveOptions& options, const std::string& destination, const std::string& text);

}  // namespace

std::string result_path_next_to(const std::string& model_path) {
  const std::string suffix = ".json";
  const bool json_name = model_path.size() > suffix.size() &&
                         model_path.compare(model_path.size() - suffix.size(), suffix.size(), suffix) == 0;
  return (json_name ? model_path.substr(0, model_path.size() - suffix.size()) : model_path) + ".result.json";
}

int run_solve(const SolveOptions& options) {
  const std::string destination = result_destination(options);
  // Every output is checked before the solve: a typo in a directory should not cost the run.
  if (destination != "-") require_writable(destination, options.result_path.empty() ? "the result" : "-o");
  require_writable(options.state_out, "--state-out");
  require_writable(options.vtu_path, "--vtu");
  // The model is read straight from the text (no tree of the document); the digest that restart
  // states carry is computed on the way, when there is a state to write or read.
  std::string digest;
  const bool restarts = !options.state_out.empty() || !options.resume_from.empty();
  const std::string text = read_file(options.model_path);
  Model model;
  try {
    model = io::parse_model(text, restarts ? &digest : nullptr);
  } catch (const ModelError& e) {
    if (!io::names_assembly(e)) throw;
    return run_assembly_solve(options, destination, text);
  }
  return solve_model(options, destination, model, digest);
}

namespace {

bool has_friction(const Model& model) {
  return model.contact && std::any_of(model.contact->pairs.begin(), model.contact->pairs.end(),
                                      [](const SurfacePair& pair) { return pair.friction > 0.0; });
}

/// One solve with the progress table (and restart states) of the command line.
Solution solve_one(const SolveOptions& options, const Model& model, const std::string& digest,
                   const RestartState* resume, const OrderingCache* cache) {
  CommandLineObserver observer(options, digest, has_friction(model));
  return solve_with_heat(model, &observer, resume, options.changes, cache);
}

/// Runs `solve`; when it throws, the result document records the failure too (main() reports it),
/// except for bad input, which writes no result (as a model that does not read).
template <class Solve>
auto recorded(const SolveOptions& options, const std::string& destination, const Solve& solve) {
  try {
    return solve();
  } catch (const ModelError&) {
    throw;
  } catch (const std::exception& e) {
    if (destination != "-") {
      write_result(options, destination, [&](io::JsonWriter& out) { io::write_failed_result(out, e.what()); });
    }
    throw;
  }
}

/// The result written (and the VTU when asked); the exit code.
int finish(const SolveOptions& options, const std::string& destination, const Model& model, const Solution& solution,
           const std::function<void(io::JsonWriter&)>& leading, bool reached = true) {
  std::cerr << solution.message << '\n';
  if (solution.error_estimate) {
    // The recovered stresses' verdict on the mesh (docs/recovery.md): error_estimate.relative.
    char line[160];
    std::snprintf(line, sizeof line, "estimated stress error %.2f %% in the energy norm (error_estimate.relative %.4g)\n",
                  100.0 * solution.error_estimate->relative, solution.error_estimate->relative);
    std::cerr << line;
  }
  write_result(options, destination, [&](io::JsonWriter& out) { io::write_result(out, model, solution, {}, leading); });
  // Said only when the user did not name the file: they should not have to guess where it went.
  if (options.result_path.empty() && destination != "-") {
    std::cerr << "result written to " << destination << " (-o FILE names another file, -o - is standard output)\n";
  }
  // A VTU that cannot be written must not turn a good result into a failed one. The VTU writer
  // works from a result tree: only this opt-in export builds one.
  if (!options.vtu_path.empty()) {
    // The result's text read as arrays, as `saasgaps export-vtu` reads the file: no tree of it.
    write_file_atomically(options.vtu_path, io::result_to_vtu(io::read_result_arrays(io::result_text(model, solution),
                                                                                     io::vtu_result_selection())));
  }
  return solution.status == RunStatus::converged && reached ? 0 : 3;
}

int solve_model(const SolveOptions& options, const std::string& destination, const Model& model,
                const std::string& digest) {
  // Said by the HTTP resume body too (io/read_card.hpp): ignoring them would run something else
  // than what was asked.
  if (!model.gaps && options.changes.tensile_schedule) throw UsageError(std::string("solve --schedule: ") + io::no_gaps_schedule);
  if (!model.gaps && options.changes.extrapolation_factor) {
    throw UsageError(std::string("solve --extrapolation: ") + io::no_gaps_extrapolation);
  }

  std::optional<RestartState> resume;
  if (!options.resume_from.empty()) {
    nlohmann::json saved;
    try {
      saved = io::parse_document(read_file(options.resume_from));
    } catch (const ModelError& e) {
      // Not JSON, or beyond a limit (io/json_limits.hpp): like any restart state that does not fit.
      const InputIssue& issue = e.issues().front();
      throw SolverError("cannot read the restart state " + options.resume_from + ": " +
                        (issue.pointer.empty() ? "" : issue.pointer + ": ") + issue.detail);
    }
    resume = io::state_from_json(saved, digest);
  }
  std::optional<OrderingCache> cache;
  if (!options.cache_dir.empty()) cache.emplace(options.cache_dir);
  const Solution solution = recorded(options, destination, [&] {
    return solve_one(options, model, digest, resume ? &*resume : nullptr, cache ? &*cache : nullptr);
  });
  return finish(options, destination, model, solution, {});
}

/// An assembly (docs/import.md) imported, then solved as its model is; with `adapt`, the adaptive
/// loop (io/import/adaptive_loop.hpp), a line per cycle on stderr and the cycles in the result's
/// `adaptation`. Restart states belong to a model's text, so they need the imported model
/// (saasgaps import first).
int run_assembly_solve(const SolveOptions& options, const std::string& destination, const std::string& text) {
  if (!options.state_out.empty() || !options.resume_from.empty()) {
    throw UsageError(std::string("solve ") + (options.state_out.empty() ? "--resume" : "--state-out") + ": " +
                     options.model_path + " is an assembly; restart states belong to a model: run saasgaps import "
                     "and solve the model it writes");
  }
  const nlohmann::json assembly = io::parse_document(text);
  const std::filesystem::path base = std::filesystem::absolute(options.model_path).parent_path();
  // A wrong `adapt` is reported by the import, with every other problem of the document.
  const auto settings = io::read_adapt_settings(assembly, [](const std::string&, const std::string&) {});
  if (!assembly.contains("adapt") || !settings) {
    const Model model = io::read_model(io::import_assembly(assembly, base));
    std::cerr << "imported " << options.model_path << ": " << model.nodes.size() << " nodes, " << model.elements.size()
              << " elements\n";
    return solve_model(options, destination, model, {});
  }
  std::optional<OrderingCache> cache;
  if (!options.cache_dir.empty()) cache.emplace(options.cache_dir);
  io::AdaptiveRun run = recorded(options, destination, [&] {
    return io::run_adaptive(
        assembly, base, io::FileAccess::anywhere, *settings,
        [&](const Model& model) { return solve_one(options, model, {}, nullptr, cache ? &*cache : nullptr); },
        [&](const io::AdaptCycle& c, const io::AdaptSizes*) {
          std::cerr << "adapt cycle " << c.cycle << ": " << c.nodes << " nodes, " << c.elements
                    << " elements, relative error " << c.relative_error << " (target " << settings->target_error
                    << "; mesh " << c.mesh_seconds << " s, import " << c.import_seconds << " s, solve "
                    << c.solve_seconds << " s, estimate " << c.estimate_seconds << " s, sizes " << c.sizes_seconds
                    << " s)\n";
        });
  });
  std::cerr << run.message << '\n';
  run.solution.message += "; " + run.message;
  return finish(options, destination, run.model, run.solution,
                [&](io::JsonWriter& out) { io::write_adaptation(out, run.cycles); }, run.reached);
}

}  // namespace

}  // namespace saasgaps::cli
