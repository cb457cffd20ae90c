#pragma once
/// What service tests do with jobs, whichever executor runs them: submit, wait for an iteration,
/// read the iteration numbers, and solve the same document with `saasgaps solve` for reference.

#include <httplib.h>

#include <cstdint>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace saasgaps::testing {

/// An example model document from schemas/examples, as text.
std::string example_text(const std::string& name);

/// POST a model; returns the job id (asserting 202 and its Location).
std::int64_t submit_job(httplib::Client& client, const std::string& body);

/// Waits until the job has finished iteration k while still running (asserting it does not stop first).
void wait_for_running_iteration(httplib::Client& client, std::int64_t job, int k);

/// The iteration numbers of the job's history, in order.
std::vector<int> iteration_numbers(httplib::Client& client, std::int64_t job);

/// `saasgaps solve` of the document, in `dir`: the reference every service result must equal.
nlohmann::json solve_locally(const std::filesystem::path& dir, const std::string& body);

/// Cancels the running job after its second iteration, checks the stopped run's result, resumes it
/// with the tensile schedule [3, 1] and 60 iterations, and checks that the new schedule starts afresh
/// after the stop and the run converges. The job must be a tilted block (long_job_model.hpp).
void cancel_then_resume_with_a_new_schedule(httplib::Client& client, std::int64_t job);

}  // namespace saasgaps::testing
