#pragma once
/// A job's states and the actions that move it, as one table: every allowed transition listed once
/// (job_transitions()), with its guard; what the table does not list is refused. The store asks it
/// before every change of a job's state (job_store.cpp, retention.cpp, run_leases.cpp).
///
///   (none)       submit          -> queued
///   queued       claim           -> running       a run starts: attempt + 1, a new lease
///   interrupted  claim           -> running       continues from the last committed iteration
///   running      iteration       -> running       under the run's lease (checked by the store)
///   running      finish          -> the run's outcome: converged, not_converged, failed, cancelled
///                                   (it stopped at a requested cancel) or interrupted (the service
///                                   shut down; not counted as an interruption)
///   queued       request_cancel  -> cancelled     at once
///   running      request_cancel  -> running       cancel_requested: the run stops at its next boundary
///   interrupted  request_cancel  -> cancelled     at once
///   running      revoke          -> cancelled     the service ended the run's Slurm job (scancel)
///   running      interrupt       -> cancelled     when its cancel was requested (kept resumable)
///                                -> failed        when counted and beyond max_interruptions
///                                -> interrupted   otherwise (the server died and is recovering on
///                                                 start, the run's Slurm job ended, sbatch failed,
///                                                 the disk is full)
///   cancelled, not_converged, interrupted, failed   resume -> queued
///   converged, not_converged, failed, cancelled     remove -> (deleted)

#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>

#include "solver/base/name_table.hpp"

namespace saasgaps::service {

enum class JobState { queued, running, converged, not_converged, failed, cancelled, interrupted };
inline constexpr std::array<JobState, 7> all_job_states = {JobState::queued,        JobState::running,
                                                           JobState::converged,     JobState::not_converged,
                                                           JobState::failed,        JobState::cancelled,
                                                           JobState::interrupted};

inline constexpr NameTable<JobState, 7> job_state_names{{{{JobState::queued, "queued"},
                                                         {JobState::running, "running"},
                                                         {JobState::converged, "converged"},
                                                         {JobState::not_converged, "not_converged"},
                                                         {JobState::failed, "failed"},
                                                         {JobState::cancelled, "cancelled"},
                                                         {JobState::interrupted, "interrupted"}}}};
inline const char* to_string(JobState state) { return job_state_names.name(state).data(); }
std::optional<JobState> parse_job_state(std::string_view text);
bool is_finished(JobState state);  ///< converged, not_converged, failed, cancelled

/// The request does not fit the job's state (resume while running, result while running, ...).
class JobConflict : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// What happens to a job (an action, to tell it from the JobEvent a state change records).
enum class JobAction {
  submit,          ///< POST /v1/jobs
  claim,           ///< a worker starts a run
  iteration,       ///< the run commits an iteration
  finish,          ///< the run ends with an outcome (JobFacts::outcome)
  request_cancel,  ///< a user asks to cancel
  revoke,          ///< the service cancels a running job without its run (its Slurm job was scancelled)
  interrupt,       ///< the run ended without finishing (recover on start, Slurm job ended, no space)
  resume,          ///< a user resumes the job
  remove,          ///< a user, or the retention, deletes the job
};
inline constexpr NameTable<JobAction, 9> job_action_names{{{{JobAction::submit, "submit"},
                                                            {JobAction::claim, "claim"},
                                                            {JobAction::iteration, "iteration"},
                                                            {JobAction::finish, "finish"},
                                                            {JobAction::request_cancel, "request_cancel"},
                                                            {JobAction::revoke, "revoke"},
                                                            {JobAction::interrupt, "interrupt"},
                                                            {JobAction::resume, "resume"},
                                                            {JobAction::remove, "remove"}}}};
inline const char* to_string(JobAction event) { return job_action_names.name(event).data(); }

/// What guards read besides the state.
struct JobFacts {
  JobState outcome = JobState::failed;  ///< finish: the state the run ended in
  bool cancel_requested = false;        ///< interrupt: a cancel was acknowledged (committed)
  bool counted = true;                  ///< interrupt: counts against max_interruptions
  int interruptions = 0;                ///< interrupt: the job's interruptions, this one included
  int max_interruptions = 0;            ///< interrupt: the server's limit
};

struct Transition {
  std::optional<JobState> from;  ///< nothing: no job yet (submit)
  JobAction event;
  std::optional<JobState> to;    ///< nothing: the job is gone (remove)
  const char* guard;             ///< when it applies, in words; empty: always
  bool (*holds)(const JobFacts&);  ///< the guard; nullptr: always
};

/// The table. Rows of one state and event are tried in order; the first whose guard holds applies.
std::span<const Transition> job_transitions();

/// The transition `event` makes from `from` given `facts`, or nullptr when the table refuses it.
const Transition* find_transition(std::optional<JobState> from, JobAction event, const JobFacts& facts = {});

/// Whether `event` may happen to a job in `from` at all, whatever the guards decide.
bool accepts(JobState from, JobAction event);

/// The states that accept `event`, as an SQL list: "'queued', 'interrupted'".
std::string sql_states_accepting(JobAction event);

/// The state `event` leads job `id` from `from` to (nothing: deleted). JobConflict when refused,
/// naming the job, its state and what the event needs ("job 3 is converged; only cancelled,
/// not_converged, interrupted or failed jobs can be resumed").
std::optional<JobState> next_state(std::int64_t id, JobState from, JobAction event, const JobFacts& facts = {});

}  // namespace saasgaps::service
