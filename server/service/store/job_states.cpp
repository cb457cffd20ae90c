#include "service/store/job_states.hpp"

#include <vector>

namespace saasgaps::service {

namespace {

using S = JobState;
using E = JobAction;

bool ended(const JobFacts& f, JobState outcome) { return f.outcome == outcome; }

// Every allowed transition, once. Guards are plain functions so the table stays a constant.
constexpr Transition table[] = {
    {std::nullopt, E::submit, S::queued, "", nullptr},

    {S::queued, E::claim, S::running, "", nullptr},
    {S::interrupted, E::claim, S::running, "", nullptr},

    {S::running, E::iteration, S::running, "", nullptr},

    {S::running, E::finish, S::converged, "the run converged", [](const JobFacts& f) { return ended(f, S::converged); }},
    {S::running, E::finish, S::not_converged, "the run reached its iteration limit",
     [](const JobFacts& f) { return ended(f, S::not_converged); }},
    {S::running, E::finish, S::failed, "the run failed", [](const JobFacts& f) { return ended(f, S::failed); }},
    {S::running, E::finish, S::cancelled, "the run stopped at a requested cancel",
     [](const JobFacts& f) { return ended(f, S::cancelled); }},
    {S::running, E::finish, S::interrupted, "the service shut down; the next start resumes it",
     [](const JobFacts& f) { return ended(f, S::interrupted); }},

    {S::queued, E::request_cancel, S::cancelled, "at once", nullptr},
    {S::running, E::request_cancel, S::running, "the run stops at its next iteration boundary", nullptr},
    {S::interrupted, E::request_cancel, S::cancelled, "at once", nullptr},

    {S::running, E::revoke, S::cancelled, "", nullptr},

    {S::running, E::interrupt, S::cancelled, "its cancel was requested",
     [](const JobFacts& f) { return f.cancel_requested; }},
    {S::running, E::interrupt, S::failed, "interrupted more than max_interruptions times",
     [](const JobFacts& f) { return f.counted && f.interruptions > f.max_interruptions; }},
    {S::running, E::interrupt, S::interrupted, "otherwise", nullptr},

    {S::cancelled, E::resume, S::queued, "", nullptr},
    {S::not_converged, E::resume, S::queued, "", nullptr},
    {S::interrupted, E::resume, S::queued, "", nullptr},
    {S::failed, E::resume, S::queued, "", nullptr},

    {S::converged, E::remove, std::nullopt, "", nullptr},
    {S::not_converged, E::remove, std::nullopt, "", nullptr},
    {S::failed, E::remove, std::nullopt, "", nullptr},
    {S::cancelled, E::remove, std::nullopt, "", nullptr},
};

/// The states that accept `event`, in the table's order.
std::vector<JobState> accepting(JobAction event) {
  std::vector<JobState> states;
  for (const Transition& t : table) {
    if (t.event != event || !t.from) continue;
    if (states.empty() || states.back() != *t.from) states.push_back(*t.from);
  }
  return states;
}

/// "a", "a or b", "a, b or c".
std::string alternatives(const std::vector<JobState>& states) {
  std::string text;
  for (std::size_t k = 0; k < states.size(); ++k) {
    if (k > 0) text += k + 1 == states.size() ? " or " : ", ";
    text += to_string(states[k]);
  }
  return text;
}

/// What the refusal of `event` says after "job N is STATE; ".
std::string refusal(JobState from, JobAction event, const JobFacts& facts) {
  if (event == E::remove) return "cancel it before deleting";
  if (event == E::finish && accepts(from, event)) {
    return std::string("a run cannot end ") + to_string(facts.outcome);
  }
  const char* needs = "";
  switch (event) {
    case E::submit: needs = "are submitted"; break;
    case E::claim: needs = "can be claimed"; break;
    case E::iteration: needs = "record iterations"; break;
    case E::finish: needs = "can finish"; break;
    case E::request_cancel: needs = "can be cancelled"; break;
    case E::revoke: needs = "can be revoked"; break;
    case E::interrupt: needs = "can be interrupted"; break;
    case E::resume: needs = "can be resumed"; break;
    case E::remove: break;
  }
  return "only " + alternatives(accepting(event)) + " jobs " + needs;
}

}  // namespace

std::optional<JobState> parse_job_state(std::string_view text) { return job_state_names.value(text); }

bool is_finished(JobState state) {
  return state == JobState::converged || state == JobState::not_converged || state == JobState::failed ||
         state == JobState::cancelled;
}

std::span<const Transition> job_transitions() { return table; }

const Transition* find_transition(std::optional<JobState> from, JobAction event, const JobFacts& facts) {
  for (const Transition& t : table) {
    if (t.from == from && t.event == event && (t.holds == nullptr || t.holds(facts))) return &t;
  }
  return nullptr;
}

bool accepts(JobState from, JobAction event) {
  for (const Transition& t : table) {
    if (t.from == from && t.event == event) return true;
  }
  return false;
}

std::string sql_states_accepting(JobAction event) {
  std::string list;
  for (JobState s : accepting(event)) list += (list.empty() ? "'" : ", '") + std::string(to_string(s)) + "'";
  return list;
}

std::optional<JobState> next_state(std::int64_t id, JobState from, JobAction event, const JobFacts& facts) {
  const Transition* t = find_transition(from, event, facts);
  if (t == nullptr) {
    throw JobConflict("job " + std::to_string(id) + " is " + to_string(from) + "; " + refusal(from, event, facts));
  }
  return t->to;
}

}  // namespace saasgaps::service
