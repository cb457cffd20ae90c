// JobStore, opening the database and keeping it writable: the integrity check and migrations at
// start, a read-only start on a full disk (every stored result still served), jobs handed on as
// interrupted when a commit fails for lack of space, and the return to writing once space is back.
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
#include <nlohmann/json.hpp>

#include "io/json/json_text.hpp"
#include "service/ops/log.hpp"
#include "service/store/job_rows.hpp"
#include "service/store/schema_migrations.hpp"

namespace saasgaps::service {

using nlohmann::json;
using namespace detail;

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

namespace {

/// Whether `bytes` can be reserved on the database's file system: a probe file beside it, allocated
/// (not sparse) and removed at once.
bool space_for(const std::string& database, std::int64_t bytes) {
  const std::string probe = database + ".space-probe";
  const int fd = ::open(probe.c_str(), O_RDWR | O_CREAT | O_TRUNC | O_CLOEXEC, 0600);
  if (fd < 0) return false;
  const bool reserved = ::posix_fallocate(fd, 0, bytes) == 0;
  ::close(fd);
  ::unlink(probe.c_str());
  return reserved;
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
  // Opened, but on a full disk: the first job would fail at its first commit. Not writable until
  // recover_writes finds space.
  if (writable() && !space_for(path_, probe_bytes)) {
    std::lock_guard lock(state_mutex_);
    write_problem_ = "the file system holding the database is full (less than " + std::to_string(probe_bytes) +
                     " bytes could be reserved); no job starts until space returns";
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
  std::lock_guard lock(state_mutex_);
  read_only_ = true;
  write_problem_ = std::string("the database cannot be written (") + why.what() + "); serving reads only";
}

bool JobStore::writable() const {
  std::lock_guard lock(state_mutex_);
  return write_problem_.empty();
}

std::string JobStore::why_not_writable() const {
  std::lock_guard lock(state_mutex_);
  return write_problem_;
}

void JobStore::require_writable() const {
  std::lock_guard lock(state_mutex_);
  if (read_only_) throw StoreUnavailable(write_problem_ + "; it becomes writable when space returns");
}

void JobStore::note_failure(const StoreError& e) {
  if (!e.no_space()) return;
  std::lock_guard lock(state_mutex_);
  if (write_problem_.empty()) {
    write_problem_ = std::string("a database write failed (") + e.what() + "); no job starts until space returns";
    log_error("store_not_writable", {{"reason", write_problem_}});
  }
}

void JobStore::hand_on(std::int64_t id, int attempt, const StoreError& why) {
  const std::string what = std::string("the database could not be written (") + why.what() +
                           "); the job resumes when space returns";
  try {
    auto db = pool_->lease();
    WriteTransaction tx(*db);
    const JobRecord job = require_job(*db, id);
    if (!accepts(job.state, JobAction::interrupt) || job.attempts != attempt) return;  // another run holds it
    interrupt(*db, id, what, max_interruptions_, false);
    tx.commit();
    log_error("job_interrupted", {{"job", id}, {"attempt", attempt}, {"reason", what}});
  } catch (const StoreError& e) {
    // Not even the interruption can be written: shown from memory until it can.
    std::lock_guard lock(state_mutex_);
    handed_on_[id] = {attempt, what, false};
    log_error("job_interrupted", {{"job", id}, {"attempt", attempt}, {"reason", what}, {"recorded", false},
                                  {"store_error", e.what()}});
  }
}

void JobStore::record_handed_on() {
  std::map<std::int64_t, HandedOn> pending;
  {
    std::lock_guard lock(state_mutex_);
    pending = handed_on_;
  }
  if (pending.empty()) return;
  auto db = pool_->lease();
  WriteTransaction tx(*db);
  for (const auto& [id, run] : pending) {
    const std::optional<JobRecord> job = find_job(*db, id);
    if (job && accepts(job->state, JobAction::interrupt) && job->attempts == run.attempt) {
      interrupt(*db, id, run.what, max_interruptions_, run.counted);
    }
  }
  tx.commit();
  std::lock_guard lock(state_mutex_);
  for (const auto& entry : pending) handed_on_.erase(entry.first);
}

JobRecord& JobStore::shown(JobRecord& job) const {
  std::lock_guard lock(state_mutex_);
  const auto found = handed_on_.find(job.id);
  if (found != handed_on_.end() && job.state == JobState::running && job.attempts == found->second.attempt) {
    job.state = JobState::interrupted;
    job.message = found->second.what;
  }
  return job;
}

bool JobStore::recover_writes() {
  if (writable()) return true;
  std::lock_guard probe(probe_mutex_);
  const auto now = std::chrono::steady_clock::now();
  if (now - last_probe_ < std::chrono::seconds(1)) return false;
  last_probe_ = now;
  if (!space_for(path_, probe_bytes)) return false;
  bool read_only = false;
  {
    std::lock_guard lock(state_mutex_);
    read_only = read_only_;
  }
  try {
    if (read_only) {
      // Shared connections need the WAL's shared-memory index, which a full disk could not hold.
      pool_->reopen(OpenMode::shared);
      pool_->lease();  // opens a shared connection, or throws
    }
    record_handed_on();
  } catch (const StoreError&) {
    if (read_only) pool_->reopen(OpenMode::exclusive);
    return false;
  }
  std::lock_guard lock(state_mutex_);
  read_only_ = false;
  write_problem_.clear();
  log_info("store_writable", {{"database", path_}});
  return true;
}

JobStore::~JobStore() = default;

}  // namespace saasgaps::service
