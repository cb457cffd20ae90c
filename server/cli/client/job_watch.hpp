#pragma once
/// `saasgaps watch ID`: follows a job's Server-Sent Events (GET /v1/jobs/ID/events) until the job
/// stops. On a terminal one progress line is rewritten in place (state, iteration, the key columns
/// of the iteration table); otherwise every event is a line of its own: a state change as
/// "job N: STATE", an iteration as a row of the progress table (cli/common/progress_table.hpp). The last
/// line says how the job ended.

#include <cstdint>
#include <string>

#include "cli/common/http_client.hpp"

namespace saasgaps::cli {

/// The exit code a job's state stands for, as `solve`'s: 0 converged; 3 not_converged, cancelled
/// or interrupted (the job can be resumed); 1 failed; -1 a state that has not ended (queued, running).
int exit_code_of_job_state(const std::string& state);

/// Follows the job until it stops and returns exit_code_of_job_state of its final state. `wide`:
/// every column of the progress table. A broken stream is reopened (from the last event seen) a
/// few times before the command gives up (std::runtime_error).
int watch_job(ServiceClient& client, std::int64_t job, bool wide);

}  // namespace saasgaps::cli
