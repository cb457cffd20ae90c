#include "service/job_client.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <thread>

#include "service/server_process.hpp"

namespace saasgaps::testing {

using nlohmann::json;

std::string example_text(const std::string& name) {
  std::ifstream in(std::string(SAASGAPS_EXAMPLES_DIR) + "/" + name);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

std::int64_t submit_job(httplib::Client& client, const std::string& body) {
  // A new job even for a model solved before (the result cache has tests of its own).
  const httplib::Result r = client.Post("/v1/jobs?cache=off", body, "application/json");
  if (!r) throw std::runtime_error("POST /v1/jobs failed: " + httplib::to_string(r.error()));
  if (r->status != 202) throw std::runtime_error("POST /v1/jobs answered " + std::to_string(r->status) + ": " + r->body);
  const std::int64_t id = json::parse(r->body)["id"].get<std::int64_t>();
  EXPECT_EQ(r->get_header_value("Location"), "/v1/jobs/" + std::to_string(id));
  return id;
}

void wait_for_running_iteration(httplib::Client& client, std::int64_t job, int k) {
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(120);
  for (;;) {
    const json j = get_json(client, "/v1/jobs/" + std::to_string(job));
    const std::string state = j["state"];
    if (state == "running" && j["iteration"].get<int>() >= k) return;
    ASSERT_TRUE(state == "queued" || state == "running") << "the job stopped before iteration " << k << ": " << j.dump();
    ASSERT_LT(std::chrono::steady_clock::now(), deadline) << "iteration " << k << " never came";
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
}

std::vector<int> iteration_numbers(httplib::Client& client, std::int64_t job) {
  std::vector<int> numbers;
  const json rows = get_json(client, "/v1/jobs/" + std::to_string(job) + "/iterations");
  for (const json& row : rows["iterations"]) {
    numbers.push_back(row["iteration"].get<int>());
  }
  return numbers;
}

json solve_locally(const std::filesystem::path& dir, const std::string& body) {
  const std::filesystem::path model = dir / "reference-model.json", result = dir / "reference-result.json";
  std::ofstream(model) << body;
  const CommandResult run = run_command({SAASGAPS_BINARY, "solve", model.string(), "-q", "-o", result.string()});
  EXPECT_LE(run.exit_code, 3) << run.output;
  std::ifstream in(result);
  return json::parse(in);
}

void cancel_then_resume_with_a_new_schedule(httplib::Client& client, std::int64_t job) {
  const std::string path = "/v1/jobs/" + std::to_string(job);
  wait_for_running_iteration(client, job, 2);
  ASSERT_EQ(client.Post(path + "/cancel", "", "application/json")->status, 202);
  const json cancelled = wait_for_state(client, job, {"cancelled"});
  const int stopped_at = cancelled["iteration"].get<int>();
  EXPECT_GE(stopped_at, 2);
  // The stopped run's result is there to look at, and says it did not converge.
  EXPECT_EQ(get_json(client, path + "/result")["status"], "not_converged");

  const httplib::Result resumed =
      client.Post(path + "/resume", R"({"tensile_schedule": [3, 1], "max_iterations": 60})", "application/json");
  ASSERT_EQ(resumed->status, 202) << resumed->body;
  EXPECT_EQ(json::parse(resumed->body)["state"], "queued");
  const json done = wait_for_state(client, job, {"converged", "not_converged", "failed"});
  EXPECT_EQ(done["state"], "converged") << done.dump();
  EXPECT_EQ(done["max_iterations"], 60);
  const json rows = get_json(client, path + "/iterations")["iterations"];
  ASSERT_GT(static_cast<int>(rows.size()), stopped_at + 2);
  // The new schedule starts afresh after the stop, and the rows record the second attempt.
  EXPECT_EQ(rows[stopped_at]["tensile_modulus"], 3.0);
  EXPECT_EQ(rows[stopped_at + 1]["tensile_modulus"], 1.0);
  EXPECT_EQ(rows[stopped_at]["attempt"], 2);
  EXPECT_EQ(rows[stopped_at - 1]["attempt"], 1);
}

}  // namespace saasgaps::testing
