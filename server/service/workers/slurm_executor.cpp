#include "service/workers/slurm_executor.hpp"

#include <csignal>
#include <iostream>
#include <set>
#include <sstream>

#include "io/mesher/subprocess.hpp"
#include "service/ops/log.hpp"
#include "service/workers/worker_protocol.hpp"

namespace saasgaps::service {

namespace {

using io::ProcessResult;
using io::run_process;

constexpr std::chrono::seconds command_limit{60};

/// Slurm job states in which the batch script may still run (or run again). Anything else (COMPLETED,
/// FAILED, CANCELLED, TIMEOUT, NODE_FAIL, PREEMPTED, BOOT_FAIL, DEADLINE, OUT_OF_MEMORY, COMPLETING:
/// the script has exited) means the worker is gone.
bool alive(const std::string& state) {
  static const std::set<std::string> states = {"PENDING",  "RUNNING",   "CONFIGURING",  "SUSPENDED",
                                               "REQUEUED", "REQUEUE_HOLD", "REQUEUE_FED", "RESIZING",
                                               "SIGNALING", "STAGE_OUT", "STOPPED",      "RESV_DEL_HOLD"};
  return states.count(state) > 0;
}

std::string trimmed(const std::string& text) {
  const auto first = text.find_first_not_of(" \t\r\n");
  if (first == std::string::npos) return {};
  return text.substr(first, text.find_last_not_of(" \t\r\n") - first + 1);
}

/// The executor's own notes, as structured log lines (log.hpp) like the rest of the server's.
void log(const std::string& line) { log_info("slurm_executor", {{"message", line}}); }

}  // namespace

std::string shell_quote(const std::string& word) {
  std::string quoted = "'";
  for (char c : word) quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return quoted + "'";
}

std::vector<std::string> split_words(const std::string& text) {
  std::istringstream in(text);
  std::vector<std::string> words;
  for (std::string w; in >> w;) words.push_back(w);
  return words;
}

SlurmExecutor::SlurmExecutor(JobStore& store, EventHub& hub, SlurmOptions options)
    : store_(store), hub_(hub), options_(std::move(options)) {
  // A Slurm command that exits before reading its input must not kill the service with SIGPIPE.
  std::signal(SIGPIPE, SIG_IGN);
  thread_ = std::thread([this] { loop(); });
}

SlurmExecutor::~SlurmExecutor() {
  stopping_ = true;
  hub_.notify();
  thread_.join();
}

std::string batch_script(const SlurmOptions& options, std::int64_t job) {
  std::string command = "exec " + shell_quote(options.worker_binary) + " worker --server " +
                        shell_quote(options.worker_url) + " --job " + std::to_string(job);
  if (!options.token_file.empty()) command += " --token-file " + shell_quote(options.token_file);
  // The run's ticket travels in the environment (SAASGAPS_TICKET, exported by sbatch), not in the script.
  return "#!/bin/sh\n# saasgaps job " + std::to_string(job) + "\n" + command + "\n";
}

void SlurmExecutor::loop() {
  std::uint64_t seen = hub_.version();
  auto last_monitor = std::chrono::steady_clock::time_point{};
  auto dispatch_paused_until = std::chrono::steady_clock::time_point{};
  int sbatch_failures = 0;
  while (!stopping_) {
    const auto now = std::chrono::steady_clock::now();
    try {
      store_.recover_writes();  // after a full disk: dispatching resumes once space returns
      if (now >= dispatch_paused_until) {
        if (dispatch()) {
          sbatch_failures = 0;
        } else {
          // sbatch failed (the controller is down, a bad option): back off rather than burn the
          // jobs' interruption budget in a burst.
          ++sbatch_failures;
          dispatch_paused_until = now + options_.poll * std::min(1 << std::min(sbatch_failures, 5), 30);
        }
      }
      if (now - last_monitor >= options_.poll) {
        monitor();
        last_monitor = now;
      }
    } catch (const std::exception& e) {
      log(std::string("dispatch or monitor failed, retrying: ") + e.what());
    }
    seen = hub_.wait(seen, options_.poll);
  }
}

bool SlurmExecutor::dispatch() {
  while (!stopping_) {
    std::optional<ClaimedJob> claimed = store_.claim("slurm (submitting)", true);
    if (!claimed) return true;
    const std::int64_t id = claimed->job.id;
    std::vector<std::string> argv = {"sbatch", "--parsable", "--job-name=" + options_.job_name, "--no-requeue"};
    if (!options_.partition.empty()) argv.push_back("--partition=" + options_.partition);
    if (!options_.account.empty()) argv.push_back("--account=" + options_.account);
    if (!options_.time_limit.empty()) argv.push_back("--time=" + options_.time_limit);
    if (!options_.log_dir.empty()) argv.push_back("--output=" + options_.log_dir + "/saasgaps-job-" + std::to_string(id) + "-%j.out");
    argv.insert(argv.end(), options_.extra.begin(), options_.extra.end());
    // The worker trades the ticket for the run's lease (once): only a job the service handed to
    // Slurm can be leased, and a ticket read later from the Slurm job's environment is spent.
    const ProcessResult r = run_process(argv, batch_script(options_, id),
                                        {"SAASGAPS_TICKET=" + worker_protocol::format_lease(claimed->ticket)}, command_limit);
    const std::string slurm_id = trimmed(r.out.substr(0, r.out.find(';')));
    if (r.exit_code != 0 || slurm_id.empty() || slurm_id.find_first_not_of("0123456789_") != std::string::npos) {
      const std::string why = "sbatch failed (exit " + std::to_string(r.exit_code) + "): " + trimmed(r.err + " " + r.out);
      log("job " + std::to_string(id) + ": " + why);
      store_.interrupt_run(id, claimed->ticket.attempt, why);
      hub_.notify();
      return false;
    }
    if (!store_.set_slurm_job(id, claimed->ticket.attempt, slurm_id, "PENDING")) {
      // Cancelled between the claim and now: nothing is to run.
      scancel(slurm_id);
    }
    log("job " + std::to_string(id) + " attempt " + std::to_string(claimed->ticket.attempt) + " is Slurm job " + slurm_id);
    note_run_started(*claimed, "slurm job " + slurm_id);
    hub_.notify();
  }
  return true;
}

void SlurmExecutor::monitor() {
  const std::vector<SlurmRun> runs = store_.slurm_runs();
  std::set<std::int64_t> running_jobs;
  for (const SlurmRun& run : runs) running_jobs.insert(run.job);
  std::erase_if(cancel_seen_, [&](const auto& entry) { return running_jobs.count(entry.first) == 0; });
  const auto now = std::chrono::steady_clock::now();
  for (const SlurmRun& run : last_runs_) {
    if (running_jobs.count(run.job) == 0) ending_[run.job] = {run, now};
  }
  last_runs_ = runs;
  std::erase_if(ending_, [&](const auto& entry) {
    return running_jobs.count(entry.first) > 0 || now - entry.second.since > std::chrono::minutes(2);
  });
  if (runs.empty() && ending_.empty()) return;

  std::string ids;
  for (const SlurmRun& run : runs) ids += (ids.empty() ? "" : ",") + run.slurm_job_id;
  for (const auto& [job, ending] : ending_) ids += (ids.empty() ? "" : ",") + ending.run.slurm_job_id;
  const ProcessResult r = run_process({"squeue", "--noheader", "--states=all", "--format=%i|%T", "--jobs=" + ids}, "",
                                      {}, command_limit);
  std::map<std::string, std::string> states;
  if (r.exit_code == 0) {
    std::istringstream lines(r.out);
    for (std::string line; std::getline(lines, line);) {
      const auto bar = line.find('|');
      if (bar != std::string::npos) states[trimmed(line.substr(0, bar))] = trimmed(line.substr(bar + 1));
    }
  } else if (r.err.find("Invalid job id") == std::string::npos) {
    // squeue itself failed (the controller is busy or down): conclude nothing this time.
    log("squeue failed (exit " + std::to_string(r.exit_code) + "): " + trimmed(r.err));
    return;
  }
  // Otherwise none of the jobs is known any more: every one has ended (and been purged).

  for (auto it = ending_.begin(); it != ending_.end();) {
    const auto found = states.find(it->second.run.slurm_job_id);
    // COMPLETING: the worker has exited but Slurm has not yet said how the job ended.
    if (found != states.end() && (alive(found->second) || found->second == "COMPLETING")) {
      ++it;
      continue;
    }
    store_.set_slurm_state(it->first, it->second.run.attempt, found == states.end() ? "GONE" : found->second);
    it = ending_.erase(it);
  }
  for (const SlurmRun& run : runs) {
    const auto found = states.find(run.slurm_job_id);
    const std::string state = found == states.end() ? "GONE" : found->second;
    if (!alive(state)) {
      log("job " + std::to_string(run.job) + ": Slurm job " + run.slurm_job_id + " is " + state);
      store_.slurm_run_ended(run.job, run.attempt, state);
      hub_.notify();
      continue;
    }
    if (state != run.slurm_state) store_.set_slurm_state(run.job, run.attempt, state);
    if (!run.cancel_requested) continue;
    const auto seen = cancel_seen_.try_emplace(run.job, now).first->second;
    if (state == "PENDING" || now - seen >= options_.cancel_grace) {
      scancel(run.slurm_job_id);
      store_.slurm_run_cancelled(run.job, run.attempt,
                                 state == "PENDING" ? "its Slurm job " + run.slurm_job_id + " was cancelled before it started"
                                                    : "the worker did not stop in time; Slurm job " + run.slurm_job_id +
                                                          " was cancelled");
      hub_.notify();
    }
  }
}

void SlurmExecutor::scancel(const std::string& slurm_job_id) {
  const ProcessResult r = run_process({"scancel", slurm_job_id}, "", {}, command_limit);
  if (r.exit_code != 0) log("scancel " + slurm_job_id + " failed: " + trimmed(r.err));
}

}  // namespace saasgaps::service
