#pragma once
/// The Slurm executor (`saasgaps serve --executor slurm`): every queued or interrupted job becomes a
/// Slurm batch job running `saasgaps worker` against this service, and a monitor follows those
/// Slurm jobs with squeue:
///   - a Slurm job that ends while its run still holds the job (node failure, time limit,
///     preemption, someone's scancel) interrupts the job, exactly as a server crash does; the job is
///     resubmitted from its last committed iteration, up to max_interruptions times;
///   - a cancel stops the worker at its next iteration boundary; a Slurm job still pending, or a
///     worker that does not stop within the grace time, is scancelled and its lease revoked;
///   - after a service restart, runs whose Slurm jobs are still alive keep their leases.
/// Slurm's own commands (sbatch --parsable, squeue, scancel) are run with argument vectors.

#include <atomic>
#include <chrono>
#include <map>
#include <string>
#include <thread>
#include <vector>

#include "service/store/event_hub.hpp"
#include "service/store/job_store.hpp"

namespace saasgaps::service {

struct SlurmOptions {
  std::string partition;                ///< sbatch --partition (empty: the cluster's default)
  std::string account;                  ///< sbatch --account
  std::string time_limit;               ///< sbatch --time, in Slurm's formats (e.g. 2:00:00)
  std::vector<std::string> extra;       ///< further sbatch arguments, as given
  std::string worker_url;               ///< the service's URL as workers on the cluster reach it
  std::string token_file;               ///< the token file as workers see it (empty: no token)
  std::string worker_binary;            ///< saasgaps as workers see it
  std::string log_dir;                  ///< worker logs (sbatch --output); empty: sbatch's default
  std::string job_name = "saasgaps";    ///< sbatch --job-name
  std::chrono::milliseconds poll{2000};           ///< squeue at most this often
  std::chrono::milliseconds cancel_grace{30000};  ///< a cancelled running worker's time to stop
};

class SlurmExecutor {
 public:
  SlurmExecutor(JobStore& store, EventHub& hub, SlurmOptions options);
  /// Stops dispatching and monitoring. Slurm jobs keep running; the next service start finds them.
  ~SlurmExecutor();
  SlurmExecutor(const SlurmExecutor&) = delete;
  SlurmExecutor& operator=(const SlurmExecutor&) = delete;

 private:
  void loop();
  /// Submits every claimable job; false when sbatch failed (then dispatching pauses).
  bool dispatch();
  void monitor();
  void scancel(const std::string& slurm_job_id);

  JobStore& store_;
  EventHub& hub_;
  SlurmOptions options_;
  std::map<std::int64_t, std::chrono::steady_clock::time_point> cancel_seen_;  ///< job -> first seen
  /// Runs that finished while their Slurm job was still ending: followed until Slurm says how it
  /// ended, so the job resource shows that (COMPLETED) rather than the last state seen running.
  struct Ending {
    SlurmRun run;
    std::chrono::steady_clock::time_point since;
  };
  std::map<std::int64_t, Ending> ending_;
  std::vector<SlurmRun> last_runs_;
  std::atomic<bool> stopping_{false};
  std::thread thread_;
};

/// The batch script that runs one job's worker: `exec BINARY worker --server URL --job ID
/// [--token-file F]`, every word quoted. The run's ticket is not in it (it travels in the environment).
std::string batch_script(const SlurmOptions& options, std::int64_t job);

/// Quotes a word for a POSIX shell: '...' with every ' written as '\''.
std::string shell_quote(const std::string& word);

/// Splits --slurm-extra at white space (no quoting: one sbatch option per word).
std::vector<std::string> split_words(const std::string& text);

}  // namespace saasgaps::service
