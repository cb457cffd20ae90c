// The worker routes without a real Slurm: a stand-in `sbatch` on PATH records the batch script and
// the run's ticket instead of queueing anything, and a stand-in `squeue` reports every Slurm job
// running, so the test plays the worker. A worker with its ticket gives the same result as `saasgaps
// solve`; a lease is granted only for a job the service handed to Slurm, once; every write checks
// the lease (stale or wrong leases, gaps, retried requests, bodies that do not decode); a finish
// spends it, and one for another model, forged or replayed, stores nothing.
#include <gtest/gtest.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <optional>
#include <thread>

#include "io/model/model_reader.hpp"
#include "service/job_client.hpp"
#include "service/long_job_model.hpp"
#include "service/runs/job_execution.hpp"
#include "service/server_process.hpp"
#include "support/environment_variable.hpp"

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
    fs::create_directories(dir_ / "bin");
    std::ofstream(dir_ / "token") << "worker-token\n";
    // sbatch: the job id from the script's comment line; the ticket from the environment.
    write_program("sbatch",
                  "script=$(cat)\n"
                  "job=$(printf '%s\\n' \"$script\" | sed -n 's/^# saasgaps job //p')\n"
                  "printf '%s' \"$SAASGAPS_TICKET\" > \"$FAKE_SLURM_DIR/job-$job.ticket\"\n"
                  "echo $((7000 + job))\n");
    write_program("squeue",
                  "for a in \"$@\"; do case \"$a\" in --jobs=*) ids=${a#--jobs=};; esac; done\n"
                  "printf '%s\\n' \"$ids\" | tr ',' '\\n' | while read -r id; do [ -n \"$id\" ] && echo \"$id|RUNNING\"; done\n"
                  "exit 0\n");
    write_program("scancel", "exit 0\n");
    fake_slurm_dir_.emplace("FAKE_SLURM_DIR", dir_.string());
    const char* path = std::getenv("PATH");
    path_.emplace("PATH", (dir_ / "bin").string() + ":" + (path != nullptr ? path : ""));
  }
  void TearDown() override {
    path_.reset();
    fake_slurm_dir_.reset();
    // A fake sbatch the server started just before it stopped can still be writing its ticket file
    // here (seen once: "Directory not empty"): try again for a moment rather than fail on cleanup.
    std::error_code error;
    for (int attempt = 0; attempt < 50; ++attempt) {
      fs::remove_all(dir_, error);
      if (!error && !fs::exists(dir_)) break;
      std::this_thread::sleep_for(std::chrono::milliseconds(100));
    }
  }

  void write_program(const std::string& name, const std::string& body) const {
    std::ofstream(dir_ / "bin" / name) << "#!/bin/sh\n" << body;
    fs::permissions(dir_ / "bin" / name, fs::perms::owner_all);
  }

  [[nodiscard]] std::vector<std::string> slurm_arguments() const {
    return {"--executor", "slurm", "--token-file", (dir_ / "token").string(), "--slurm-poll", "0.2"};
  }

  /// The ticket the stand-in sbatch received for the job, "ATTEMPT:TICKET".
  [[nodiscard]] std::string ticket_of(std::int64_t job) const {
    const fs::path file = dir_ / ("job-" + std::to_string(job) + ".ticket");
    for (int k = 0; k < 400 && !fs::exists(file); ++k) std::this_thread::sleep_for(std::chrono::milliseconds(25));
    std::ifstream in(file);
    std::string ticket;
    std::getline(in, ticket);
    return ticket;
  }

  static std::string cbor(const json& j) {
    const std::vector<std::uint8_t> bytes = json::to_cbor(j);
    return {bytes.begin(), bytes.end()};
  }

  fs::path dir_;
  std::optional<EnvironmentVariable> fake_slurm_dir_;  ///< where the stand-in sbatch writes tickets
  std::optional<EnvironmentVariable> path_;            ///< the stand-ins' directory first
};

TEST_F(Worker, AWorkerWithItsTicketMatchesSolveAndTheTicketIsSpent) {
  ServerProcess server(dir_ / "jobs.db", slurm_arguments());
  httplib::Client client = server.client();
  client.set_bearer_token_auth("worker-token");
  const std::string body = example_text("report-problem2.json");
  const std::int64_t job = submit_job(client, body);
  const std::string ticket = ticket_of(job);
  ASSERT_FALSE(ticket.empty());
  const std::vector<std::string> worker = {SAASGAPS_BINARY, "worker", "--server", "http://127.0.0.1:" + std::to_string(server.port()),
                                           "--job", std::to_string(job), "--token-file", (dir_ / "token").string()};
  std::vector<std::string> with_ticket = worker;
  with_ticket.insert(with_ticket.end(), {"--ticket", ticket});
  const CommandResult run = run_command(with_ticket);
  EXPECT_EQ(run.exit_code, 0) << run.output;
  const json done = get_json(client, "/v1/jobs/" + std::to_string(job));
  EXPECT_EQ(done["state"], "converged") << done.dump();
  EXPECT_EQ(result_numbers(get_json(client, "/v1/jobs/" + std::to_string(job) + "/result")),
            result_numbers(solve_locally(dir_, body)));
  // The same ticket again (read from the Slurm job's environment, say) is spent: the worker stops.
  const CommandResult again = run_command(with_ticket);
  EXPECT_EQ(again.exit_code, 5) << again.output;
  EXPECT_NE(again.output.find("holds this ticket"), std::string::npos) << again.output;
  // Without a ticket a worker has nothing to run.
  const CommandResult bare = run_command(worker);
  EXPECT_NE(bare.exit_code, 0) << bare.output;
  EXPECT_NE(bare.output.find("no ticket"), std::string::npos) << bare.output;
}

TEST_F(Worker, ALeaseOnlyForAJobHandedToSlurmAndOnlyOnce) {
  ServerProcess server(dir_ / "jobs.db", slurm_arguments());
  httplib::Client client = server.client();
  client.set_bearer_token_auth("worker-token");
  const std::int64_t first = submit_job(client, example_text("report-problem1.json"));
  const std::int64_t second = submit_job(client, example_text("report-problem1.json"));
  const std::string path = "/v1/jobs/" + std::to_string(first);
  const std::string ticket = ticket_of(first);
  ASSERT_EQ(ticket.rfind("1:", 0), 0U) << ticket;
  // No ticket, a made-up one, another job's: refused, and the run keeps its ticket.
  EXPECT_EQ(client.Post(path + "/lease", "", "application/json")->status, 400);
  EXPECT_EQ(client.Post(path + "/lease", {{"Saasgaps-Ticket", "1:0123456789abcdef0123456789abcdef"}}, "", "application/json")->status, 409);
  EXPECT_EQ(client.Post(path + "/lease", {{"Saasgaps-Ticket", ticket_of(second)}}, "", "application/json")->status, 409);
  EXPECT_EQ(client.Post(path + "/lease", {{"Saasgaps-Ticket", "2:" + ticket.substr(2)}}, "", "application/json")->status, 409);
  const httplib::Result granted = client.Post(path + "/lease", {{"Saasgaps-Ticket", ticket}}, "", "application/json");
  ASSERT_EQ(granted->status, 201) << granted->body;
  EXPECT_EQ(json::parse(granted->body)["attempt"], 1);
  EXPECT_EQ(client.Post(path + "/lease", {{"Saasgaps-Ticket", ticket}}, "", "application/json")->status, 409);
  // A job no run of which is with Slurm (finished, here) cannot be leased with any ticket.
  const std::vector<std::string> worker = {SAASGAPS_BINARY, "worker", "--server", "http://127.0.0.1:" + std::to_string(server.port()),
                                           "--token-file", (dir_ / "token").string(), "--job", std::to_string(second),
                                           "--ticket", ticket_of(second)};
  ASSERT_EQ(run_command(worker).exit_code, 0);
  EXPECT_EQ(client.Post("/v1/jobs/" + std::to_string(second) + "/lease", {{"Saasgaps-Ticket", ticket_of(second)}}, "",
                        "application/json")->status, 409);
}

TEST_F(Worker, EveryWriteChecksTheLeaseAndAFinishSpendsIt) {
  ServerProcess server(dir_ / "jobs.db", slurm_arguments());
  httplib::Client client = server.client();
  client.set_bearer_token_auth("worker-token");
  const std::string model = example_text("report-problem1.json");
  const std::int64_t job = submit_job(client, model);
  const std::string path = "/v1/jobs/" + std::to_string(job);
  const httplib::Result granted = client.Post(path + "/lease", {{"Saasgaps-Ticket", ticket_of(job)}}, "", "application/json");
  ASSERT_EQ(granted->status, 201) << granted->body;
  const json lease = json::parse(granted->body);
  const httplib::Headers held = {{"Saasgaps-Lease", "1:" + lease["secret"].get<std::string>()}};

  const httplib::Result work = client.Get(path + "/work", held);
  ASSERT_EQ(work->status, 200) << work->body;
  const json w = json::from_cbor(work->body);
  EXPECT_EQ(w["model"].get<std::string>(), model);
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

  // A thermal row under the lease: stored once (a repeat, as a resumed run sends, changes nothing);
  // without the right secret, refused.
  const std::string thermal = cbor({{"index", 1}, {"row", R"({"index":1,"kind":"steady"})"}});
  EXPECT_EQ(client.Post(path + "/work/thermal", held, thermal, "application/cbor")->status, 204);
  EXPECT_EQ(client.Post(path + "/work/thermal", held, thermal, "application/cbor")->status, 204);
  EXPECT_EQ(get_json(client, path + "/thermal")["thermal"], json::parse(R"([{"index":1,"kind":"steady"}])"));
  EXPECT_EQ(client.Post(path + "/work/thermal", {{"Saasgaps-Lease", "1:guess"}}, thermal, "application/cbor")->status, 409);
  EXPECT_EQ(client.Post(path + "/work/thermal", held, "{not cbor", "application/cbor")->status, 400);

  // A cancel reaches the worker in the answer to its next iteration.
  ASSERT_EQ(client.Post(path + "/cancel", "", "application/json")->status, 202);
  const std::string second = cbor({{"iteration", 2}, {"row", R"({"iteration":2})"}, {"state", json::binary({2})}});
  const httplib::Result answer = client.Post(path + "/work/iterations", held, second, "application/cbor");
  ASSERT_EQ(answer->status, 200);
  EXPECT_EQ(json::parse(answer->body)["stop"], true);

  // A result for another model (its digest is not the job's) is refused, and nothing is stored.
  const std::string digest = io::model_text_digest(model);
  const std::string other = io::model_text_digest(example_text("report-problem2.json"));
  ASSERT_NE(digest, other);
  const auto finish_of = [](const std::string& result, const std::string& model_digest) {
    return cbor({{"state", "cancelled"}, {"result", result}, {"message", "stopped"}, {"model_digest", model_digest}});
  };
  const std::string honest = R"({"status":"not_converged"})";
  const std::string forged = R"({"status":"converged","forged":true})";
  EXPECT_EQ(client.Post(path + "/work/finish", held, finish_of(forged, other), "application/cbor")->status, 422);
  EXPECT_EQ(client.Post(path + "/work/finish", held, cbor({{"state", "cancelled"}}), "application/cbor")->status, 400);
  EXPECT_EQ(get_json(client, path)["state"], "running");
  EXPECT_EQ(client.Post(path + "/work/finish", held, finish_of(honest, digest), "application/cbor")->status, 204);
  EXPECT_EQ(client.Post(path + "/work/finish", held, finish_of(honest, digest), "application/cbor")->status, 204);  // a retry
  EXPECT_EQ(get_json(client, path)["state"], "cancelled");
  // The finish spent the lease: another finish under it (a replay with another result) and any
  // other write are refused; the stored result stays the run's.
  const httplib::Result replayed = client.Post(path + "/work/finish", held, finish_of(forged, digest), "application/cbor");
  EXPECT_EQ(replayed->status, 409) << replayed->body;
  EXPECT_EQ(client.Post(path + "/work/iterations", held, cbor({{"iteration", 3}, {"row", "{}"}, {"state", json::binary({3})}}),
                        "application/cbor")->status, 409);
  EXPECT_EQ(get_json(client, path + "/result"), json::parse(honest));
  // After a resume the job runs again under a new attempt: the old lease can no longer finish it.
  ASSERT_EQ(client.Post(path + "/resume", "{}", "application/json")->status, 202);
  EXPECT_EQ(client.Post(path + "/work/finish", held, finish_of(forged, digest), "application/cbor")->status, 409);
}

}  // namespace
}  // namespace saasgaps::testing
