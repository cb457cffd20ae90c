/// JobStore, a job's life: submitted (with its idempotency key), claimed by a run, its iterations and
/// thermal rows committed, finished, cancelled, resumed, and recovered after a dead server.
#include "service/store/job_store.hpp"

#include <nlohmann/json.hpp>

#include "io/json/json_text.hpp"
#include "io/restart/read_card.hpp"
#include "service/store/job_rows.hpp"
#include "service/store/job_store_detail.hpp"

namespace saasgaps::service {

using nlohmann::json;
using namespace detail;

JobStore::Submitted JobStore::submit(const std::string& model, const std::string& title, int max_iterations,
                                     const std::optional<std::string>& idempotency_key,
                                     const std::string& request_digest, const std::optional<std::string>& cache_key) {
  require_writable();
  try {
    return insert_job(model, title, max_iterations, idempotency_key, request_digest, cache_key);
  } catch (const StoreError& e) {
    note_failure(e);
    throw;
  }
}

std::int64_t JobStore::insert_job_row(Connection& db, const std::string& model, const std::string& title,
                                      int max_iterations, const std::optional<std::string>& idempotency_key,
                                      const std::string& request_digest, const std::optional<std::string>& cache_key) {
  const std::string now = utc_now();
  const char* state = to_string(*find_transition(std::nullopt, JobAction::submit)->to);
  db.prepare(
        "INSERT INTO jobs (state, title, created_at, updated_at, max_iterations, idempotency_key, request_digest,"
        " cache_key) VALUES (?, ?, ?, ?, ?, ?, ?, ?)")
      .bind(1, state)
      .bind(2, title)
      .bind(3, now)
      .bind(4, now)
      .bind(5, max_iterations)
      .bind(6, idempotency_key)
      .bind(7, request_digest)
      .bind(8, cache_key)
      .run();
  const std::int64_t id = db.last_insert_id();
  db.prepare("INSERT INTO models (job_id, document) VALUES (?, ?)").bind(1, id).bind(2, model).run();
  add_event(db, id, "state", io::json_text(json{{"job", id}, {"state", state}, {"iteration", 0}}));
  return id;
}

std::optional<JobRecord> JobStore::replayed_job(Connection& db, const std::optional<std::string>& idempotency_key,
                                               const std::string& request_digest) {
  if (!idempotency_key) return std::nullopt;
  Statement q = db.prepare("SELECT id, request_digest FROM jobs WHERE idempotency_key = ?");
  q.bind(1, *idempotency_key);
  if (!q.step()) return std::nullopt;
  if (q.text(1) != request_digest) {
    throw JobConflict("Idempotency-Key \"" + *idempotency_key + "\" was used for a different request (job " +
                      std::to_string(q.integer(0)) + ")");
  }
  return require_job(db, q.integer(0));
}

JobStore::Submitted JobStore::insert_job(const std::string& model, const std::string& title, int max_iterations,
                                         const std::optional<std::string>& idempotency_key,
                                         const std::string& request_digest,
                                         const std::optional<std::string>& cache_key) {
  auto db = pool_->lease();
  WriteTransaction tx(*db);
  if (std::optional<JobRecord> earlier = replayed_job(*db, idempotency_key, request_digest)) return {*earlier, true};
  const std::int64_t id = insert_job_row(*db, model, title, max_iterations, idempotency_key, request_digest, cache_key);
  JobRecord job = require_job(*db, id);
  tx.commit();
  return {job, false};
}

std::optional<ClaimedJob> JobStore::claim(const std::string& worker, bool with_ticket) {
  // A job started now would fail at its first commit: wait for recover_writes.
  if (!writable()) return std::nullopt;
  try {
    auto db = pool_->lease();
    WriteTransaction tx(*db);
    Statement next = db->prepare("SELECT id FROM jobs WHERE state IN (" + sql_states_accepting(JobAction::claim) +
                                 ") ORDER BY id LIMIT 1");
    if (!next.step()) return std::nullopt;
    ClaimedJob claimed = start_run(*db, next.integer(0), worker, with_ticket);
    tx.commit();
    return claimed;
  } catch (const StoreError& e) {
    note_failure(e);
    throw;
  }
}

void JobStore::record_iteration(std::int64_t id, int iteration, const std::string& row,
                                const std::vector<std::uint8_t>& state, const std::optional<CommitTime>& previous,
                                const Lease* lease) {
  run_write(id, [&](Connection& db, const JobRecord&) {
    if (lease && !check_lease(db, id, *lease, iteration, row)) return false;  // committed before: a retry
    write_iteration(db, id, iteration, row, state, previous);
    return true;
  });
}

void JobStore::run_write(std::int64_t id, const std::function<bool(Connection&, const JobRecord&)>& write) {
  require_writable();
  int attempt = 0;
  try {
    auto db = pool_->lease();
    WriteTransaction tx(*db);
    const JobRecord job = require_job(*db, id);
    attempt = job.attempts;
    if (write(*db, job)) tx.commit();
  } catch (const StoreError& e) {
    note_failure(e);
    if (e.no_space() && attempt > 0) hand_on(id, attempt, e);
    throw;
  }
}

void JobStore::write_iteration(Connection& db, std::int64_t id, int iteration, const std::string& row,
                               const std::vector<std::uint8_t>& state, const std::optional<CommitTime>& previous) {
  const std::string now = utc_now();
  add_commit_seconds(db, id, previous);
  // A plain INSERT: an iteration recorded twice would be a bug, and must fail loudly.
  db.prepare("INSERT INTO iterations (job_id, iteration, row) VALUES (?, ?, ?)").bind(1, id).bind(2, iteration).bind(3, row).run();
  db.prepare("INSERT INTO states (job_id, iteration, state, created_at) VALUES (?, ?, ?, ?)")
      .bind(1, id)
      .bind(2, iteration)
      .bind_blob(3, state)
      .bind(4, now)
      .run();
  // Keep the latest two states: the newest, and one to fall back on.
  db.prepare("DELETE FROM states WHERE job_id = ? AND iteration < ?").bind(1, id).bind(2, iteration - 1).run();
  // The first committed iteration after a resume has used the new schedule: from here on a restart
  // continues it rather than starting it again.
  db.prepare(
        "UPDATE jobs SET iteration = ?, heartbeat_at = ?, updated_at = ?,"
        " settings = json_set(settings, '$.restart_schedule', json('false')) WHERE id = ?")
      .bind(1, iteration)
      .bind(2, now)
      .bind(3, now)
      .bind(4, id)
      .run();
  add_event(db, id, "iteration", row);
}

void JobStore::record_thermal(std::int64_t id, int index, const std::string& row, const Lease* lease) {
  run_write(id, [&](Connection& db, const JobRecord& job) {
    // A thermal row comes before the next iteration: the lease must be one that may commit it.
    if (lease) check_lease(db, id, *lease, job.iteration + 1, row);
    Statement old = db.prepare("SELECT row FROM thermal_rows WHERE job_id = ? AND row_index = ?");
    old.bind(1, id).bind(2, index);
    // A resumed run reports its rows again: the same row changes nothing and announces nothing.
    if (old.step() && old.text(0) == row) return false;
    db.prepare("INSERT OR REPLACE INTO thermal_rows (job_id, row_index, row) VALUES (?, ?, ?)")
        .bind(1, id)
        .bind(2, index)
        .bind(3, row)
        .run();
    add_event(db, id, "thermal", row);
    return true;
  });
}

void JobStore::finish(std::int64_t id, JobState state, const std::optional<std::string>& result,
                      const std::optional<std::string>& message, const std::optional<std::string>& error,
                      const std::optional<CommitTime>& last_commit, const Lease* lease,
                      const std::string& finish_digest) {
  require_writable();
  int attempt = 0;
  try {
    auto db = pool_->lease();
    WriteTransaction tx(*db);
    const JobRecord job = require_job(*db, id);
    attempt = job.attempts;
    if (lease && !check_lease(*db, id, *lease, std::nullopt, finish_digest)) return;  // finished before: a retry
    const JobState outcome = *next_state(id, job.state, JobAction::finish, {.outcome = state});
    add_commit_seconds(*db, id, last_commit);
    if (result) {
      db->prepare("INSERT OR REPLACE INTO results (job_id, document) VALUES (?, ?)").bind(1, id).bind(2, *result).run();
    }
    // The finish spends the lease: nothing more is written under it.
    db->prepare("UPDATE jobs SET lease_owner = NULL, cancel_requested = 0, lease_secret = NULL, finish_digest = ? WHERE id = ?")
        .bind(1, lease ? std::optional<std::string>(spent_lease(lease->secret, finish_digest)) : std::nullopt)
        .bind(2, id)
        .run();
    const bool read_card_changed =
        job.settings.tensile_schedule || job.settings.max_iterations || job.settings.extrapolation_factor;
    if (outcome == JobState::converged && result && !read_card_changed) {
      // A converged job answers its model's cache key from now on (the newest one, when the key was
      // solved again with ?cache=off), unless a resume changed its READ card: then its result is
      // not its model's alone.
      db->prepare(
            "INSERT OR REPLACE INTO result_cache (cache_key, job_id, created_at)"
            " SELECT cache_key, id, ? FROM jobs WHERE id = ? AND cache_key IS NOT NULL")
          .bind(1, utc_now())
          .bind(2, id)
          .run();
    }
    change_state(*db, id, outcome, message, error);
    tx.commit();
  } catch (const StoreError& e) {
    note_failure(e);
    if (e.no_space() && attempt > 0) hand_on(id, attempt, e);
    throw;
  }
}

std::optional<std::int64_t> JobStore::cached_job(const std::string& cache_key) {
  auto db = pool_->lease();
  Statement q = db->prepare(
      "SELECT c.job_id FROM result_cache c JOIN jobs j ON j.id = c.job_id JOIN results r ON r.job_id = c.job_id"
      " WHERE c.cache_key = ? AND j.state = 'converged'");
  q.bind(1, cache_key);
  if (!q.step()) return std::nullopt;
  return q.integer(0);
}

std::int64_t JobStore::cache_entries() {
  auto db = pool_->lease();
  Statement q = db->prepare("SELECT count(*) FROM result_cache");
  q.step();
  return q.integer(0);
}

bool JobStore::finish_allowed(std::int64_t id, const Lease& lease, const std::string& finish_digest) {
  auto db = pool_->lease();
  return check_lease(*db, id, lease, std::nullopt, finish_digest);
}

JobRecord JobStore::cancel(std::int64_t id) {
  require_writable();
  auto db = pool_->lease();
  WriteTransaction tx(*db);
  const JobRecord job = require_job(*db, id);
  const JobState next = *next_state(id, job.state, JobAction::request_cancel);
  if (next == job.state) {
    // A run holds the job: it stops at its next iteration boundary.
    db->prepare("UPDATE jobs SET cancel_requested = 1, updated_at = ? WHERE id = ?").bind(1, utc_now()).bind(2, id).run();
  } else {
    change_state(*db, id, next, "cancelled before it ran again");
  }
  JobRecord updated = require_job(*db, id);
  tx.commit();
  return updated;
}

JobRecord JobStore::resume(std::int64_t id, const ResumeOptions& changes) {
  require_writable();
  auto db = pool_->lease();
  WriteTransaction tx(*db);
  const JobRecord job = require_job(*db, id);
  const JobState next = *next_state(id, job.state, JobAction::resume);
  ResumeOptions settings = job.settings;
  settings.apply(changes);
  db->prepare("UPDATE jobs SET settings = ?, max_iterations = COALESCE(?, max_iterations), interruptions = 0 WHERE id = ?")
      .bind(1, io::stored_read_card_text(settings))
      .bind(2, changes.max_iterations)
      .bind(3, id)
      .run();
  change_state(*db, id, next, "resumed from iteration " + std::to_string(job.iteration));
  JobRecord updated = require_job(*db, id);
  tx.commit();
  return updated;
}

int JobStore::recover_interrupted(bool keep_slurm_jobs) {
  const std::string what = "the server stopped while solving";
  std::vector<std::pair<std::int64_t, int>> orphans;  // job, attempt
  {
    auto db = pool_->lease();
    Statement q = db->prepare(
        "SELECT id, attempts FROM jobs WHERE state IN (" + sql_states_accepting(JobAction::interrupt) +
        ") AND NOT (? AND slurm_job_id IS NOT NULL)");
    q.bind(1, keep_slurm_jobs ? 1 : 0);
    while (q.step()) orphans.emplace_back(q.integer(0), static_cast<int>(q.integer(1)));
  }
  if (orphans.empty()) return 0;
  {
    // Shown interrupted at once; written now if the store can, else once recover_writes can.
    std::lock_guard lock(state_mutex_);
    for (const auto& [id, attempt] : orphans) handed_on_[id] = {attempt, what, true};
  }
  if (writable()) {
    try {
      record_handed_on();
    } catch (const StoreError& e) {
      if (!e.no_space()) throw;
      note_failure(e);
    }
  }
  return static_cast<int>(orphans.size());
}

}  // namespace saasgaps::service
