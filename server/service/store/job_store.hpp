#pragma once
/// The service's only state: jobs, their submitted models, iteration histories, restart states,
/// results and events, in one SQLite file (WAL, full-sync commits, BEGIN IMMEDIATE writes).
///
/// Every state change is one transaction together with the event that announces it; every finished
/// iteration's history row and restart state commit together (with their event) before the next
/// iteration starts. A single server owns a database at a time (DatabaseLock, database_lock.hpp), so
/// on start-up every job still marked running was left by a dead server.

#include <chrono>
#include <cstdint>
#include <map>
#include <memory>
#include <functional>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "service/ops/utc_time.hpp"
#include "service/store/job_states.hpp"
#include "service/store/sqlite.hpp"
#include "solver/state/resume_options.hpp"

namespace saasgaps::service {

/// The job does not exist.
class JobNotFound : public std::runtime_error {
 public:
  explicit JobNotFound(std::int64_t id) : std::runtime_error("no job " + std::to_string(id)) {}
};

/// The store is open read-only (it could not write at start-up, e.g. a full disk): reads work,
/// writes are refused until space returns (JobStore::recover_writes reopens it writable).
class StoreUnavailable : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct JobRecord {
  std::int64_t id = 0;
  JobState state = JobState::queued;
  std::string title;
  std::string created_at;
  std::optional<std::string> started_at;
  std::optional<std::string> finished_at;
  int iteration = 0;  ///< last finished iteration
  int max_iterations = 0;
  int attempts = 0;       ///< runs started (the first run, resumes, automatic restarts)
  int interruptions = 0;  ///< times a server died while running it
  bool cancel_requested = false;
  std::optional<std::string> error;
  std::optional<std::string> message;
  std::optional<std::string> last_row;  ///< JSON of the last history row
  /// The READ-card changes in force for the job from now on (restart_schedule: a new schedule not
  /// yet used by any committed iteration).
  ResumeOptions settings;
  std::optional<std::string> slurm_job_id;  ///< the Slurm job running it (executor slurm)
  std::optional<std::string> slurm_state;   ///< that Slurm job's state as squeue last showed it
  bool adaptive = false;  ///< an adaptive job (an assembly with `adapt`): its cycles in adapt_cycles
};

/// The right to write a job's iterations and result: the run's attempt number and a secret the
/// service drew when the run started. A later run draws a new one, so a worker presumed dead can
/// never overwrite a newer run's rows.
struct Lease {
  int attempt = 0;
  std::string secret;
};

/// A write from a run that no longer holds the job (stale attempt, wrong secret, job not running).
class LeaseConflict : public JobConflict {
 public:
  using JobConflict::JobConflict;
};

/// What a worker needs to run a job.
struct ClaimedJob {
  JobRecord job;
  std::string model;                             ///< the submitted document
  std::optional<std::vector<std::uint8_t>> state;  ///< the latest restart state, when resuming
  /// This run's lease. A run handed to Slurm has none yet (empty secret): its worker redeems `ticket`.
  Lease lease;
  /// A run handed to Slurm: the single-use ticket (attempt and 128 random bits) its worker trades
  /// for the lease (JobStore::redeem_ticket). Empty for a run in the service's own pool.
  Lease ticket;
};

/// A running Slurm-executed job as the monitor sees it.
struct SlurmRun {
  std::int64_t job = 0;
  int attempt = 0;
  std::string slurm_job_id;
  std::string slurm_state;
  bool cancel_requested = false;
  std::string updated_at;  ///< last change (cancel request, iteration, state)
};

/// How long an iteration's commit took (encoding its state, writing and committing it), in s.
struct CommitTime {
  int iteration = 0;
  double seconds = 0.0;
};

struct JobEvent {
  std::int64_t id = 0;
  std::string kind;  ///< "state" or "iteration"
  std::string data;  ///< JSON
};

/// A study's point as POST /v1/studies hands it to the store (docs/studies.md).
struct StudyPointInput {
  /// "queued": `model` becomes a new job; "converged": answered by `cached_job` with `outputs`;
  /// "failed": refused before running, `message` says why.
  std::string status = "queued";
  std::string model, title;
  int max_iterations = 0;
  std::optional<std::string> cache_key;
  std::optional<std::int64_t> cached_job;
  std::string outputs = "{}";
  std::string message;
};

/// A study's point as stored: `status` empty while it follows its job (the job's state is then the
/// point's), final once its job has finished and its outputs were reduced.
struct StudyPointRow {
  std::size_t index = 0;
  std::optional<std::int64_t> job;
  bool cached = false;
  std::string status;
  std::string outputs = "{}";
  std::string message;
  std::optional<JobState> job_state;  ///< the job's state now (none when the job was deleted)
  std::optional<std::string> job_error;
};

/// What an adaptive job re-imports in every cycle: the uploaded assembly and the files it names.
struct AdaptiveInput {
  std::string assembly;  ///< the assembly document as uploaded
  std::vector<std::pair<std::string, std::string>> files;  ///< (file name, content), in name order
};

/// A stored cycle of an adaptive job.
struct StoredAdaptCycle {
  int cycle = 0;
  std::string row;                        ///< its `adaptation` row (JSON)
  std::optional<std::string> next_sizes;  ///< the sizes it asked for the next mesh (JSON); none for the last
};

struct StudyRecord {
  std::int64_t id = 0;
  std::string title, created_at;
  std::string document;  ///< the study document as submitted
  std::vector<StudyPointRow> points;
};

class JobStore {
 public:
  /// Opens or creates the database, checks its integrity (PRAGMA quick_check: a damaged file is a
  /// StoreError naming the damage), and migrates its schema to the current version. When the file
  /// cannot be written (a full disk) but can be read, opens it read-only instead (see writable()).
  /// max_interruptions: after this many server deaths while running, a job fails instead of resuming.
  JobStore(std::string path, int max_interruptions);
  ~JobStore();

  struct Submitted {
    JobRecord job;
    bool replayed = false;  ///< an earlier request with the same Idempotency-Key made this job
  };
  /// Queues a validated model. With an idempotency key seen before: the same request returns its
  /// job (replayed), a different request under the same key is a JobConflict. `cache_key`
  /// (io/json/canonical_json.hpp): when the job converges, it answers that key from then on.
  Submitted submit(const std::string& model, const std::string& title, int max_iterations,
                   const std::optional<std::string>& idempotency_key, const std::string& request_digest,
                   const std::optional<std::string>& cache_key = std::nullopt);

  /// The result cache (docs/studies.md): the converged job whose model has this cache key, if any.
  /// An entry is written by finish() for a converged job submitted with a key and never resumed
  /// with READ-card changes (they change the result without changing the model), replacing an
  /// older entry of the key; it is deleted with its job (remove, retention).
  [[nodiscard]] std::optional<std::int64_t> cached_job(const std::string& cache_key);
  /// Entries in the cache (the metrics' gauge).
  [[nodiscard]] std::int64_t cache_entries();

  [[nodiscard]] JobRecord get(std::int64_t id);
  struct Page {
    std::vector<JobRecord> jobs;
    std::optional<std::int64_t> next_before;  ///< id to continue below, when more remain
  };
  /// Newest first, optionally one state only; page_size jobs with id below `before`.
  [[nodiscard]] Page list(std::optional<JobState> state, int page_size, std::optional<std::int64_t> before);
  /// History rows (JSON) with iteration > after, in order.
  [[nodiscard]] std::vector<std::string> iterations(std::int64_t id, int after);
  /// Thermal history rows (JSON, io/thermal_row_json.hpp) with index > after, in order.
  [[nodiscard]] std::vector<std::string> thermal_rows(std::int64_t id, int after);
  [[nodiscard]] std::string model(std::int64_t id);
  /// The result document; JobConflict while running, JobNotFound (for the result) when none exists.
  [[nodiscard]] std::optional<std::string> result(std::int64_t id);

  /// A stored result document read in pieces, holding its own connection (and a read transaction)
  /// until destroyed: GET /v1/jobs/{id}/result streams it without a copy of the whole text.
  class StoredResult {
   public:
    virtual ~StoredResult() = default;
    [[nodiscard]] virtual std::size_t size() const = 0;
    /// Bytes [offset, offset + count); throws StoreError when the job was deleted meanwhile.
    virtual void read(std::size_t offset, char* out, std::size_t count) = 0;
  };
  /// The same conditions as result(): JobConflict while running, nullptr when there is none.
  [[nodiscard]] std::unique_ptr<StoredResult> open_result(std::int64_t id);
  [[nodiscard]] std::vector<JobEvent> events(std::int64_t id, std::int64_t after_event, int limit);
  [[nodiscard]] int queue_length();
  [[nodiscard]] int running_count();
  /// Jobs per state (every state present, 0 when none).
  [[nodiscard]] std::vector<std::pair<JobState, int>> count_by_state();
  /// Bytes of the database file and its WAL.
  [[nodiscard]] std::int64_t database_bytes() const;
  /// False while the store cannot write: opened read-only, or a write failed for want of space
  /// (disk full, quota) and recover_writes has not yet found space again. why_not_writable() says
  /// what failed. No job is claimed meanwhile.
  [[nodiscard]] bool writable() const;
  [[nodiscard]] std::string why_not_writable() const;
  /// While not writable, at most once a second: when probe_bytes can be reserved beside the
  /// database again (a probe file, removed at once), reopens a read-only store writable, records
  /// the interruptions still held in memory, and becomes writable. True when writable.
  bool recover_writes();
  /// Free space the probe of recover_writes must find (bytes).
  static constexpr std::int64_t probe_bytes = 1 << 20;

  /// The oldest queued or interrupted job, now running (attempts + 1), or nothing (also while not
  /// writable). In-process runs get their lease; with_ticket (a run handed to Slurm) gets a ticket
  /// instead, which only its worker can trade for the lease.
  std::optional<ClaimedJob> claim(const std::string& worker, bool with_ticket = false);
  /// One finished iteration: its history row, its restart state (only the latest two are kept) and
  /// its event, in one transaction. A commit that fails for want of space hands the job on:
  /// interrupted (not counted as an interruption), recorded at once if the store can, else held in
  /// memory (shown by get and list) until recover_writes records it; then the StoreError is rethrown. previous: the commit time of the iteration before, added to
  /// its stored row as commit_seconds in the same transaction. With a lease (a remote worker),
  /// LeaseConflict unless the lease still holds the running job; an iteration this lease already
  /// committed with the same row is accepted again unchanged (a retried request whose answer was lost).
  void record_iteration(std::int64_t id, int iteration, const std::string& row,
                        const std::vector<std::uint8_t>& state, const std::optional<CommitTime>& previous = {},
                        const Lease* lease = nullptr);
  /// One thermal history row of a run with `thermal` (index: its position in the run) and its
  /// `thermal` event, in one transaction. A row already stored with the same text (a resumed run
  /// reports its rows again) is left alone without an event; a different one replaces it. With a
  /// lease, LeaseConflict unless the lease may commit the job's next iteration. A failure for want
  /// of space hands the job on, as record_iteration does.
  void record_thermal(std::int64_t id, int index, const std::string& row, const Lease* lease = nullptr);
  [[nodiscard]] bool cancel_requested(std::int64_t id);
  /// A run ended: its final state, result document and message (and the commit time of its last
  /// iteration, added to that row as commit_seconds). With a lease, LeaseConflict unless it holds
  /// the running job; the finish spends the lease (no write under it is accepted again). A repeat by
  /// the same lease with the same finish_digest (a retried request) is ignored; any other is a
  /// LeaseConflict. A failure for want of space hands the job on, as record_iteration does.
  void finish(std::int64_t id, JobState state, const std::optional<std::string>& result,
              const std::optional<std::string>& message, const std::optional<std::string>& error,
              const std::optional<CommitTime>& last_commit = {}, const Lease* lease = nullptr,
              const std::string& finish_digest = {});
  /// Whether a finish under `lease` with `finish_digest` would be written (true) or is a retry of
  /// the finish already recorded (false); LeaseConflict otherwise. A read: finish checks again.
  [[nodiscard]] bool finish_allowed(std::int64_t id, const Lease& lease, const std::string& finish_digest);

  /// Cancels a queued or interrupted job at once, or asks a running one to stop at its next
  /// iteration boundary. JobConflict for a finished job.
  JobRecord cancel(std::int64_t id);
  /// Queues a cancelled, not_converged, interrupted or failed job to continue from its last saved
  /// iteration with the given changes. JobConflict when queued, running or converged.
  JobRecord resume(std::int64_t id, const ResumeOptions& changes);
  /// Deletes a finished job and all its rows, and gives the freed pages back to the file system.
  /// JobConflict when not finished.
  void remove(std::int64_t id);
  /// Retention: deletes every finished job that finished before `cutoff` (ISO 8601 UTC, as
  /// utc_now() writes it), then reclaims the space. Returns how many.
  int remove_finished_before(const std::string& cutoff);

  /// Start-up: jobs left running by a dead server become interrupted (to be resumed by the
  /// workers), or failed once interrupted more than max_interruptions times; a job whose cancel was
  /// acknowledged (cancel_requested committed) becomes cancelled, keeping its restart state.
  /// Returns how many. keep_slurm_jobs: jobs handed to a Slurm job stay running, whatever their
  /// cancel flag: the Slurm monitor decides, and it is the one that scancels and records those whose
  /// cancel was acknowledged (the Slurm job may still be running on the cluster). When the store cannot write (a full disk), the
  /// jobs are shown interrupted from memory and recorded by recover_writes once space returns.
  int recover_interrupted(bool keep_slurm_jobs = false);

  // Studies (study_store.cpp, docs/studies.md).

  /// The study, its points, and a queued job for each point to solve, in one transaction: a server
  /// killed at any instant has either all of it or none.
  std::int64_t create_study(const std::string& document, const std::string& title,
                            const std::vector<StudyPointInput>& points);
  /// The study and its points with their jobs' states; JobNotFound (as a study) when there is none.
  [[nodiscard]] StudyRecord study(std::int64_t id);
  /// Every study, newest first, without its document.
  [[nodiscard]] std::vector<StudyRecord> studies();
  /// A point's final status, outputs (JSON) and message, once its job has finished; an empty status
  /// makes it follow its job again (a resumed study).
  void set_study_point(std::int64_t study, std::size_t index, const std::string& status, const std::string& outputs,
                       const std::string& message);

  // Adaptive jobs (adapt_store.cpp, docs/http-api.md).

  /// Queues an adaptive job: `model` (the first mesh's model document, what GET .../model shows),
  /// the assembly and its files, in one transaction. Idempotency keys as submit.
  Submitted submit_adaptive(const std::string& model, const std::string& title, int max_iterations,
                            const AdaptiveInput& input, const std::optional<std::string>& idempotency_key,
                            const std::string& request_digest);
  /// The assembly and files of an adaptive job; none for any other job.
  [[nodiscard]] std::optional<AdaptiveInput> adaptive_input(std::int64_t id);
  /// One solved cycle (its row and the sizes it asked for) and its `adapt_cycle` event, in one
  /// transaction; a cycle stored before is replaced and the cycles after it dropped (a resumed run
  /// solves the last cycle again). Written like a thermal row (run_write: space, hand-on).
  void record_adapt_cycle(std::int64_t id, int cycle, const std::string& row,
                          const std::optional<std::string>& next_sizes);
  /// The stored cycles in order; with_sizes false leaves next_sizes empty (the job view).
  [[nodiscard]] std::vector<StoredAdaptCycle> adapt_cycles(std::int64_t id, bool with_sizes = false);

  // Remote workers and the Slurm executor (run_leases.cpp).

  /// A Slurm worker trades its run's ticket for the lease: the job must be running under the
  /// ticket's attempt, handed to Slurm with exactly this ticket, not yet redeemed. The ticket is
  /// spent; the lease (a new secret) is returned. LeaseConflict otherwise.
  Lease redeem_ticket(std::int64_t id, const Lease& ticket, const std::string& worker);
  /// What the lease holder needs to run: the model, the latest state, the settings. LeaseConflict
  /// unless the lease holds the running job.
  ClaimedJob work(std::int64_t id, const Lease& lease);
  /// Records the Slurm job that runs this attempt; false when the attempt no longer holds the job.
  bool set_slurm_job(std::int64_t id, int attempt, const std::string& slurm_job_id, const std::string& slurm_state);
  /// Running jobs handed to Slurm, oldest first.
  [[nodiscard]] std::vector<SlurmRun> slurm_runs();
  /// The Slurm job's state as squeue shows it now (shown on the job resource).
  void set_slurm_state(std::int64_t id, int attempt, const std::string& slurm_state);
  /// The Slurm job of this attempt ended while the job was still running: a requested cancel becomes
  /// cancelled; anything else is an interruption (interrupted, or failed beyond max_interruptions),
  /// exactly as a server crash. Nothing when the attempt no longer holds the job.
  void slurm_run_ended(std::int64_t id, int attempt, const std::string& slurm_state);
  /// A run that never got going (sbatch failed): an interruption, counted like any other.
  void interrupt_run(std::int64_t id, int attempt, const std::string& what);
  /// Cancel a running job whose Slurm job was scancelled by the service: the lease is revoked.
  void slurm_run_cancelled(std::int64_t id, int attempt, const std::string& why);

 private:
  class Pool;
  /// A running job handed on in memory only (its interruption could not be written yet).
  struct HandedOn {
    int attempt = 0;
    std::string what;
    bool counted = false;  ///< an interruption counted against max_interruptions (a dead server)
  };
  void open_writable();
  void open_read_only(const StoreError& why);
  void require_writable() const;
  /// The rows `query` selects (job id and `after` bound as its two parameters); JobNotFound without the job.
  [[nodiscard]] std::vector<std::string> rows_after(std::int64_t id, const char* query, int after);
  /// One write of a run's commit in a write transaction: `write` (given the job as the transaction
  /// reads it) returns whether to commit. A failure for want of space hands the job on and rethrows.
  void run_write(std::int64_t id, const std::function<bool(Connection&, const JobRecord&)>& write);
  /// A write failed: for want of space, the store is not writable until recover_writes.
  void note_failure(const StoreError& e);
  /// A run's commit failed for want of space: the job becomes interrupted, now or (held in memory)
  /// when recover_writes can record it.
  void hand_on(std::int64_t id, int attempt, const StoreError& why);
  /// Records the interruptions held in memory; StoreError when it cannot.
  void record_handed_on();
  /// The job an earlier request with this Idempotency-Key made (inside the caller's transaction);
  /// none without a key or a job; JobConflict when that request's digest differs.
  static std::optional<JobRecord> replayed_job(Connection& db, const std::optional<std::string>& idempotency_key,
                                               const std::string& request_digest);
  Submitted insert_job(const std::string& model, const std::string& title, int max_iterations,
                       const std::optional<std::string>& idempotency_key, const std::string& request_digest,
                       const std::optional<std::string>& cache_key);
  /// A queued job's rows (job, model, its first event) inside the caller's transaction; its id.
  static std::int64_t insert_job_row(Connection& db, const std::string& model, const std::string& title,
                                     int max_iterations, const std::optional<std::string>& idempotency_key,
                                     const std::string& request_digest, const std::optional<std::string>& cache_key);
  /// The writes of record_iteration, inside its transaction.
  static void write_iteration(Connection& db, std::int64_t id, int iteration, const std::string& row,
                              const std::vector<std::uint8_t>& state, const std::optional<CommitTime>& previous);
  /// A record as the API shows it: a job handed on in memory reads interrupted.
  JobRecord& shown(JobRecord& job) const;
  /// Gives pages freed by deletes back to the file system (auto_vacuum=INCREMENTAL).
  void reclaim_space();

  std::string path_;
  std::unique_ptr<Pool> pool_;
  int max_interruptions_;
  mutable std::mutex state_mutex_;  ///< guards the members below
  bool read_only_ = false;          ///< opened read-only (exclusive mode)
  std::string write_problem_;       ///< why the store cannot write; empty when it can
  std::map<std::int64_t, HandedOn> handed_on_;
  std::mutex probe_mutex_;
  std::chrono::steady_clock::time_point last_probe_{};
};

}  // namespace saasgaps::service
