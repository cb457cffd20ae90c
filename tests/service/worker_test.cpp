// The worker routes without Slurm: a `saasgaps worker` started by hand takes a queued job from a
// local-executor service and gives the same result as `saasgaps solve`; the lease rules hold for
// every write (stale or wrong leases, gaps, retried requests, bodies that do not decode).
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "service/job_client.hpp"
#include "service/long_job_model.hpp"
#include "service/server_process.hpp"

namespace saasgaps::testing {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

class Worker : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("saasgaps-worker-" + std::to_string(::getpid()) + "-" +
                                        ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
    std::ofstream(dir_ / "token") << "worker-token\n";
  }
  void TearDown() override { fs::remove_all(dir_); }

  static std::string cbor(const json& j) {
    const std::vector<std::uint8_t> bytes = json::to_cbor(j);
    return {bytes.begin(), bytes.end()};
  }

  fs::path dir_;
};

TEST_F(Worker, AWorkerStartedByHandTakesAQueuedJobAndMatchesSolve) {
  ServerProcess server(dir_ / "jobs.db", {"--token-file", (dir_ / "token").string()});
  httplib::Client client = server.client();
  client.set_bearer_token_auth("worker-token");
  // The pool's one thread is busy with a long job; the second job waits in the queue for us.
  const std::int64_t busy = submit_job(client, tilted_block_document(120).dump());
  wait_for_state(client, busy, {"running"});
  const std::string body = example_text("report-problem2.json");
  const std::int64_t job = submit_job(client, body);
  const CommandResult run = run_command({SAASGAPS_BINARY, "worker", "--server", "http://127.0.0.1:" + std::to_string(server.port()),
                                         "--job", std::to_string(job), "--token-file", (dir_ / "token").string()});
  EXPECT_EQ(run.exit_code, 0) << run.output;
  const json done = get_json(client, "/v1/jobs/" + std::to_string(job));
  EXPECT_EQ(done["state"], "converged") << done.dump();
  EXPECT_EQ(result_numbers(get_json(client, "/v1/jobs/" + std::to_string(job) + "/result")),
            result_numbers(solve_locally(dir_, body)));
  // Without the token the worker is refused like any client.
  const CommandResult anonymous = run_command({SAASGAPS_BINARY, "worker", "--server",
                                               "http://127.0.0.1:" + std::to_string(server.port()), "--job", "1"});
  EXPECT_EQ(anonymous.exit_code, 1) << anonymous.output;
  EXPECT_NE(anonymous.output.find("401"), std::string::npos) << anonymous.output;
  client.Post("/v1/jobs/" + std::to_string(busy) + "/cancel", "", "application/json");
}

TEST_F(Worker, EveryWriteChecksTheLease) {
  ServerProcess server(dir_ / "jobs.db");
  httplib::Client client = server.client();
  // Keep the pool busy so that the job under test stays queued until this test takes it.
  const std::int64_t busy = submit_job(client, tilted_block_document(120).dump());
  wait_for_state(client, busy, {"running"});
  const std::int64_t job = submit_job(client, example_text("report-problem1.json"));
  const std::string path = "/v1/jobs/" + std::to_string(job);

  const httplib::Result granted = client.Post(path + "/lease", "", "application/json");
  ASSERT_EQ(granted->status, 201) << granted->body;
  const json lease = json::parse(granted->body);
  EXPECT_EQ(lease["attempt"], 1);
  const httplib::Headers held = {{"Saasgaps-Lease", "1:" + lease["secret"].get<std::string>()}};
  // Taking a running job again is refused.
  EXPECT_EQ(client.Post(path + "/lease", "", "application/json")->status, 409);

  const httplib::Result work = client.Get(path + "/work", held);
  ASSERT_EQ(work->status, 200) << work->body;
  const json w = json::from_cbor(work->body);
  EXPECT_EQ(w["model"].get<std::string>(), example_text("report-problem1.json"));
  EXPECT_TRUE(w["state"].is_null());

  const std::string first = cbor({{"iteration", 1}, {"row", R"({"iteration":1})"}, {"state", json::binary({1, 2})}});
  const std::string first_changed = cbor({{"iteration", 1}, {"row", R"({"iteration":1,"x":2})"}, {"state", json::binary({1})}});
  const std::string third = cbor({{"iteration", 3}, {"row", R"({"iteration":3})"}, {"state", json::binary({3})}});
  EXPECT_EQ(client.Post(path + "/work/iterations", held, first, "application/cbor")->status, 200);
  // The same request again (its answer was lost): accepted, not written twice.
  EXPECT_EQ(client.Post(path + "/work/iterations", held, first, "application/cbor")->status, 200);
  EXPECT_EQ(iteration_numbers(client, job), std::vector<int>({1}));
  // Another row for a committed iteration, or a gap: refused.
  EXPECT_EQ(client.Post(path + "/work/iterations", held, first_changed, "application/cbor")->status, 409);
  EXPECT_EQ(client.Post(path + "/work/iterations", held, third, "application/cbor")->status, 409);
  // Wrong secret, stale attempt, no lease, a body that is not CBOR.
  EXPECT_EQ(client.Get(path + "/work", {{"Saasgaps-Lease", "1:guess"}})->status, 409);
  EXPECT_EQ(client.Get(path + "/work", {{"Saasgaps-Lease", "0:" + lease["secret"].get<std::string>()}})->status, 400);
  EXPECT_EQ(client.Get(path + "/work")->status, 400);
  EXPECT_EQ(client.Post(path + "/work/iterations", held, "{not cbor", "application/cbor")->status, 400);
  EXPECT_EQ(client.Post(path + "/work/finish", held, cbor({{"state", "interrupted"}}), "application/cbor")->status, 400);

  // A cancel reaches the worker in the answer to its next iteration.
  ASSERT_EQ(client.Post(path + "/cancel", "", "application/json")->status, 202);
  const std::string second = cbor({{"iteration", 2}, {"row", R"({"iteration":2})"}, {"state", json::binary({2})}});
  const httplib::Result answer = client.Post(path + "/work/iterations", held, second, "application/cbor");
  ASSERT_EQ(answer->status, 200);
  EXPECT_EQ(json::parse(answer->body)["stop"], true);
  const std::string finish = cbor({{"state", "cancelled"}, {"result", R"({"status":"not_converged"})"}, {"message", "stopped"}});
  EXPECT_EQ(client.Post(path + "/work/finish", held, finish, "application/cbor")->status, 204);
  EXPECT_EQ(client.Post(path + "/work/finish", held, finish, "application/cbor")->status, 204);  // a retry
  EXPECT_EQ(get_json(client, path)["state"], "cancelled");
  // After a resume the job is queued again: the old lease can no longer finish it.
  ASSERT_EQ(client.Post(path + "/resume", "{}", "application/json")->status, 202);
  EXPECT_EQ(client.Post(path + "/work/finish", held, finish, "application/cbor")->status, 409);
  client.Post("/v1/jobs/" + std::to_string(busy) + "/cancel", "", "application/json");
}

}  // namespace
}  // namespace saasgaps::testing
