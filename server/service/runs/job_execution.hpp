#pragma once
/// One run of a job, wherever it happens: in the service's own worker pool (executor local) or in a
/// `saasgaps worker` process that reports over HTTP (executor slurm, or a worker started by hand).
/// Both run the same function and hand the same bytes (history row JSON, restart state CBOR, result
/// document) to a sink; the service commits them with the same JobStore calls. That is what makes a
/// remote run's result identical, to the last digit, to a local one.

#include <atomic>
#include <cstdint>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "service/store/job_store.hpp"
#include "solver/lac/ordering_cache.hpp"
#include "solver/model/model.hpp"

namespace saasgaps::service {

/// A model document read and checked. Its digest (which ties restart states to it) is not part of
/// reading: execute_run computes it from the text when a state is first written or checked
/// (io::model_text_digest), on the commit thread while the solve goes on.
struct ParsedModel {
  Model model;
};

/// Reads a model document for a run (io::parse_model).
std::shared_ptr<const ParsedModel> parse_run_model(const std::string& text);

/// What a run starts from.
struct RunInput {
  std::string model;                               ///< the submitted document
  std::shared_ptr<const ParsedModel> parsed;       ///< `model` read already, when the service kept it
  std::optional<std::vector<std::uint8_t>> state;  ///< the latest committed restart state (CBOR)
  ResumeOptions settings;                          ///< resume changes in force
  std::int64_t job = 0;                            ///< the job's id, for log lines
};

/// Where a run's iterations and its end go.
class RunSink {
 public:
  virtual ~RunSink() = default;
  /// A finished iteration: committed (row and state in one transaction) when this returns. Called
  /// on a CommitPipeline's thread while the solver computes the next iteration, so it may run
  /// concurrently with stop_requested (never with another iteration or finish).
  virtual void iteration(int iteration, const std::string& row, const std::vector<std::uint8_t>& state) = 0;
  /// A thermal history row (io/thermal_row_json.hpp) at position `index` of the run: committed
  /// when this returns. Called on the CommitPipeline's thread like iteration.
  virtual void thermal(int index, const std::string& row) = 0;
  /// A cancel was asked for: stop at this iteration boundary. (A sink that learns of a cancel only
  /// from a commit's answer stops one iteration later: the commit overlaps the next iteration.)
  virtual bool stop_requested() = 0;
  /// The run ended with this job state, result document, message and error.
  virtual void finish(JobState state, const std::optional<std::string>& result,
                      const std::optional<std::string>& message, const std::optional<std::string>& error) = 0;
};

/// The sink can no longer speak for this run (its lease was revoked, the service is unreachable):
/// the run stops without finishing; the service decides what becomes of the job.
class RunAbandoned : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// What the service notes when a run's iteration or end is committed, whichever executor ran it
/// (the local sink and the remote worker routes both call these): a structured log line and the
/// /metrics counters.
void note_run_started(const ClaimedJob& claimed, const std::string& worker);
void note_iteration(std::int64_t job, const std::string& row);
/// `store` gives the job's last iteration for the line.
void note_finished(JobStore& store, std::int64_t job, JobState state, const std::optional<std::string>& message,
                   const std::optional<std::string>& error);

/// Solves the job from `input` and reports every iteration and the end to `sink`. A stop while
/// `shutting_down` hands the job on (interrupted); a stop the sink asked for is a cancel. Solver
/// failures end the run as failed; RunAbandoned from the sink propagates.
/// ordering_cache (optional): where fill-reducing orderings of meshes solved before are kept.
void execute_run(const RunInput& input, RunSink& sink, const std::atomic<bool>& shutting_down,
                 const OrderingCache* ordering_cache = nullptr);

}  // namespace saasgaps::service
