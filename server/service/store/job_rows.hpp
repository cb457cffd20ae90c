#pragma once
/// A job's row in the jobs table, for every store file: the columns a JobRecord is read from, finding
/// a job, its state changes and events (each in the caller's transaction), and the commit time added
/// to a stored history row.

#include <cstdint>
#include <optional>
#include <string>

#include "service/store/job_store.hpp"
#include "service/store/sqlite.hpp"

namespace saasgaps::service {
namespace detail {

/// What read_job reads, in its order: a SELECT of these FROM jobs.
inline constexpr const char* job_columns =
    "id, state, title, created_at, started_at, finished_at, iteration, max_iterations, attempts, interruptions, "
    "cancel_requested, error, message, settings, "
    "(SELECT row FROM iterations i WHERE i.job_id = jobs.id ORDER BY iteration DESC LIMIT 1), "
    "slurm_job_id, slurm_state, EXISTS (SELECT 1 FROM adapt_inputs a WHERE a.job_id = jobs.id)";

/// The JobRecord of a row selected with job_columns.
JobRecord read_job(const Statement& q);
std::optional<JobRecord> find_job(Connection& db, std::int64_t id);
/// find_job, or JobNotFound.
JobRecord require_job(Connection& db, std::int64_t id);
/// Records an event of the job (kind "state", "iteration" or "thermal"; data JSON).
void add_event(Connection& db, std::int64_t job, const std::string& kind, const std::string& data);
/// Sets a job's state (and optional message / error) and records the state event.
void change_state(Connection& db, std::int64_t job, JobState state, const std::optional<std::string>& message = {},
                  const std::optional<std::string>& error = {});
/// Adds commit_seconds to a stored history row (the row's own commit could not hold it).
void add_commit_seconds(Connection& db, std::int64_t job, const std::optional<CommitTime>& commit);

}  // namespace detail
}  // namespace saasgaps::service
