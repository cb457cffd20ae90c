#include "service/job_store.hpp"

#include "service/job_store_detail.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstring>
#include <ctime>
#include <nlohmann/json.hpp>

#include "io/json_text.hpp"
#include "io/model_reader.hpp"

namespace saasgaps::service {

using nlohmann::json;

namespace detail {

/// Schema versions, applied in order; PRAGMA user_version records how far a database has come.
const std::vector<const char*> migrations = {
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
};

constexpr const char* job_columns =
    "id, state, title, created_at, started_at, finished_at, iteration, max_iterations, attempts, interruptions, "
    "cancel_requested, error, message, settings, "
    "(SELECT row FROM iterations i WHERE i.job_id = jobs.id ORDER BY iteration DESC LIMIT 1), "
    "slurm_job_id, slurm_state";

json settings_json(const RunSettings& s) {
  json j = json::object();
  if (s.tensile_schedule) j["tensile_schedule"] = *s.tensile_schedule;
  if (s.max_iterations) j["max_iterations"] = *s.max_iterations;
  if (s.extrapolation_factor) j["extrapolation_factor"] = *s.extrapolation_factor;
  j["restart_schedule"] = s.restart_schedule;
  return j;
}

RunSettings parse_settings(const std::string& text) {
  // Written by settings_json; anything else is damage, read as "no changes" rather than an error
  // on every read of the job.
  json j;
  try {
    j = io::parse_document(text);
  } catch (const ModelError&) {
    // damage: j stays null
  }
  RunSettings s;
  if (!j.is_object()) return s;
  if (j.contains("tensile_schedule")) s.tensile_schedule = j["tensile_schedule"].get<std::vector<double>>();
  if (j.contains("max_iterations")) s.max_iterations = j["max_iterations"].get<int>();
  if (j.contains("extrapolation_factor")) s.extrapolation_factor = j["extrapolation_factor"].get<double>();
  s.restart_schedule = j.value("restart_schedule", false);
  return s;
}

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
  j.settings = parse_settings(q.text(13));
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

const char* to_string(JobState state) {
  switch (state) {
    case JobState::queued: return "queued";
    case JobState::running: return "running";
    case JobState::converged: return "converged";
    case JobState::not_converged: return "not_converged";
    case JobState::failed: return "failed";
    case JobState::cancelled: return "cancelled";
    case JobState::interrupted: return "interrupted";
  }
  return "failed";
}

std::optional<JobState> parse_job_state(std::string_view text) {
  for (JobState s : {JobState::queued, JobState::running, JobState::converged, JobState::not_converged,
                     JobState::failed, JobState::cancelled, JobState::interrupted}) {
    if (text == to_string(s)) return s;
  }
  return std::nullopt;
}

bool is_finished(JobState state) {
  return state == JobState::converged || state == JobState::not_converged || state == JobState::failed ||
         state == JobState::cancelled;
}

std::string utc_now() { return utc_text(std::chrono::system_clock::now()); }

std::string utc_text(std::chrono::system_clock::time_point now) {
  const std::time_t seconds = std::chrono::system_clock::to_time_t(now);
  const auto millis =
      std::chrono::duration_cast<std::chrono::milliseconds>(now.time_since_epoch()).count() % 1000;
  std::tm tm{};
  gmtime_r(&seconds, &tm);
  char text[96];
  std::snprintf(text, sizeof text, "%04d-%02d-%02dT%02d:%02d:%02d.%03dZ", tm.tm_year + 1900, tm.tm_mon + 1,
                tm.tm_mday, tm.tm_hour, tm.tm_min, tm.tm_sec, static_cast<int>(millis));
  return text;
}

namespace {

/// PRAGMA quick_check: every page's b-tree structure, record formats and freelist, in one pass over
/// the file (linear in its size). integrity_check also cross-checks every index against its table,
/// which costs a lookup per row; the indexes here are small and rebuilt by REINDEX, so the damage
/// that matters (pages a read would trip on) is what quick_check finds.
void check_integrity(Connection& db, const std::string& path) {
  std::vector<std::string> problems;
  try {
    Statement q = db.prepare("PRAGMA quick_check(5)");
    while (q.step()) problems.push_back(q.text(0));
  } catch (const StoreError& e) {
    if (e.no_space()) throw;
    problems = {e.what()};
  }
  if (problems.size() == 1 && problems.front() == "ok") return;
  std::string text;
  for (const std::string& p : problems) text += (text.empty() ? "" : "; ") + p;
  throw StoreError("the database " + path + " is damaged (" + text +
                       "); refusing to serve it. Restore a backup, or copy out what is readable with: "
                       "sqlite3 " + path + " .recover | sqlite3 recovered.db",
                   SQLITE_CORRUPT);
}

std::int64_t schema_version(Connection& db) {
  Statement q = db.prepare("PRAGMA user_version");
  q.step();
  return q.integer(0);
}

}  // namespace

JobStore::JobStore(std::string path, int max_interruptions)
    : path_(std::move(path)), max_interruptions_(max_interruptions) {
  try {
    open_writable();
  } catch (const StoreError& e) {
    if (!e.no_space()) throw;
    open_read_only(e);
  }
}

void JobStore::open_writable() {
  pool_ = std::make_unique<Pool>(path_, OpenMode::shared);
  auto db = pool_->lease();
  check_integrity(*db, path_);
  const auto version = static_cast<std::size_t>(schema_version(*db));
  if (version > migrations.size()) {
    throw StoreError("the database has schema version " + std::to_string(version) +
                     ", newer than this server knows (" + std::to_string(migrations.size()) + ")");
  }
  // A new file gets incremental auto-vacuum before its first table, so deletes can shrink it.
  if (version == 0) db->execute("PRAGMA auto_vacuum = INCREMENTAL");
  if (version < migrations.size()) {
    WriteTransaction tx(*db);
    for (std::size_t v = version; v < migrations.size(); ++v) db->execute(migrations[v]);
    db->execute("PRAGMA user_version = " + std::to_string(migrations.size()));
    tx.commit();
  }
  // A file made before that setting changes its mode once, by rewriting it (VACUUM). The mode is
  // recorded in the file's header, so this needs no schema version of its own.
  std::int64_t mode = 0;
  {
    Statement q = db->prepare("PRAGMA auto_vacuum");
    q.step();
    mode = q.integer(0);
  }
  if (mode != 2) db->execute("PRAGMA auto_vacuum = INCREMENTAL; VACUUM;");
}

void JobStore::open_read_only(const StoreError& why) {
  pool_.reset();
  pool_ = std::make_unique<Pool>(path_, OpenMode::exclusive);
  auto db = pool_->lease();
  check_integrity(*db, path_);
  if (static_cast<std::size_t>(schema_version(*db)) != migrations.size()) {
    throw StoreError("the database " + path_ + " needs a schema migration but cannot be written: " + why.what(),
                     why.code());
  }
  read_only_reason_ = std::string("the database cannot be written (") + why.what() + "); serving reads only";
}

void JobStore::require_writable() const {
  if (!writable()) throw StoreUnavailable(read_only_reason_ + "; free space and restart the server");
}

void JobStore::reclaim_space() {
  try {
    auto db = pool_->lease();
    // Frees every page on the freelist, then folds the WAL into the file so it shrinks now.
    db->execute("PRAGMA incremental_vacuum; PRAGMA wal_checkpoint(TRUNCATE);");
  } catch (const StoreError&) {
    // The delete is committed; the space comes back at the next delete or checkpoint.
  }
}

JobStore::~JobStore() = default;

JobStore::Submitted JobStore::submit(const std::string& model, const std::string& title, int max_iterations,
                                     const std::optional<std::string>& idempotency_key,
                                     const std::string& request_digest) {
  require_writable();
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
  db->prepare(
        "INSERT INTO jobs (state, title, created_at, updated_at, max_iterations, idempotency_key, request_digest)"
        " VALUES ('queued', ?, ?, ?, ?, ?, ?)")
      .bind(1, title)
      .bind(2, now)
      .bind(3, now)
      .bind(4, max_iterations)
      .bind(5, idempotency_key)
      .bind(6, request_digest)
      .run();
  const std::int64_t id = db->last_insert_id();
  db->prepare("INSERT INTO models (job_id, document) VALUES (?, ?)").bind(1, id).bind(2, model).run();
  add_event(*db, id, "state", io::json_text(json{{"job", id}, {"state", "queued"}, {"iteration", 0}}));
  JobRecord job = require_job(*db, id);
  tx.commit();
  return {job, false};
}

JobRecord JobStore::get(std::int64_t id) {
  auto db = pool_->lease();
  return require_job(*db, id);
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
  while (q.step()) page.jobs.push_back(read_job(q));
  if (static_cast<int>(page.jobs.size()) > page_size) {
    page.jobs.pop_back();
    page.next_before = page.jobs.back().id;
  }
  return page;
}

std::vector<std::string> JobStore::iterations(std::int64_t id, int after) {
  auto db = pool_->lease();
  require_job(*db, id);
  Statement q = db->prepare("SELECT row FROM iterations WHERE job_id = ? AND iteration > ? ORDER BY iteration");
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
  Statement q = db->prepare("SELECT COUNT(*) FROM jobs WHERE state IN ('queued', 'interrupted')");
  q.step();
  return static_cast<int>(q.integer(0));
}

int JobStore::running_count() {
  auto db = pool_->lease();
  Statement q = db->prepare("SELECT COUNT(*) FROM jobs WHERE state = 'running'");
  q.step();
  return static_cast<int>(q.integer(0));
}

std::optional<ClaimedJob> JobStore::claim(const std::string& worker) {
  if (!writable()) return std::nullopt;
  auto db = pool_->lease();
  WriteTransaction tx(*db);
  Statement next = db->prepare("SELECT id FROM jobs WHERE state IN ('queued', 'interrupted') ORDER BY id LIMIT 1");
  if (!next.step()) return std::nullopt;
  ClaimedJob claimed = start_run(*db, next.integer(0), worker);
  tx.commit();
  return claimed;
}

void JobStore::record_iteration(std::int64_t id, int iteration, const std::string& row,
                                const std::vector<std::uint8_t>& state, const std::optional<CommitTime>& previous,
                                const Lease* lease) {
  require_writable();
  auto db = pool_->lease();
  WriteTransaction tx(*db);
  if (lease && !check_lease(*db, id, *lease, iteration, row)) return;  // committed before: a retry
  const std::string now = utc_now();
  add_commit_seconds(*db, id, previous);
  // A plain INSERT: an iteration recorded twice would be a bug, and must fail loudly.
  db->prepare("INSERT INTO iterations (job_id, iteration, row) VALUES (?, ?, ?)").bind(1, id).bind(2, iteration).bind(3, row).run();
  db->prepare("INSERT INTO states (job_id, iteration, state, created_at) VALUES (?, ?, ?, ?)")
      .bind(1, id)
      .bind(2, iteration)
      .bind_blob(3, state)
      .bind(4, now)
      .run();
  // Keep the latest two states: the newest, and one to fall back on.
  db->prepare("DELETE FROM states WHERE job_id = ? AND iteration < ?").bind(1, id).bind(2, iteration - 1).run();
  // The first committed iteration after a resume has used the new schedule: from here on a restart
  // continues it rather than starting it again.
  db->prepare(
        "UPDATE jobs SET iteration = ?, heartbeat_at = ?, updated_at = ?,"
        " settings = json_set(settings, '$.restart_schedule', json('false')) WHERE id = ?")
      .bind(1, iteration)
      .bind(2, now)
      .bind(3, now)
      .bind(4, id)
      .run();
  add_event(*db, id, "iteration", row);
  tx.commit();
}

bool JobStore::cancel_requested(std::int64_t id) {
  auto db = pool_->lease();
  Statement q = db->prepare("SELECT cancel_requested FROM jobs WHERE id = ?");
  q.bind(1, id);
  return q.step() && q.integer(0) != 0;
}

void JobStore::finish(std::int64_t id, JobState state, const std::optional<std::string>& result,
                      const std::optional<std::string>& message, const std::optional<std::string>& error,
                      const std::optional<CommitTime>& last_commit, const Lease* lease) {
  require_writable();
  auto db = pool_->lease();
  WriteTransaction tx(*db);
  if (lease && !check_lease(*db, id, *lease, std::nullopt, {})) return;  // finished before: a retry
  add_commit_seconds(*db, id, last_commit);
  if (result) {
    db->prepare("INSERT OR REPLACE INTO results (job_id, document) VALUES (?, ?)").bind(1, id).bind(2, *result).run();
  }
  db->prepare("UPDATE jobs SET lease_owner = NULL, cancel_requested = 0 WHERE id = ?").bind(1, id).run();
  change_state(*db, id, state, message, error);
  tx.commit();
}

JobRecord JobStore::cancel(std::int64_t id) {
  require_writable();
  auto db = pool_->lease();
  WriteTransaction tx(*db);
  const JobRecord job = require_job(*db, id);
  switch (job.state) {
    case JobState::queued:
    case JobState::interrupted:
      change_state(*db, id, JobState::cancelled, "cancelled before it ran again");
      break;
    case JobState::running:
      db->prepare("UPDATE jobs SET cancel_requested = 1, updated_at = ? WHERE id = ?").bind(1, utc_now()).bind(2, id).run();
      break;
    default:
      throw JobConflict("job " + std::to_string(id) + " is " + to_string(job.state) + "; only queued, running or "
                        "interrupted jobs can be cancelled");
  }
  JobRecord updated = require_job(*db, id);
  tx.commit();
  return updated;
}

JobRecord JobStore::resume(std::int64_t id, const RunSettings& changes) {
  require_writable();
  auto db = pool_->lease();
  WriteTransaction tx(*db);
  const JobRecord job = require_job(*db, id);
  if (job.state == JobState::queued || job.state == JobState::running || job.state == JobState::converged) {
    throw JobConflict("job " + std::to_string(id) + " is " + to_string(job.state) + "; only cancelled, "
                      "not_converged, interrupted or failed jobs can be resumed");
  }
  RunSettings settings = job.settings;
  if (changes.tensile_schedule) {
    settings.tensile_schedule = changes.tensile_schedule;
    settings.restart_schedule = true;
  }
  if (changes.max_iterations) settings.max_iterations = changes.max_iterations;
  if (changes.extrapolation_factor) settings.extrapolation_factor = changes.extrapolation_factor;
  db->prepare("UPDATE jobs SET settings = ?, max_iterations = COALESCE(?, max_iterations), interruptions = 0 WHERE id = ?")
      .bind(1, io::json_text(settings_json(settings)))
      .bind(2, changes.max_iterations)
      .bind(3, id)
      .run();
  change_state(*db, id, JobState::queued, "resumed from iteration " + std::to_string(job.iteration));
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
    if (!is_finished(job.state)) {
      throw JobConflict("job " + std::to_string(id) + " is " + to_string(job.state) + "; cancel it before deleting");
    }
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
    db->prepare(
          "DELETE FROM jobs WHERE state IN ('converged', 'not_converged', 'failed', 'cancelled')"
          " AND finished_at IS NOT NULL AND finished_at < ?")
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
  for (JobState s : {JobState::queued, JobState::running, JobState::converged, JobState::not_converged,
                     JobState::failed, JobState::cancelled, JobState::interrupted}) {
    counts.emplace_back(s, 0);
  }
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
  if (!writable()) return 0;
  auto db = pool_->lease();
  WriteTransaction tx(*db);
  std::vector<std::int64_t> orphans;
  Statement q = db->prepare("SELECT id FROM jobs WHERE state = 'running' AND NOT (? AND slurm_job_id IS NOT NULL)");
  q.bind(1, keep_slurm_jobs ? 1 : 0);
  while (q.step()) orphans.push_back(q.integer(0));
  for (std::int64_t id : orphans) interrupt(*db, id, "the server stopped while solving", max_interruptions_);
  tx.commit();
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
