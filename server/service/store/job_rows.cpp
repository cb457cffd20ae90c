#include "service/store/job_rows.hpp"

#include <nlohmann/json.hpp>

#include "io/json/json_text.hpp"
#include "io/restart/read_card.hpp"

namespace saasgaps::service {

using nlohmann::json;

namespace detail {

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
  j.adaptive = q.integer(17) != 0;
  return j;
}

std::optional<JobRecord> find_job(Connection& db, std::int64_t id) {
  Statement q = db.prepare(std::string("SELECT ") + job_columns + " FROM jobs WHERE id = ?");
  q.bind(1, id);
  if (!q.step()) return std::nullopt;
  return read_job(q);
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

void add_commit_seconds(Connection& db, std::int64_t job, const std::optional<CommitTime>& commit) {
  if (!commit) return;
  db.prepare("UPDATE iterations SET row = json_set(row, '$.commit_seconds', ?) WHERE job_id = ? AND iteration = ?")
      .bind(1, commit->seconds)
      .bind(2, job)
      .bind(3, commit->iteration)
      .run();
}

}  // namespace detail
}  // namespace saasgaps::service
