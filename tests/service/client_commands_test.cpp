// The command-line client against a real server, as a user types it: `saasgaps submit` then
// `saasgaps watch` through a whole run, `status`, `jobs` and `fetch`; a model the server refuses;
// a long job cancelled with `saasgaps cancel` and continued with `saasgaps resume` (new READ card),
// with the token from SAASGAPS_TOKEN. Exit codes are solve's (cli/client/client_commands.hpp).
#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <sys/wait.h>

#include "service/job_client.hpp"
#include "service/long_job_model.hpp"
#include "service/server_process.hpp"
#include "service/service_fixture.hpp"
#include "support/captured_command.hpp"
#include "support/transient_heating.hpp"

namespace saasgaps::testing {
namespace {

using nlohmann::json;

#define EXPECT_CONTAINS(text, part) EXPECT_NE((text).find(part), std::string::npos) << (text)

class ClientCommands : public ServiceFixture {
 protected:
  /// Runs a shell command line in the test's directory with `saasgaps` meaning the binary under test,
  /// standard output and error captured apart (not a terminal: one line per event).
  Outcome shell(const std::string& environment, const std::string& line) const {
    return run_captured("cd " + dir_.string() + " && saasgaps() { " + environment + " " + SAASGAPS_BINARY +
                            " \"$@\"; }; { " + line + "; }",
                        dir_ / "out.txt", dir_ / "err.txt");
  }

  static std::string read(const std::string& file) { return read_text(file); }

  static std::string url(const ServerProcess& server) { return "http://127.0.0.1:" + std::to_string(server.port()); }
};

TEST_F(ClientCommands, SubmitAndWatchFollowARunToItsEndThenFetchItsParts) {
  ServerProcess server(database());
  std::ofstream(dir_ / "model.json") << example_text("report-problem3-case3.json");
  const std::string server_url = "SAASGAPS_SERVER=" + url(server);

  const Outcome run = shell(server_url, "id=$(saasgaps submit model.json) && echo \"job id $id\" && saasgaps watch $id");
  EXPECT_EQ(run.exit_code, 0) << run.out << run.err;
  EXPECT_CONTAINS(run.out, "job id 1\n");
  EXPECT_CONTAINS(run.err, "submitted model.json as job 1 (queued): " + url(server) + "/v1/jobs/1");
  // Not a terminal: a line per state change, the table's rows, and how the job ended.
  EXPECT_CONTAINS(run.out, "job 1: running\n");
  EXPECT_CONTAINS(run.out, "E tension");
  httplib::Client client = server.client();
  const std::string iterations = std::to_string(get_json(client, "/v1/jobs/1")["iteration"].get<int>());
  EXPECT_CONTAINS(run.out, "\n" + std::string(5 - iterations.size(), ' ') + iterations + " ");  // the last row
  EXPECT_CONTAINS(run.out, "job 1 converged: converged in " + iterations + " iterations");

  const Outcome status = shell(server_url, "saasgaps status 1");
  EXPECT_EQ(status.exit_code, 0) << status.err;
  EXPECT_CONTAINS(status.out, "job 1: converged\n");
  EXPECT_CONTAINS(status.out, "iteration   " + iterations + " of at most");
  const Outcome list = shell(server_url, "saasgaps jobs --state converged && saasgaps jobs --state failed");
  EXPECT_EQ(list.exit_code, 0) << list.err;
  EXPECT_CONTAINS(list.out, "converged");
  EXPECT_CONTAINS(list.out, "no failed jobs\n");

  const Outcome fetch = shell(server_url, "saasgaps fetch 1 -o result.json && saasgaps fetch 1 --vtu -o result.vtu && "
                                        "saasgaps fetch 1 --plot convergence -o convergence.svg");
  EXPECT_EQ(fetch.exit_code, 0) << fetch.err;
  const json result = json::parse(read((dir_ / "result.json").string()));
  EXPECT_EQ(result_numbers(result), result_numbers(solve_locally(example_text("report-problem3-case3.json"))));
  EXPECT_EQ(read((dir_ / "result.vtu").string()).rfind("<?xml", 0), 0U);
  EXPECT_CONTAINS(read((dir_ / "convergence.svg").string()), "<svg");

  // A job that is not there: the server's problem, title and detail, exit 1.
  const Outcome missing = shell(server_url, "saasgaps status 7");
  EXPECT_EQ(missing.exit_code, 1);
  EXPECT_CONTAINS(missing.err, "(HTTP 404)");
  EXPECT_CONTAINS(missing.err, "no job 7");
}

// A transient heat conduction run: `watch` prints its thermal rows as `solve` does.
TEST_F(ClientCommands, WatchPrintsTheThermalRowsOfAHeatConductionRun) {
  ServerProcess server(database());
  std::ofstream(dir_ / "heated.json") << transient_heating("ring-shrink-fit-plane-strain.json", {.hot = 400.0}).dump();
  const Outcome run = shell("SAASGAPS_SERVER=" + url(server), "saasgaps submit heated.json --watch");
  EXPECT_EQ(run.exit_code, 0) << run.out << run.err;
  EXPECT_CONTAINS(run.out, "thermal t = 0.25: 5 steps, max step |dT| 400, T 0 .. 400\n");
  EXPECT_CONTAINS(run.out, "thermal t = 1: 20 steps");
  EXPECT_CONTAINS(run.out, "converged");
}

TEST_F(ClientCommands, InvalidModelIsExitTwoWithEveryPointer) {
  ServerProcess server(database());
  json model = json::parse(example_text("report-problem1.json"));
  model["analysis"]["type"] = "plane";
  model["nodes"][0]["r"] = "x";
  model["solver"]["max_iterations"] = 1000000000;  // the command line's limit holds over HTTP too
  std::ofstream(dir_ / "bad.json") << model.dump();
  const Outcome r = shell("", "saasgaps submit bad.json --server " + url(server));
  EXPECT_EQ(r.exit_code, 2) << r.out << r.err;
  EXPECT_EQ(r.out, "");
  EXPECT_CONTAINS(r.err, "error: Invalid model (HTTP 422): 3 errors");
  EXPECT_CONTAINS(r.err, "\n/analysis/type: ");
  EXPECT_CONTAINS(r.err, "\n/nodes/0/r: ");
  EXPECT_CONTAINS(r.err, "\n/solver/max_iterations: max_iterations = 1000000000 is out of range: need 1 <= max_iterations <= 100000");
  // No server there: exit 1 naming the URL.
  const Outcome away = shell("", "saasgaps jobs --server http://127.0.0.1:" + std::to_string(free_port()));
  EXPECT_EQ(away.exit_code, 1);
  EXPECT_CONTAINS(away.err, "is `saasgaps serve` running there?");
}

TEST_F(ClientCommands, CancelThenResumeWithANewReadCard) {
  std::ofstream(dir_ / "token") << "s3cret\n";
  ServerProcess server(database(), {"--token-file", (dir_ / "token").string()});
  httplib::Client client = server.client();
  client.set_bearer_token_auth("s3cret");
  std::ofstream(dir_ / "long.json") << tilted_block_document(120).dump();
  const std::string environment = "SAASGAPS_SERVER=" + url(server) + " SAASGAPS_TOKEN=s3cret";

  // Without the token the server refuses (401), and says so.
  const Outcome refused = shell("SAASGAPS_SERVER=" + url(server), "saasgaps submit long.json");
  EXPECT_EQ(refused.exit_code, 1);
  EXPECT_CONTAINS(refused.err, "(HTTP 401)");

  const Outcome submitted = shell(environment, "saasgaps submit long.json");
  ASSERT_EQ(submitted.exit_code, 0) << submitted.err;
  const std::int64_t job = std::stoll(submitted.out);
  const std::string id = std::to_string(job);
  wait_for_running_iteration(client, job, 2);
  const Outcome cancel = shell(environment, "saasgaps cancel " + id + " && saasgaps watch " + id);
  EXPECT_EQ(cancel.exit_code, 3) << cancel.out << cancel.err;  // cancelled: it can be resumed
  EXPECT_CONTAINS(cancel.out, "job " + id + ": cancel requested; it stops at the next iteration boundary");
  EXPECT_CONTAINS(cancel.out, "job " + id + " cancelled");
  const int stopped_at = get_json(client, "/v1/jobs/" + id)["iteration"].get<int>();
  ASSERT_GE(stopped_at, 2);

  const Outcome bad = shell(environment, "saasgaps resume " + id + " --extrapolation 1");
  EXPECT_EQ(bad.exit_code, 64);
  EXPECT_CONTAINS(bad.err, "--extrapolation: must be a number at least 0 and below 1, got \"1\"");

  const Outcome resumed = shell(environment, "saasgaps resume " + id + " --schedule 3,1 --max-iterations 60 --watch");
  EXPECT_EQ(resumed.exit_code, 0) << resumed.out << resumed.err;
  EXPECT_CONTAINS(resumed.err, "job " + id + " queued to continue after " + std::to_string(stopped_at) + " iterations");
  EXPECT_CONTAINS(resumed.out, "job " + id + " converged: converged in ");
  const json rows = get_json(client, "/v1/jobs/" + id + "/iterations")["iterations"];
  ASSERT_GT(static_cast<int>(rows.size()), stopped_at + 1);
  EXPECT_EQ(rows[stopped_at]["tensile_modulus"], 3.0);  // the new schedule, afresh
  EXPECT_EQ(rows[stopped_at]["attempt"], 2);
  EXPECT_EQ(get_json(client, "/v1/jobs/" + id)["max_iterations"], 60);

  // A converged job cannot be resumed: the server's 409, title and detail, exit 1.
  const Outcome again = shell(environment, "saasgaps resume " + id);
  EXPECT_EQ(again.exit_code, 1);
  EXPECT_CONTAINS(again.err, "(HTTP 409)");
  EXPECT_CONTAINS(again.err, "converged");
}

}  // namespace
}  // namespace saasgaps::testing
