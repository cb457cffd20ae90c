/// Runs of jobs and their leases: starting a run, checking a lease on every write, interrupting a
/// run that ended without finishing; the operations of remote workers and the Slurm executor.
#include <cstdio>
#include <random>

#include "io/json/fingerprint.hpp"
#include "io/restart/state_codec.hpp"
#include "service/store/job_rows.hpp"
#include "service/store/job_store.hpp"
#include "service/store/job_store_detail.hpp"

namespace saasgaps::service {

using namespace detail;

namespace {

/// 128 random bits in hex: the secret half of a run's lease or ticket.
std::string new_lease_secret() {
  std::random_device device;
  std::string secret;
  for (int k = 0; k < 4; ++k) {
    char word[9];
    std::snprintf(word, sizeof word, "%08x", static_cast<unsigned>(device()));
    secret += word;
  }
  return secret;
}

/// The model and the latest restart state of claimed.job.
void load_run_input(Connection& db, ClaimedJob& claimed) {
  const std::int64_t id = claimed.job.id;
  Statement model = db.prepare("SELECT document FROM models WHERE job_id = ?");
  model.bind(1, id);
  if (!model.step()) throw StoreError("job " + std::to_string(id) + " has no model");
  claimed.model = model.text(0);
  Statement state = db.prepare("SELECT state FROM states WHERE job_id = ? ORDER BY iteration DESC LIMIT 1");
  state.bind(1, id);
  if (state.step()) claimed.state = state.blob(0);
}

/// A running job cancelled without its run's say (its Slurm job ended or was scancelled, or the
/// server died after acknowledging its cancel): the lease is revoked, so the run can write nothing
/// more. The caller asked the table (job_states.hpp).
void cancel_revoked(Connection& db, const JobRecord& job, JobState cancelled, const std::string& why) {
  db.prepare("UPDATE jobs SET lease_owner = NULL, lease_secret = NULL, lease_ticket = NULL, cancel_requested = 0 WHERE id = ?")
      .bind(1, job.id)
      .run();
  change_state(db, job.id, cancelled, "cancelled after iteration " + std::to_string(job.iteration) + "; " + why);
}

}  // namespace

namespace detail {

ClaimedJob start_run(Connection& db, std::int64_t id, const std::string& worker, bool with_ticket) {
  const JobState running = *next_state(id, require_job(db, id).state, JobAction::claim);
  const std::string now = utc_now();
  const std::string secret = new_lease_secret();
  // A run handed to Slurm holds a ticket, not yet a lease: only the worker sbatch started can
  // redeem it (once), so nobody else can take the run, however the job's id is learnt.
  db.prepare(
        "UPDATE jobs SET attempts = attempts + 1, started_at = COALESCE(started_at, ?), lease_owner = ?,"
        " heartbeat_at = ?, cancel_requested = 0, finished_at = NULL, error = NULL, lease_secret = ?,"
        " lease_ticket = ?, finish_digest = NULL, slurm_job_id = NULL, slurm_state = NULL WHERE id = ?")
      .bind(1, now)
      .bind(2, worker)
      .bind(3, now)
      .bind(4, with_ticket ? std::optional<std::string>() : secret)
      .bind(5, with_ticket ? std::optional<std::string>(secret) : std::nullopt)
      .bind(6, id)
      .run();
  change_state(db, id, running);
  ClaimedJob claimed;
  claimed.job = require_job(db, id);
  (with_ticket ? claimed.ticket : claimed.lease) = {claimed.job.attempts, secret};
  load_run_input(db, claimed);
  return claimed;
}

std::string spent_lease(const std::string& secret, const std::string& finish_digest) {
  io::Fingerprint f;
  f.add(secret);
  f.add(std::string_view("\0", 1));
  f.add(finish_digest);
  return f.hex();
}

bool same_secret(const std::string& a, const std::string& b) {
  // The length is no secret (32 hex digits); the content is compared whole, wherever it differs.
  if (a.size() != b.size() || b.empty()) return false;
  unsigned char differ = 0;
  for (std::size_t k = 0; k < a.size(); ++k) differ |= static_cast<unsigned char>(a[k] ^ b[k]);
  return differ == 0;
}

bool check_lease(Connection& db, std::int64_t id, const Lease& lease, std::optional<int> iteration,
                 const std::string& row) {
  Statement q = db.prepare("SELECT state, attempts, lease_secret, iteration, finish_digest FROM jobs WHERE id = ?");
  q.bind(1, id);
  if (!q.step()) throw JobNotFound(id);
  const JobState state = parse_job_state(q.text(0)).value_or(JobState::failed);
  const auto attempts = static_cast<int>(q.integer(1));
  const std::optional<std::string> secret = q.optional_text(2);
  const auto committed = static_cast<int>(q.integer(3));
  const std::optional<std::string> spent = q.optional_text(4);
  const std::string job = "job " + std::to_string(id);
  // The finish spent the lease; only the same finish again (a retry whose answer was lost) is
  // recognized, and changes nothing.
  if (!iteration && is_finished(state) && lease.attempt == attempts && spent &&
      same_secret(spent_lease(lease.secret, row), *spent)) {
    return false;
  }
  if (lease.attempt != attempts || !secret || !same_secret(lease.secret, *secret)) {
    throw LeaseConflict(job + ": the lease of attempt " + std::to_string(lease.attempt) +
                        " is no longer valid (the job is " + to_string(state) + ", attempt " +
                        std::to_string(attempts) + (is_finished(state) ? "; a finish spent its lease" : "") +
                        "); this run must stop");
  }
  if (!iteration) {
    if (accepts(state, JobAction::finish)) return true;
    throw LeaseConflict(job + " is " + to_string(state) + "; attempt " + std::to_string(attempts) + " cannot finish it");
  }
  if (!accepts(state, JobAction::iteration)) {
    throw LeaseConflict(job + " is " + to_string(state) + "; attempt " + std::to_string(attempts) +
                        " cannot record iteration " + std::to_string(*iteration));
  }
  if (*iteration == committed + 1) return true;
  if (*iteration <= committed) {
    Statement old = db.prepare("SELECT row FROM iterations WHERE job_id = ? AND iteration = ?");
    old.bind(1, id).bind(2, *iteration);
    if (old.step() && old.text(0) == row) return false;
  }
  throw LeaseConflict(job + ": iteration " + std::to_string(*iteration) + " does not follow the last committed one (" +
                      std::to_string(committed) + ")");
}

void interrupt(Connection& db, std::int64_t id, const std::string& what, int max_interruptions, bool counted) {
  db.prepare(
        "UPDATE jobs SET interruptions = interruptions + ?, lease_owner = NULL, lease_secret = NULL,"
        " lease_ticket = NULL WHERE id = ?")
      .bind(1, counted ? 1 : 0)
      .bind(2, id)
      .run();
  const JobRecord job = require_job(db, id);
  const JobState next = *next_state(id, job.state, JobAction::interrupt,
                                    {.cancel_requested = job.cancel_requested,
                                     .counted = counted,
                                     .interruptions = job.interruptions,
                                     .max_interruptions = max_interruptions});
  switch (next) {
    case JobState::cancelled:
      // The cancel was acknowledged (202) and committed: honour it rather than resume the job. Its
      // restart state stays, so it can still be resumed by hand.
      cancel_revoked(db, job, next, what);
      break;
    case JobState::failed:
      change_state(db, id, next, std::nullopt,
                   what + "; interrupted " + std::to_string(job.interruptions) +
                       " times, it is not resumed again automatically (resume it by hand to try once more)");
      break;
    default:
      change_state(db, id, next, what + "; resumes from iteration " + std::to_string(job.iteration));
  }
}

}  // namespace detail

// Remote workers and the Slurm executor.

Lease JobStore::redeem_ticket(std::int64_t id, const Lease& ticket, const std::string& worker) {
  require_writable();
  auto db = pool_->lease();
  WriteTransaction tx(*db);
  Statement q = db->prepare("SELECT state, attempts, lease_ticket FROM jobs WHERE id = ?");
  q.bind(1, id);
  if (!q.step()) throw JobNotFound(id);
  const JobState state = parse_job_state(q.text(0)).value_or(JobState::failed);
  const auto attempts = static_cast<int>(q.integer(1));
  const std::optional<std::string> issued = q.optional_text(2);
  if (state != JobState::running || attempts != ticket.attempt || !issued || !same_secret(ticket.secret, *issued)) {
    throw LeaseConflict("job " + std::to_string(id) + ": no run of it holds this ticket (attempt " +
                        std::to_string(ticket.attempt) + "; the job is " + to_string(state) + ", attempt " +
                        std::to_string(attempts) + "). A lease is granted once, to the worker the service "
                        "submitted to Slurm for the run; this run must stop");
  }
  const Lease lease{attempts, new_lease_secret()};
  db->prepare("UPDATE jobs SET lease_secret = ?, lease_ticket = NULL, heartbeat_at = ? WHERE id = ?")
      .bind(1, lease.secret)
      .bind(2, utc_now())
      .bind(3, id)
      .run();
  db->prepare("UPDATE jobs SET lease_owner = COALESCE(lease_owner, ?) WHERE id = ?").bind(1, worker).bind(2, id).run();
  tx.commit();
  return lease;
}

ClaimedJob JobStore::work(std::int64_t id, const Lease& lease) {
  auto db = pool_->lease();
  // A read that must agree with the lease check: one snapshot.
  WriteTransaction tx(*db);
  const JobRecord job = require_job(*db, id);
  check_lease(*db, id, lease, job.iteration + 1, {});  // refuses a stale lease, or a job not running
  ClaimedJob claimed;
  claimed.job = job;
  claimed.lease = lease;
  load_run_input(*db, claimed);
  tx.commit();
  return claimed;
}

bool JobStore::set_slurm_job(std::int64_t id, int attempt, const std::string& slurm_job_id,
                             const std::string& slurm_state) {
  require_writable();
  auto db = pool_->lease();
  WriteTransaction tx(*db);
  db->prepare(
        "UPDATE jobs SET slurm_job_id = ?, slurm_state = ?, lease_owner = ?, updated_at = ?"
        " WHERE id = ? AND attempts = ? AND state = 'running'")
      .bind(1, slurm_job_id)
      .bind(2, slurm_state)
      .bind(3, "slurm job " + slurm_job_id)
      .bind(4, utc_now())
      .bind(5, id)
      .bind(6, attempt)
      .run();
  const bool held = db->changes() == 1;
  tx.commit();
  return held;
}

std::vector<SlurmRun> JobStore::slurm_runs() {
  auto db = pool_->lease();
  Statement q = db->prepare(
      "SELECT id, attempts, slurm_job_id, COALESCE(slurm_state, ''), cancel_requested, updated_at FROM jobs"
      " WHERE state = 'running' AND slurm_job_id IS NOT NULL ORDER BY id");
  std::vector<SlurmRun> runs;
  while (q.step()) {
    runs.push_back({q.integer(0), static_cast<int>(q.integer(1)), q.text(2), q.text(3), q.integer(4) != 0, q.text(5)});
  }
  return runs;
}

void JobStore::set_slurm_state(std::int64_t id, int attempt, const std::string& slurm_state) {
  require_writable();
  auto db = pool_->lease();
  db->prepare("UPDATE jobs SET slurm_state = ? WHERE id = ? AND attempts = ? AND slurm_job_id IS NOT NULL")
      .bind(1, slurm_state)
      .bind(2, id)
      .bind(3, attempt)
      .run();
}

void JobStore::slurm_run_ended(std::int64_t id, int attempt, const std::string& slurm_state) {
  require_writable();
  auto db = pool_->lease();
  WriteTransaction tx(*db);
  const JobRecord job = require_job(*db, id);
  if (!accepts(job.state, JobAction::interrupt) || job.attempts != attempt || !job.slurm_job_id) return;
  db->prepare("UPDATE jobs SET slurm_state = ? WHERE id = ?").bind(1, slurm_state).bind(2, id).run();
  const std::string what = "Slurm job " + *job.slurm_job_id + " ended (" + slurm_state + ") before its worker finished";
  interrupt(*db, id, what, max_interruptions_);  // a requested cancel ends cancelled
  tx.commit();
}

void JobStore::interrupt_run(std::int64_t id, int attempt, const std::string& what) {
  require_writable();
  auto db = pool_->lease();
  WriteTransaction tx(*db);
  const JobRecord job = require_job(*db, id);
  if (!accepts(job.state, JobAction::interrupt) || job.attempts != attempt) return;  // another run holds it
  interrupt(*db, id, what, max_interruptions_);
  tx.commit();
}

void JobStore::slurm_run_cancelled(std::int64_t id, int attempt, const std::string& why) {
  require_writable();
  auto db = pool_->lease();
  WriteTransaction tx(*db);
  const JobRecord job = require_job(*db, id);
  if (!accepts(job.state, JobAction::revoke) || job.attempts != attempt) return;  // another run holds it
  db->prepare("UPDATE jobs SET slurm_state = 'CANCELLED' WHERE id = ?").bind(1, id).run();
  cancel_revoked(*db, job, *next_state(id, job.state, JobAction::revoke), why);
  tx.commit();
}

}  // namespace saasgaps::service
