#include "service/runs/job_execution.hpp"

#include <mutex>

#include "io/model/model_reader.hpp"
#include "io/restart/stored_state.hpp"
#include "io/results/history_json.hpp"
#include "io/results/result_writer.hpp"
#include "io/results/thermal_row_json.hpp"
#include "service/ops/log.hpp"
#include "service/runs/commit_pipeline.hpp"
#include "service/runs/metrics.hpp"
#include "solver/analysis/analysis.hpp"
#include "solver/thermal/thermal_analysis.hpp"

namespace saasgaps::service {

namespace {

/// The model's digest, computed once, when first asked for, on whichever thread asks (the commit
/// pipeline's at the first iteration, or the run's own when it resumes from a state).
class LazyDigest {
 public:
  explicit LazyDigest(const std::string& text) : text_(text) {}
  const std::string& get() const {
    std::call_once(once_, [this] { digest_ = io::model_text_digest(text_); });
    return digest_;
  }

 private:
  const std::string& text_;  // the run's input, which outlives the run
  mutable std::once_flag once_;
  mutable std::string digest_;
};

/// Hands every iteration to the sink, committed on the pipeline's thread while the solver goes on,
/// and tells the solver when to stop.
class SinkObserver final : public IterationObserver {
 public:
  SinkObserver(RunSink& sink, const LazyDigest& digest, const std::atomic<bool>& shutting_down,
               CommitPipeline& pipeline)
      : sink_(sink), digest_(digest), shutting_down_(shutting_down), pipeline_(pipeline) {}

  void on_iteration(const IterationRecord& row, const RestartState& state) override {
    // The previous commit must end before its row and state buffers are reused.
    pipeline_.wait();
    row_ = io::history_row_text(row);
    state_ = state;  // the solver changes `state` next; the copy reuses the buffers of the last one
    pipeline_.post([this, iteration = row.iteration] {
      sink_.iteration(iteration, row_, io::encode_stored_state(state_, digest_.get()));
    });
  }

  /// Thermal rows commit on the pipeline's thread too, in order with the iterations.
  void on_thermal(const ThermalRecord& row) override {
    pipeline_.wait();
    thermal_row_ = io::thermal_row_text(row);
    pipeline_.post([this, index = row.index] { sink_.thermal(index, thermal_row_); });
  }

  /// A failed commit stops the run at once: execute_run then rethrows the failure.
  bool stop_requested() override { return shutting_down_ || pipeline_.failed() || sink_.stop_requested(); }

 private:
  RunSink& sink_;
  const LazyDigest& digest_;
  const std::atomic<bool>& shutting_down_;
  CommitPipeline& pipeline_;
  std::string row_;
  std::string thermal_row_;
  RestartState state_;
};

}  // namespace

void note_run_started(const ClaimedJob& claimed, const std::string& worker) {
  if (claimed.state) {
    log_info("job_resumed", {{"job", claimed.job.id}, {"from_iteration", claimed.job.iteration},
                             {"attempt", claimed.job.attempts}, {"worker", worker}});
  } else {
    log_info("job_started", {{"job", claimed.job.id}, {"attempt", claimed.job.attempts}, {"worker", worker}});
  }
}

void note_iteration(std::int64_t job, const std::string& row) {
  double seconds = 0.0;
  int attempt = 1;
  int iteration = 0;
  try {
    const nlohmann::json j = io::parse_document(row);
    seconds = j.value("seconds", 0.0);
    attempt = j.value("attempt", 1);
    iteration = j.value("iteration", 0);
  } catch (const std::exception&) {  // nlohmann's for a figure of the wrong type, ModelError for the text
    // The row is committed already; a line without its figures is better than none.
  }
  Metrics::global().count_iteration(seconds);
  log_info("job_iteration", {{"job", job}, {"iteration", iteration}, {"attempt", attempt}, {"seconds", seconds}});
}

void note_finished(JobStore& store, std::int64_t job, JobState state, const std::optional<std::string>& message,
                   const std::optional<std::string>& error) {
  Metrics::global().count_finished(state);
  nlohmann::json fields = {{"job", job}, {"state", to_string(state)}};
  try {
    fields["iterations"] = store.get(job).iteration;
  } catch (const std::exception&) {
    // Deleted meanwhile, or the database is failing: the line goes out without the count.
  }
  if (message) fields["message"] = *message;
  if (error) fields["error"] = *error;
  if (state == JobState::failed) {
    log_error("job_finished", fields);
  } else {
    log_info("job_finished", fields);
  }
}

std::shared_ptr<const ParsedModel> parse_run_model(const std::string& text) {
  auto parsed = std::make_shared<ParsedModel>();
  parsed->model = io::parse_model(text);
  return parsed;
}

void execute_run(const RunInput& input, RunSink& sink, const std::atomic<bool>& shutting_down,
                 const OrderingCache* ordering_cache) {
  // Declared in this order so that the pipeline, destroyed first, ends the commit in flight while
  // what it reads (the observer's row and state buffers, the model's digest) still exists, on every
  // way out: a run that throws after an iteration was posted must not leave that commit reading a
  // destroyed observer.
  std::shared_ptr<const ParsedModel> parsed;
  const LazyDigest digest(input.model);
  std::optional<SinkObserver> observer;
  CommitPipeline pipeline;
  try {
    // The service hands over the model its POST read already; otherwise (a resume, a restart, a
    // remote worker) the document is read here.
    parsed = input.parsed ? input.parsed : parse_run_model(input.model);
    const Model& model = parsed->model;
    std::optional<RestartState> state;
    if (input.state) state = io::decode_stored_state(*input.state, digest.get());

    observer.emplace(sink, digest, shutting_down, pipeline);
    const Solution solution = solve_with_heat(model, &*observer, state ? &*state : nullptr, input.settings, ordering_cache);
    // Every iteration is committed before the run's end is; a commit that failed ends the run here.
    pipeline.wait();

    JobState final_state = JobState::converged;
    std::string message = solution.message;
    if (solution.status == RunStatus::not_converged) final_state = JobState::not_converged;
    if (solution.status == RunStatus::stopped) {
      // A shutdown hands the job to the next server; a user's cancel keeps it cancelled.
      final_state = shutting_down ? JobState::interrupted : JobState::cancelled;
      message = shutting_down ? "the server shut down after iteration " + std::to_string(solution.iterations) +
                                    "; resumes from there"
                              : "cancelled after iteration " + std::to_string(solution.iterations);
    }
    sink.finish(final_state, io::result_text(model, solution), message, std::nullopt);
  } catch (const RunAbandoned&) {
    throw;
  } catch (const std::exception& e) {
    const auto* store_error = dynamic_cast<const StoreError*>(&e);
    if (store_error != nullptr && store_error->no_space()) {
      // The store handed the job on (interrupted) when the commit failed: it resumes once space
      // returns. Recording it failed would lose that.
      return;
    }
    try {
      // The commit in flight ends first (its own failure, if any, was rethrown already or is this one).
      pipeline.wait();
      sink.finish(JobState::failed, io::failed_result_text(e.what()), std::nullopt, e.what());
    } catch (const RunAbandoned&) {
      throw;
    } catch (const std::exception& again) {
      // Even the failure cannot be recorded (the database gone): the job stays running in the file
      // and the next server start marks it interrupted and resumes it.
      Metrics::global().count_store_error();
      log_error("job_not_recorded", {{"job", input.job}, {"error", e.what()}, {"store_error", again.what()},
                                     {"note", "the job stays in the database as running; the next start resumes it"}});
    }
  }
}

}  // namespace saasgaps::service
