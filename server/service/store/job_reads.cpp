/// JobStore, what it answers without writing: a job, a page of jobs, their history rows, model,
/// result (whole or in pieces) and events, and the counts the probes and metrics report.
#include "service/store/job_store.hpp"

#include <sys/stat.h>

#include "service/store/job_rows.hpp"
#include "service/store/job_store_detail.hpp"
#include "service/store/stored_result.hpp"

namespace saasgaps::service {

using namespace detail;

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

std::unique_ptr<JobStore::StoredResult> JobStore::open_result(std::int64_t id) {
  if (pool_->mode() == OpenMode::exclusive) {
    std::optional<std::string> text = result(id);
    return text ? text_result(std::move(*text)) : nullptr;
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
  return blob_result(std::move(connection), id);
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

bool JobStore::cancel_requested(std::int64_t id) {
  auto db = pool_->lease();
  Statement q = db->prepare("SELECT cancel_requested FROM jobs WHERE id = ?");
  q.bind(1, id);
  return q.step() && q.integer(0) != 0;
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

}  // namespace saasgaps::service
