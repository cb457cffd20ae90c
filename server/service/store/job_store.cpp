#include "service/store/job_store.hpp"

#include "service/store/job_store_detail.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <sys/statvfs.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstring>
#include <ctime>
#include <nlohmann/json.hpp>

#include "io/json/json_text.hpp"
#include "io/model/model_reader.hpp"
#include "io/restart/read_card.hpp"
#include "service/ops/log.hpp"

namespace saasgaps::service {

using nlohmann::json;

namespace detail {

extern const std::vector<const char*> migrations = {
    // 1: the first schema.
    R"sql(
    CREATE TABLE jobs (
      id INTEGER PRIMARY KEY AUTOINCREMENT,
      state TEXT NOT NULL,
      title TEXT NOT NULL,
      created_at TEXT NOT NULL,
      started_at TEXT,
      finished_at TEXT,
      updated_at TEXT NOT NULL,
      iteration INTEGER NOT NULL DEFAULT 0,
      max_iterations INTEGER NOT NULL,
      attempts INTEGER NOT NULL DEFAULT 0,
      interruptions INTEGER NOT NULL DEFAULT 0,
      cancel_requested INTEGER NOT NULL DEFAULT 0,
      settings TEXT NOT NULL DEFAULT '{}',
      lease_owner TEXT,
      heartbeat_at TEXT,
      idempotency_key TEXT UNIQUE,
      request_digest TEXT,
      error TEXT,
      message TEXT
    );
    CREATE INDEX jobs_by_state ON jobs(state, id);
    CREATE TABLE models (
      job_id INTEGER PRIMARY KEY REFERENCES jobs(id) ON DELETE CASCADE,
      document TEXT NOT NULL
    );
    CREATE TABLE iterations (
      job_id INTEGER NOT NULL REFERENCES jobs(id) ON DELETE CASCADE,
      iteration INTEGER NOT NULL,
      row TEXT NOT NULL,
      PRIMARY KEY (job_id, iteration)
    ) WITHOUT ROWID;
    CREATE TABLE states (
      job_id INTEGER NOT NULL REFERENCES jobs(id) ON DELETE CASCADE,
      iteration INTEGER NOT NULL,
      state BLOB NOT NULL,
      created_at TEXT NOT NULL,
      PRIMARY KEY (job_id, iteration)
    );
    CREATE TABLE results (
      job_id INTEGER PRIMARY KEY REFERENCES jobs(id) ON DELETE CASCADE,
      document TEXT NOT NULL
    );
    CREATE TABLE events (
      id INTEGER PRIMARY KEY AUTOINCREMENT,
      job_id INTEGER NOT NULL REFERENCES jobs(id) ON DELETE CASCADE,
      kind TEXT NOT NULL,
      data TEXT NOT NULL,
      created_at TEXT NOT NULL
    );
    CREATE INDEX events_by_job ON events(job_id, id);
    )sql",
    // 2: leases of runs (remote workers) and the Slurm job running each.
    R"sql(
    ALTER TABLE jobs ADD COLUMN lease_secret TEXT;
    ALTER TABLE jobs ADD COLUMN slurm_job_id TEXT;
    ALTER TABLE jobs ADD COLUMN slurm_state TEXT;
    )sql",
    // 3: the single-use ticket of a run handed to Slurm, and what a finish keeps of its spent lease.
    R"sql(
    ALTER TABLE jobs ADD COLUMN lease_ticket TEXT;
    ALTER TABLE jobs ADD COLUMN finish_digest TEXT;
    )sql",
    // 4: the thermal history rows of runs with `thermal` (a table of their own: their key is the
    // row's index in the run, not an iteration, and a database of older jobs simply has none).
    R"sql(
    CREATE TABLE thermal_rows (
      job_id INTEGER NOT NULL REFERENCES jobs(id) ON DELETE CASCADE,
      row_index INTEGER NOT NULL,
      row TEXT NOT NULL,
      PRIMARY KEY (job_id, row_index)
    ) WITHOUT ROWID;
    )sql",
};

constexpr const char* job_columns =
    "id, state, title, created_at, started_at, finished_at, iteration, max_iterations, attempts, interruptions, "
    "cancel_requested, error, message, settings, "
    "(SELECT row FROM iterations i WHERE i.job_id = jobs.id ORDER BY iteration DESC LIMIT 1), "
    "slurm_job_id, slurm_state";

JobRecord read_job(const Statement& q) {
  JobRecord j;
  j.id = q.integer(0);
  j.state = parse_job_state(q.text(1)).value_or(JobState::failed);
  j.title = q.text(2);
  j.created_at = q.text(3);
  j.started_at = q.optional_text(4);
  j.finished_at = q.optional_text(5);
  j.iteration = static_cast<int>(q.integer(6));
  j.max_iterations = static_cast<int>(q.integer(7));
  j.attempts = static_cast<int>(q.integer(8));
  j.interruptions = static_cast<int>(q.integer(9));
  j.cancel_requested = q.integer(10) != 0;
  j.error = q.optional_text(11);
  j.message = q.optional_text(12);
  j.settings = io::stored_read_card(q.text(13));
  j.last_row = q.optional_text(14);
  j.slurm_job_id = q.optional_text(15);
  j.slurm_state = q.optional_text(16);
  return j;
}

std::optional<JobRecord> find_job(Connection& db, std::int64_t id) {
  Statement q = db.prepare(std::string("SELECT ") + job_columns + " FROM jobs WHERE id = ?");
  q.bind(1, id);
  if (!q.step()) return std::nullopt;
  return read_job(q);
}

/// Adds commit_seconds to a stored history row (the row's own commit could not hold it).
void add_commit_seconds(Connection& db, std::int64_t job, const std::optional<CommitTime>& commit) {
  if (!commit) return;
  db.prepare("UPDATE iterations SET row = json_set(row, '$.commit_seconds', ?) WHERE job_id = ? AND iteration = ?")
      .bind(1, commit->seconds)
      .bind(2, job)
      .bind(3, commit->iteration)
      .run();
}

JobRecord require_job(Connection& db, std::int64_t id) {
  std::optional<JobRecord> job = find_job(db, id);
  if (!job) throw JobNotFound(id);
  return *job;
}

void add_event(Connection& db, std::int64_t job, const std::string& kind, const std::string& data) {
  db.prepare("INSERT INTO events (job_id, kind, data, created_at) VALUES (?, ?, ?, ?)")
      .bind(1, job)
      .bind(2, kind)
      .bind(3, data)
      .bind(4, utc_now())
      .run();
}

/// Sets a job's state (and optional message / error) and records the state event.
void change_state(Connection& db, std::int64_t job, JobState state, const std::optional<std::string>& message,
                  const std::optional<std::string>& error) {
  const std::string now = utc_now();
  db.prepare(
        "UPDATE jobs SET state = ?, updated_at = ?, message = COALESCE(?, message), error = ?,"
        " finished_at = CASE WHEN ? THEN ? ELSE finished_at END WHERE id = ?")
      .bind(1, to_string(state))
      .bind(2, now)
      .bind(3, message)
      .bind(4, error)
      .bind(5, is_finished(state) ? 1 : 0)
      .bind(6, now)
      .bind(7, job)
      .run();
  const JobRecord record = require_job(db, job);
  json data = {{"job", job}, {"state", to_string(state)}, {"iteration", record.iteration}};
  if (record.message) data["message"] = *record.message;
  if (error) data["error"] = *error;
  add_event(db, job, "state", io::json_text(data));
}

}  // namespace detail

using namespace detail;

void JobStore::reclaim_space() {
  try {
    auto db = pool_->lease();
    // Frees every page on the freelist, then folds the WAL into the file so it shrinks now.
    db->execute("PRAGMA incremental_vacuum; PRAGMA wal_checkpoint(TRUNCATE);");
  } catch (const StoreError&) {
    // The delete is committed; the space comes back at the next delete or checkpoint.
  }
}

JobStore::Submitted JobStore::submit(const std::string& model, const std::string& title, int max_iterations,
                                     const std::optional<std::string>& idempotency_key,
                                     const std::string& request_digest) {
  require_writable();
  try {
    return insert_job(model, title, max_iterations, idempotency_key, request_digest);
  } catch (const StoreError& e) {
    note_failure(e);
    throw;
  }
}

JobStore::Submitted JobStore::insert_job(const std::string& model, const std::string& title, int max_iterations,
                                         const std::optional<std::string>& idempotency_key,
                                         const std::string& request_digest) {
  auto db = pool_->lease();
  WriteTransaction tx(*db);
  if (idempotency_key) {
    Statement q = db->prepare("SELECT id, request_digest FROM jobs WHERE idempotency_key = ?");
    q.bind(1, *idempotency_key);
    if (q.step()) {
      if (q.text(1) != request_digest) {
        throw JobConflict("Idempotency-Key \"" + *idempotency_key + "\" was used for a different request (job " +
                          std::to_string(q.integer(0)) + ")");
      }
      return {require_job(*db, q.integer(0)), true};
    }
  }
  const std::string now = utc_now();
  const char* state = to_string(*find_transition(std::nullopt, JobAction::submit)->to);
  db->prepare(
        "INSERT INTO jobs (state, title, created_at, updated_at, max_iterations, idempotency_key, request_digest)"
        " VALUES (?, ?, ?, ?, ?, ?, ?)")
      .bind(1, state)
      .bind(2, title)
      .bind(3, now)
      .bind(4, now)
      .bind(5, max_iterations)
      .bind(6, idempotency_key)
      .bind(7, request_digest)
      .run();
  const std::int64_t id = db->last_insert_id();
  db->prepare("INSERT INTO models (job_id, document) VALUES (?, ?)").bind(1, id).bind(2, model).run();
  add_event(*db, id, "state", io::json_text(json{{"job", id}, {"state", state}, {"iteration", 0}}));
  JobRecord job = require_job(*db, id);
  tx.commit();
  return {job, false};
}

JobRecord JobStore::get(std::int64_t id) {
  auto db = pool_->lease();
  JobRecord job = require_job(*db, id);
  return shown(job);
}

JobStore::Page JobStore::list(std::optional<JobState> state, int page_size, std::optional<std::int64_t> before) {
  auto db = pool_->lease();
  Statement q = db->prepare(std::string("SELECT ") + job_columns +
                            " FROM jobs WHERE (?1 IS NULL OR state = ?1) AND (?2 IS NULL OR id < ?2)"
                            " ORDER BY id DESC LIMIT ?3");
  if (state) q.bind(1, to_string(*state)); else q.bind_null(1);
  q.bind(2, before);
  q.bind(3, page_size + 1);
  Page page;
  while (q.step()) {
    page.jobs.push_back(read_job(q));
    shown(page.jobs.back());
  }
  if (static_cast<int>(page.jobs.size()) > page_size) {
    page.jobs.pop_back();
    page.next_before = page.jobs.back().id;
  }
  return page;
}

std::vector<std::string> JobStore::iterations(std::int64_t id, int after) {
  return rows_after(id, "SELECT row FROM iterations WHERE job_id = ? AND iteration > ? ORDER BY iteration", after);
}

std::vector<std::string> JobStore::thermal_rows(std::int64_t id, int after) {
  return rows_after(id, "SELECT row FROM thermal_rows WHERE job_id = ? AND row_index > ? ORDER BY row_index", after);
}

std::vector<std::string> JobStore::rows_after(std::int64_t id, const char* query, int after) {
  auto db = pool_->lease();
  require_job(*db, id);
  Statement q = db->prepare(query);
  q.bind(1, id).bind(2, after);
  std::vector<std::string> rows;
  while (q.step()) rows.push_back(q.text(0));
  return rows;
}

std::string JobStore::model(std::int64_t id) {
  auto db = pool_->lease();
  Statement q = db->prepare("SELECT document FROM models WHERE job_id = ?");
  q.bind(1, id);
  if (!q.step()) throw JobNotFound(id);
  return q.text(0);
}

std::optional<std::string> JobStore::result(std::int64_t id) {
  auto db = pool_->lease();
  const JobRecord job = require_job(*db, id);
  if (job.state == JobState::running) {
    throw JobConflict("job " + std::to_string(id) + " is running; its result is written when it stops");
  }
  Statement q = db->prepare("SELECT document FROM results WHERE job_id = ?");
  q.bind(1, id);
  if (!q.step()) return std::nullopt;
  return q.text(0);
}

namespace {

/// A result's blob handle on a connection of its own (opened for the purpose: a pool lease cannot
/// outlive the call that takes it).
class BlobResult final : public JobStore::StoredResult {
 public:
  BlobResult(std::unique_ptr<Connection> connection, std::int64_t id)
      : connection_(std::move(connection)), blob_(*connection_, "results", "document", id) {}
  [[nodiscard]] std::size_t size() const override { return blob_.size(); }
  void read(std::size_t offset, char* out, std::size_t count) override { blob_.read(offset, out, count); }

 private:
  std::unique_ptr<Connection> connection_;
  BlobReader blob_;
};

/// A result read whole, for a read-only store: its one exclusive connection cannot be shared with
/// a blob handle's connection of its own.
class TextResult final : public JobStore::StoredResult {
 public:
  explicit TextResult(std::string text) : text_(std::move(text)) {}
  [[nodiscard]] std::size_t size() const override { return text_.size(); }
  void read(std::size_t offset, char* out, std::size_t count) override { text_.copy(out, count, offset); }

 private:
  std::string text_;
};

}  // namespace

std::unique_ptr<JobStore::StoredResult> JobStore::open_result(std::int64_t id) {
  if (pool_->mode() == OpenMode::exclusive) {
    std::optional<std::string> text = result(id);
    return text ? std::make_unique<TextResult>(std::move(*text)) : nullptr;
  }
  auto connection = std::make_unique<Connection>(pool_->path());
  const JobRecord job = require_job(*connection, id);
  if (job.state == JobState::running) {
    throw JobConflict("job " + std::to_string(id) + " is running; its result is written when it stops");
  }
  // results.job_id is the rowid.
  Statement q = connection->prepare("SELECT 1 FROM results WHERE job_id = ?");
  q.bind(1, id);
  if (!q.step()) return nullptr;
  return std::make_unique<BlobResult>(std::move(connection), id);
}

std::vector<JobEvent> JobStore::events(std::int64_t id, std::int64_t after_event, int limit) {
  auto db = pool_->lease();
  require_job(*db, id);
  Statement q = db->prepare("SELECT id, kind, data FROM events WHERE job_id = ? AND id > ? ORDER BY id LIMIT ?");
  q.bind(1, id).bind(2, after_event).bind(3, limit);
  std::vector<JobEvent> events;
  while (q.step()) events.push_back({q.integer(0), q.text(1), q.text(2)});
  return events;
}

int JobStore::queue_length() {
  auto db = pool_->lease();
  Statement q = db->prepare("SELECT COUNT(*) FROM jobs WHERE state IN (" + sql_states_accepting(JobAction::claim) + ")");
  q.step();
  return static_cast<int>(q.integer(0));
}

int JobStore::running_count() {
  auto db = pool_->lease();
  Statement q = db->prepare("SELECT COUNT(*) FROM jobs WHERE state = 'running'");
  q.step();
  return static_cast<int>(q.integer(0));
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

bool JobStore::cancel_requested(std::int64_t id) {
  auto db = pool_->lease();
  Statement q = db->prepare("SELECT cancel_requested FROM jobs WHERE id = ?");
  q.bind(1, id);
  return q.step() && q.integer(0) != 0;
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
    change_state(*db, id, outcome, message, error);
    tx.commit();
  } catch (const StoreError& e) {
    note_failure(e);
    if (e.no_space() && attempt > 0) hand_on(id, attempt, e);
    throw;
  }
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

void JobStore::remove(std::int64_t id) {
  require_writable();
  {
    auto db = pool_->lease();
    WriteTransaction tx(*db);
    const JobRecord job = require_job(*db, id);
    next_state(id, job.state, JobAction::remove);
    db->prepare("DELETE FROM jobs WHERE id = ?").bind(1, id).run();
    tx.commit();
  }
  reclaim_space();
}

int JobStore::remove_finished_before(const std::string& cutoff) {
  if (!writable()) return 0;
  int removed = 0;
  {
    auto db = pool_->lease();
    WriteTransaction tx(*db);
    db->prepare("DELETE FROM jobs WHERE state IN (" + sql_states_accepting(JobAction::remove) +
                ") AND finished_at IS NOT NULL AND finished_at < ?")
        .bind(1, cutoff)
        .run();
    removed = db->changes();
    tx.commit();
  }
  if (removed > 0) reclaim_space();
  return removed;
}

std::vector<std::pair<JobState, int>> JobStore::count_by_state() {
  std::vector<std::pair<JobState, int>> counts;
  for (JobState s : all_job_states) counts.emplace_back(s, 0);
  auto db = pool_->lease();
  Statement q = db->prepare("SELECT state, COUNT(*) FROM jobs GROUP BY state");
  while (q.step()) {
    const std::optional<JobState> state = parse_job_state(q.text(0));
    if (state) counts[static_cast<std::size_t>(*state)].second = static_cast<int>(q.integer(1));
  }
  return counts;
}

std::int64_t JobStore::database_bytes() const {
  std::int64_t bytes = 0;
  for (const std::string& file : {path_, path_ + "-wal"}) {
    struct stat st {};
    if (::stat(file.c_str(), &st) == 0) bytes += st.st_size;
  }
  return bytes;
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

DatabaseLock::DatabaseLock(const std::string& database_path) {
  const std::string& path = database_path;
  fd_ = ::open(path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
  if (fd_ < 0) throw StoreError("cannot open " + path + ": " + std::strerror(errno));
  if (::flock(fd_, LOCK_EX | LOCK_NB) != 0) {
    ::close(fd_);
    fd_ = -1;
    throw StoreError("the database " + database_path + " is in use by another saasgaps server");
  }
}

DatabaseLock::~DatabaseLock() {
  if (fd_ >= 0) ::close(fd_);
}

}  // namespace saasgaps::service
