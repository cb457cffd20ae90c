// Jobs through a real one-node Slurm cluster (tests/slurm/slurm_cluster.sh): `saasgaps serve
// --executor slurm` submits each job as an sbatch of `saasgaps worker`, which reports every
// iteration over HTTP. The results must equal `saasgaps solve` to the last digit, whatever happens
// to the Slurm job or to the service on the way.
#include <gtest/gtest.h>
#include <sqlite3.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <thread>

#include "service/job_client.hpp"
#include "service/long_job_model.hpp"
#include "service/server_process.hpp"

namespace saasgaps::testing {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

constexpr const char* token = "slurm-test-token";

/// Reads the fixture's environment file: SLURM_CONF when the cluster runs, UNAVAILABLE otherwise.
std::map<std::string, std::string> cluster_environment() {
  std::map<std::string, std::string> values;
  std::ifstream in(SAASGAPS_SLURM_ENV);
  for (std::string line; std::getline(in, line);) {
    const auto eq = line.find('=');
    if (eq != std::string::npos) values[line.substr(0, eq)] = line.substr(eq + 1);
  }
  return values;
}

/// `saasgaps solve` of a document, once per document for the whole test program.
json reference_of(const fs::path& dir, const std::string& body) {
  static std::map<std::string, json> solved;
  const auto found = solved.find(body);
  if (found != solved.end()) return found->second;
  return solved[body] = solve_locally(dir, body);
}

class Slurm : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto env = cluster_environment();
    if (env.count("UNAVAILABLE")) GTEST_SKIP() << "Slurm cannot start on this machine: " << env.at("UNAVAILABLE");
    ASSERT_TRUE(env.count("SLURM_CONF")) << "no cluster: run through ctest (fixture slurm_cluster_start), or "
                                            "tests/slurm/slurm_cluster.sh start " << SAASGAPS_SLURM_ENV;
    // The service runs sbatch, squeue and scancel against the test cluster.
    ::setenv("SLURM_CONF", env.at("SLURM_CONF").c_str(), 1);
    dir_ = fs::temp_directory_path() / ("saasgaps-slurm-" + std::to_string(::getpid()) + "-" +
                                        ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
    std::ofstream(dir_ / "token") << token << "\n";
  }
  void TearDown() override {
    // No worker of this test may outlive it and take the next test's CPUs: the cluster is ours.
    if (!dir_.empty()) run_command({"scancel", "--partition=debug"});
    // Logs of the workers stay when a test failed, to see what happened.
    if (!HasFailure()) fs::remove_all(dir_);
  }

  [[nodiscard]] std::vector<std::string> serve_arguments(const std::vector<std::string>& more = {}) const {
    std::vector<std::string> a = {"--executor",     "slurm", "--token-file", (dir_ / "token").string(),
                                  "--slurm-log-dir", dir_.string(), "--slurm-poll", "0.2"};
    a.insert(a.end(), more.begin(), more.end());
    return a;
  }

  static httplib::Client client_of(const ServerProcess& server) {
    httplib::Client c = server.client();
    c.set_bearer_token_auth(token);
    return c;
  }

  [[nodiscard]] fs::path database() const { return dir_ / "jobs.db"; }

  /// The job's Slurm job id as the job resource shows it.
  static std::string slurm_job_of(httplib::Client& client, std::int64_t job) {
    const json j = get_json(client, "/v1/jobs/" + std::to_string(job));
    return j["slurm"].is_object() ? j["slurm"]["job_id"].get<std::string>() : "";
  }

  /// The lease of the job's current run, read from the database (what its worker holds).
  [[nodiscard]] std::string lease_of(std::int64_t job) const {
    sqlite3* db = nullptr;
    sqlite3_open_v2(database().c_str(), &db, SQLITE_OPEN_READONLY, nullptr);
    sqlite3_stmt* q = nullptr;
    sqlite3_prepare_v2(db, "SELECT attempts, lease_secret FROM jobs WHERE id = ?", -1, &q, nullptr);
    sqlite3_bind_int64(q, 1, job);
    std::string lease;
    if (sqlite3_step(q) == SQLITE_ROW && sqlite3_column_text(q, 1)) {
      lease = std::to_string(sqlite3_column_int(q, 0)) + ":" + reinterpret_cast<const char*>(sqlite3_column_text(q, 1));
    }
    sqlite3_finalize(q);
    sqlite3_close(db);
    return lease;
  }

  /// The job converged through Slurm: each iteration once and in order, the same numbers as `solve`.
  void expect_identical_to_solve(httplib::Client& client, std::int64_t job, const json& reference) {
    const json done = wait_for_state(client, job, {"converged", "not_converged", "failed", "cancelled"});
    ASSERT_EQ(done["state"], "converged") << done.dump();
    const std::vector<int> numbers = iteration_numbers(client, job);
    ASSERT_EQ(static_cast<int>(numbers.size()), reference["iterations"].get<int>());
    for (std::size_t k = 0; k < numbers.size(); ++k) EXPECT_EQ(numbers[k], static_cast<int>(k) + 1);
    EXPECT_EQ(result_numbers(get_json(client, "/v1/jobs/" + std::to_string(job) + "/result")), result_numbers(reference));
  }

  fs::path dir_;
};

TEST_F(Slurm, ReportProblemsAndALargeModelGiveTheSameResultAsSolve) {
  ServerProcess server(database(), serve_arguments());
  httplib::Client client = client_of(server);
  const std::vector<std::string> bodies = {example_text("report-problem1.json"), example_text("report-problem2.json"),
                                           tilted_block_document(160).dump()};
  std::vector<std::int64_t> jobs;
  for (const std::string& body : bodies) jobs.push_back(submit_job(client, body));
  for (std::size_t k = 0; k < jobs.size(); ++k) {
    expect_identical_to_solve(client, jobs[k], reference_of(dir_, bodies[k]));
    const json j = get_json(client, "/v1/jobs/" + std::to_string(jobs[k]));
    EXPECT_EQ(j["attempts"], 1);
    ASSERT_TRUE(j["slurm"].is_object()) << j.dump();
    EXPECT_FALSE(j["slurm"]["job_id"].get<std::string>().empty());
  }
  // The monitor records how each Slurm job ended.
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(20);
  while (get_json(client, "/v1/jobs/" + std::to_string(jobs.back()))["slurm"]["state"] != "COMPLETED" &&
         std::chrono::steady_clock::now() < deadline) {
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
  }
  EXPECT_EQ(get_json(client, "/v1/jobs/" + std::to_string(jobs.back()))["slurm"]["state"], "COMPLETED");
}

TEST_F(Slurm, ScancelMidRunResumesAndTheStaleWorkerIsRefused) {
  const std::string body = tilted_block_document(160).dump();
  const json reference = reference_of(dir_, body);
  ServerProcess server(database(), serve_arguments());
  httplib::Client client = client_of(server);
  const std::int64_t job = submit_job(client, body);
  wait_for_running_iteration(client, job, 3);
  const std::string first_slurm_job = slurm_job_of(client, job);
  const std::string stale_lease = lease_of(job);
  ASSERT_FALSE(stale_lease.empty());
  // A lost node, as far as the service can tell: the Slurm job ends without the worker finishing.
  ASSERT_EQ(run_command({"scancel", first_slurm_job}).exit_code, 0);
  expect_identical_to_solve(client, job, reference);
  const json done = get_json(client, "/v1/jobs/" + std::to_string(job));
  EXPECT_EQ(done["attempts"], 2);
  EXPECT_EQ(done["interruptions"], 1);
  EXPECT_NE(slurm_job_of(client, job), first_slurm_job);

  // The first run's lease is stale: every write it could still attempt is refused and changes nothing.
  const std::string path = "/v1/jobs/" + std::to_string(job);
  const httplib::Headers stale = {{"Saasgaps-Lease", stale_lease}};
  const std::vector<std::uint8_t> late_iteration =
      json::to_cbor(json{{"iteration", 4}, {"row", R"({"iteration":4})"}, {"state", json::binary({1, 2, 3})}});
  const auto late = client.Post(path + "/work/iterations", stale, std::string(late_iteration.begin(), late_iteration.end()),
                                "application/cbor");
  ASSERT_TRUE(late);
  EXPECT_EQ(late->status, 409) << late->body;
  const std::vector<std::uint8_t> late_finish =
      json::to_cbor(json{{"state", "failed"}, {"error", "late"}, {"model_digest", "0000000000000000"}});
  EXPECT_EQ(client.Post(path + "/work/finish", stale, std::string(late_finish.begin(), late_finish.end()),
                        "application/cbor")->status, 409);
  EXPECT_EQ(client.Get(path + "/work", stale)->status, 409);
  // A wrong secret for the current attempt is refused too.
  EXPECT_EQ(client.Get(path + "/work", {{"Saasgaps-Lease", "2:not-the-secret"}})->status, 409);
  // A worker started with the stale lease stops at once with its own exit code.
  const CommandResult worker = run_command({SAASGAPS_BINARY, "worker", "--server", "http://127.0.0.1:" + std::to_string(server.port()),
                                            "--job", std::to_string(job), "--lease", stale_lease, "--token-file",
                                            (dir_ / "token").string()});
  EXPECT_EQ(worker.exit_code, 5) << worker.output;
  EXPECT_NE(worker.output.find("no longer valid"), std::string::npos) << worker.output;
  expect_identical_to_solve(client, job, reference);
}

TEST_F(Slurm, KillNineOfTheServiceMidRunKeepsTheSlurmJobAndItsLease) {
  const std::string body = tilted_block_document(160).dump();
  const json reference = reference_of(dir_, body);
  const std::vector<std::string> arguments = serve_arguments({"--port", std::to_string(free_port())});
  std::int64_t job = 0;
  std::string slurm_job;
  {
    ServerProcess server(database(), arguments);
    httplib::Client client = client_of(server);
    job = submit_job(client, body);
    wait_for_running_iteration(client, job, 3);
    slurm_job = slurm_job_of(client, job);
    server.kill_hard();
  }
  // The worker retries while the service is down; the restarted service finds its Slurm job alive.
  std::this_thread::sleep_for(std::chrono::milliseconds(500));
  ServerProcess restarted(database(), arguments);
  httplib::Client client = client_of(restarted);
  expect_identical_to_solve(client, job, reference);
  const json done = get_json(client, "/v1/jobs/" + std::to_string(job));
  EXPECT_EQ(done["attempts"], 1) << done.dump();
  EXPECT_EQ(done["interruptions"], 0);
  EXPECT_EQ(slurm_job_of(client, job), slurm_job);
}

TEST_F(Slurm, ASlurmJobThatEndedWhileTheServiceWasDownIsResubmitted) {
  const std::string body = tilted_block_document(120).dump();
  const json reference = reference_of(dir_, body);
  std::int64_t job = 0;
  {
    ServerProcess server(database(), serve_arguments());
    httplib::Client client = client_of(server);
    job = submit_job(client, body);
    wait_for_running_iteration(client, job, 2);
    const std::string slurm_job = slurm_job_of(client, job);
    server.kill_hard();
    ASSERT_EQ(run_command({"scancel", slurm_job}).exit_code, 0);
  }
  ServerProcess restarted(database(), serve_arguments());
  httplib::Client client = client_of(restarted);
  expect_identical_to_solve(client, job, reference);
  const json done = get_json(client, "/v1/jobs/" + std::to_string(job));
  EXPECT_EQ(done["attempts"], 2) << done.dump();
  EXPECT_EQ(done["interruptions"], 1);
}

TEST_F(Slurm, CancelThenResumeWithANewSchedule) {
  ServerProcess server(database(), serve_arguments());
  httplib::Client client = client_of(server);
  // The worker stops at an iteration boundary and reports; the resume is a new Slurm job.
  cancel_then_resume_with_a_new_schedule(client, submit_job(client, tilted_block_document(120).dump()));
}

TEST_F(Slurm, CancelOfAPendingSlurmJobScancelsIt) {
  // --begin keeps the Slurm job pending: the cancel cannot wait for an iteration boundary.
  ServerProcess server(database(), serve_arguments({"--slurm-extra", "--begin=now+3600"}));
  httplib::Client client = client_of(server);
  const std::int64_t job = submit_job(client, example_text("report-problem1.json"));
  const std::string path = "/v1/jobs/" + std::to_string(job);
  for (int k = 0; k < 200 && slurm_job_of(client, job).empty(); ++k) std::this_thread::sleep_for(std::chrono::milliseconds(50));
  const std::string slurm_job = slurm_job_of(client, job);
  ASSERT_FALSE(slurm_job.empty());
  ASSERT_EQ(client.Post(path + "/cancel", "", "application/json")->status, 202);
  const json cancelled = wait_for_state(client, job, {"cancelled"}, std::chrono::seconds(20));
  EXPECT_EQ(cancelled["slurm"]["state"], "CANCELLED");
  EXPECT_EQ(cancelled["iteration"], 0);
  const CommandResult squeue = run_command({"squeue", "--noheader", "--states=all", "--format=%T", "--jobs=" + slurm_job});
  EXPECT_NE(squeue.output.find("CANCELLED"), std::string::npos) << squeue.output;
}

TEST_F(Slurm, FiftyQueuedJobsDrainWithNothingLost) {
  ServerProcess server(database(), serve_arguments());
  httplib::Client client = client_of(server);
  const std::string body = example_text("report-problem1.json");
  const json reference = reference_of(dir_, body);
  std::vector<std::int64_t> jobs;
  for (int k = 0; k < 50; ++k) jobs.push_back(submit_job(client, body));
  std::set<std::string> slurm_jobs;
  for (const std::int64_t job : jobs) {
    const json done = wait_for_state(client, job, {"converged", "not_converged", "failed", "cancelled"}, std::chrono::seconds(60));
    ASSERT_EQ(done["state"], "converged") << done.dump();
    EXPECT_EQ(done["attempts"], 1);
    EXPECT_EQ(iteration_numbers(client, job).size(), reference["iterations"].get<std::size_t>());
    EXPECT_EQ(result_numbers(get_json(client, "/v1/jobs/" + std::to_string(job) + "/result")), result_numbers(reference));
    slurm_jobs.insert(slurm_job_of(client, job));
  }
  EXPECT_EQ(slurm_jobs.size(), jobs.size());
  EXPECT_EQ(get_json(client, "/healthz")["queue_length"], 0);
}

}  // namespace
}  // namespace saasgaps::testing
