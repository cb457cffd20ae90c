#include "service/runs/adaptive_execution.hpp"

#include <optional>
#include <string>

#include "io/import/adaptive_loop.hpp"
#include "io/json/json_text.hpp"
#include "io/model/model_reader.hpp"
#include "io/results/result_writer.hpp"
#include "service/ops/log.hpp"
#include "service/ops/private_directory.hpp"
#include "service/runs/job_execution.hpp"
#include "service/runs/metrics.hpp"
#include "solver/thermal/thermal_analysis.hpp"

namespace saasgaps::service {

namespace {

using nlohmann::json;

/// Stops a cycle's solve when the job is cancelled or the server shuts down; keeps no rows.
class StopObserver final : public IterationObserver {
 public:
  StopObserver(JobStore& store, std::int64_t job, const std::atomic<bool>& shutting_down)
      : store_(store), job_(job), shutting_down_(shutting_down) {}
  void on_iteration(const IterationRecord&, const RestartState&) override {}
  bool stop_requested() override { return shutting_down_ || store_.cancel_requested(job_); }

 private:
  JobStore& store_;
  std::int64_t job_;
  const std::atomic<bool>& shutting_down_;
};

/// Where the stored cycles say the loop goes on; none to start from the geometry's own mesh.
std::optional<io::AdaptResume> resume_point(std::vector<StoredAdaptCycle> stored) {
  // The last cycle asked for no sizes: its result was not committed, so it is solved again.
  if (!stored.empty() && !stored.back().next_sizes) stored.pop_back();
  if (stored.empty()) return std::nullopt;
  io::AdaptResume resume;
  for (const StoredAdaptCycle& c : stored) resume.cycles.push_back(io::adaptation_row(json::parse(c.row)));
  resume.sizes = io::adapt_sizes_from_json(json::parse(*stored.back().next_sizes));
  if (stored.size() >= 2) resume.previous = io::adapt_sizes_from_json(json::parse(*stored[stored.size() - 2].next_sizes));
  return resume;
}

std::string adaptive_result_text(const io::AdaptiveRun& run) {
  std::string text;
  io::JsonWriter out(io::string_sink(text));
  io::write_result(out, run.model, run.solution, {}, [&](io::JsonWriter& w) { io::write_adaptation(w, run.cycles); });
  out.flush();
  return text;
}

}  // namespace

void execute_adaptive_run(JobStore& store, EventHub& hub, const ClaimedJob& claimed, const AdaptiveInput& input,
                          const std::atomic<bool>& shutting_down, const OrderingCache* ordering_cache) {
  const std::int64_t id = claimed.job.id;
  auto end = [&](JobState state, const std::optional<std::string>& result, const std::optional<std::string>& message,
                 const std::optional<std::string>& error) {
    store.finish(id, state, result, message, error);
    note_finished(store, id, state, message, error);
  };
  try {
    const PrivateDirectory dir("adapt");
    for (const auto& [name, content] : input.files) dir.write(name, content);
    const json assembly = io::parse_document(input.assembly);
    std::string problems;
    const auto settings = io::read_adapt_settings(
        assembly, [&](const std::string& pointer, const std::string& what) { problems += pointer + ": " + what + "; "; });
    if (!settings) throw std::runtime_error("the stored assembly has no valid adapt: " + problems);
    const std::optional<io::AdaptResume> resume = resume_point(store.adapt_cycles(id, true));
    if (resume) {
      log_info("adapt_resumed", {{"job", id}, {"after_cycle", resume->cycles.back().cycle}});
    }
    StopObserver observer(store, id, shutting_down);
    io::AdaptiveRun run = io::run_adaptive(
        assembly, dir.path(), io::FileAccess::base_only, *settings,
        [&](const Model& model) { return solve_with_heat(model, &observer, nullptr, {}, ordering_cache); },
        [&](const io::AdaptCycle& c, const io::AdaptSizes* next) {
          const std::string row = io::json_text(io::adaptation_json(c));
          store.record_adapt_cycle(id, c.cycle, row,
                                   next != nullptr ? std::optional<std::string>(io::json_text(io::adapt_sizes_json(*next)))
                                                   : std::nullopt);
          hub.notify();
          log_info("adapt_cycle", {{"job", id}, {"cycle", c.cycle}, {"nodes", c.nodes},
                                   {"relative_error", c.relative_error}});
        },
        resume ? &*resume : nullptr, [&] { return observer.stop_requested(); });
    if (run.stopped) {
      const int done = run.cycles.empty() ? 0 : run.cycles.back().cycle;
      // A shutdown hands the job to the next server; a user's cancel keeps it cancelled.
      const std::string where = "during cycle " + std::to_string(done + 1) + " (" + std::to_string(done) +
                                (done == 1 ? " cycle" : " cycles") + " stored)";
      end(shutting_down ? JobState::interrupted : JobState::cancelled, std::nullopt,
          shutting_down ? "the server shut down " + where + "; resumes from there" : "cancelled " + where,
          std::nullopt);
      return;
    }
    JobState state = JobState::converged;
    if (run.solution.status != RunStatus::converged || !run.reached) state = JobState::not_converged;
    run.solution.message += "; " + run.message;  // as saasgaps solve words it
    end(state, adaptive_result_text(run), run.solution.message, std::nullopt);
  } catch (const std::exception& e) {
    const auto* store_error = dynamic_cast<const StoreError*>(&e);
    if (store_error != nullptr && store_error->no_space()) return;  // handed on (interrupted) by the store
    try {
      end(JobState::failed, io::failed_result_text(e.what()), std::nullopt, e.what());
    } catch (const std::exception& again) {
      Metrics::global().count_store_error();
      log_error("job_not_recorded", {{"job", id}, {"error", e.what()}, {"store_error", again.what()},
                                     {"note", "the job stays in the database as running; the next start resumes it"}});
    }
  }
}

}  // namespace saasgaps::service
