// Adaptive jobs through the service (issue 32): an uploaded assembly with `adapt` runs the adaptive
// loop as one job; each cycle is stored, shown in the job's `adaptation`, streamed as an
// `adapt_cycle` event and drawn by plots/adaptation.svg; the job's result is the last cycle's with
// `adaptation`, the same numbers as `saasgaps solve ASSEMBLY.json`. A server killed (SIGKILL)
// mid-loop loses no stored cycle, and the restarted server goes on after the last of them to the
// same result.
#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <string>
#include <thread>
#include <vector>

#include "service/service_fixture.hpp"
#include "support/environment_variable.hpp"

namespace saasgaps::testing {
namespace {

using nlohmann::json;
using AdaptService = ServiceFixture;

std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

/// The upload directories (service/ops/private_directory.hpp) in `dir`.
std::vector<std::string> upload_directories(const std::filesystem::path& dir) {
  std::vector<std::string> found;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    if (entry.path().filename().string().starts_with("saasgaps-upload-")) found.push_back(entry.path().filename());
  }
  return found;
}

/// The adaptation rows without their wall times: what must match between runs.
json cycle_numbers(json rows) {
  for (json& row : rows) row.erase("seconds");
  return rows;
}

/// The result's numbers: no wall times (history rows, adaptation rows).
json numbers(json result) {
  result = result_numbers(std::move(result));
  if (result.contains("adaptation")) result["adaptation"] = cycle_numbers(result["adaptation"]);
  return result;
}

class AdaptServiceRun : public AdaptService {
 protected:
  /// LE1 from its .geo with the given adapt block, uploaded as an assembly and its mesh.
  static httplib::MultipartFormDataItems le1_upload(const json& assembly) {
    return {{"assembly", assembly.dump(), "", "application/json"},
            {"mesh", example_text("assemblies/le1.geo"), "le1.geo", "text/plain"}};
  }

  static json le1(const json& adapt) {
    json a = json::parse(example_text("assemblies/le1-adapt.assembly.json"));
    a["adapt"] = adapt;
    return a;
  }

  static std::int64_t submit_upload(httplib::Client& client, const json& assembly) {
    const httplib::Result queued = client.Post("/v1/imports?submit=true", le1_upload(assembly));
    EXPECT_TRUE(queued);
    if (!queued) return 0;
    EXPECT_EQ(queued->status, 202) << queued->body;
    return json::parse(queued->body).value("id", std::int64_t{0});
  }

  /// `saasgaps solve ASSEMBLY.json` of the same assembly (next to a copy of le1.geo): the reference.
  json solve_assembly(const json& assembly) const {
    std::ofstream(dir_ / "le1.geo") << example_text("assemblies/le1.geo");
    const auto path = dir_ / "le1.assembly.json", out = dir_ / "le1-result.json";
    std::ofstream(path) << assembly.dump();
    const CommandResult run = run_command({SAASGAPS_BINARY, "solve", path.string(), "-q", "-o", out.string()});
    EXPECT_LE(run.exit_code, 3) << run.output;
    std::ifstream in(out);
    return json::parse(in);
  }
};

TEST_F(AdaptServiceRun, CyclesAreStoredStreamedAndPlottedAndTheResultIsTheCommandLines) {
  const json assembly = le1({{"target_error", 0.03}, {"max_cycles", 4}});
  const json reference = solve_assembly(assembly);
  ASSERT_GE(reference["adaptation"].size(), 2U) << reference.dump().substr(0, 400);

  ServerProcess server(database());
  httplib::Client client = server.client();
  const std::int64_t job = submit_upload(client, assembly);
  const std::string path = "/v1/jobs/" + std::to_string(job);
  const json done = wait_for_state(client, job, {"converged", "not_converged", "failed"});
  ASSERT_EQ(done["state"], "converged") << done.dump();
  // The job's cycles as they were stored, each with its time split.
  const json& cycles = done["adaptation"];
  ASSERT_EQ(cycles.size(), reference["adaptation"].size()) << done.dump();
  for (std::size_t k = 0; k < cycles.size(); ++k) {
    EXPECT_EQ(cycles[k]["cycle"], static_cast<int>(k) + 1);
    for (const char* part : {"mesh", "import", "solve", "estimate", "sizes"}) {
      EXPECT_TRUE(cycles[k]["seconds"][part].is_number()) << part;
    }
    EXPECT_GT(cycles[k]["seconds"]["estimate"].get<double>(), 0.0);
  }
  EXPECT_EQ(cycle_numbers(cycles), cycle_numbers(reference["adaptation"]));
  EXPECT_LE(cycles.back()["relative_error"].get<double>(), 0.03);
  EXPECT_NE(done["message"].get<std::string>().find("adaptation reached relative error"), std::string::npos);

  // The result: the last cycle's, with the same adaptation rows as the job shows.
  const json result = get_json(client, path + "/result");
  EXPECT_EQ(result["adaptation"], cycles);
  EXPECT_EQ(numbers(result), numbers(reference));

  // One adapt_cycle event per cycle.
  const httplib::Result events = client.Get(path + "/events");
  ASSERT_EQ(events->status, 200);
  EXPECT_EQ(count(events->body, "event: adapt_cycle\n"), cycles.size());

  // The convergence plot (error against unknowns, log-log) and its numbers.
  const httplib::Result svg = client.Get(path + "/plots/adaptation.svg");
  ASSERT_EQ(svg->status, 200) << svg->body;
  EXPECT_EQ(svg->get_header_value("Content-Type"), "image/svg+xml");
  EXPECT_NE(svg->body.find("<svg"), std::string::npos);
  const httplib::Result csv = client.Get(path + "/plots/adaptation.csv");
  ASSERT_EQ(csv->status, 200) << csv->body;
  EXPECT_NE(csv->body.find("cycle,unknowns,relative_error"), std::string::npos) << csv->body;

  // A job of a model has no cycles to plot: 409.
  const std::int64_t plain = submit(client, example_text("report-problem3-case1.json"));
  wait_for_state(client, plain, {"converged", "not_converged", "failed"});
  EXPECT_FALSE(get_json(client, "/v1/jobs/" + std::to_string(plain)).contains("adaptation"));
  problem(client.Get("/v1/jobs/" + std::to_string(plain) + "/plots/adaptation.svg"), 409);
}

TEST_F(AdaptServiceRun, AServerKilledMidLoopLosesNoStoredCycle) {
  // Three cycles to the 2 % target (148, 2449, then about 6000 nodes).
  const json assembly = le1({{"target_error", 0.02}, {"max_cycles", 4}});
  const json reference = solve_assembly(assembly);
  const std::size_t cycles = reference["adaptation"].size();
  ASSERT_GE(cycles, 3U) << reference.dump().substr(0, 400);

  // The servers' temporary directory: the killed server leaves its upload directory there, and
  // the next server removes it when it starts (docs/operations.md, "Temporary files").
  const std::filesystem::path tmp = dir_ / "tmp";
  std::filesystem::create_directories(tmp);
  const EnvironmentVariable tmpdir("TMPDIR", tmp.string());  // the servers inherit it
  std::int64_t job = 0;
  json before;
  {
    ServerProcess server(database());
    httplib::Client client = server.client();
    job = submit_upload(client, assembly);
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(120);
    while (std::chrono::steady_clock::now() < deadline) {
      before = get_json(client, "/v1/jobs/" + std::to_string(job));
      if (before["state"] != "running" && before["state"] != "queued") break;
      if (before.value("adaptation", json::array()).size() >= 1) break;
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    ASSERT_EQ(before["state"], "running") << before.dump();
    ASSERT_GE(before["adaptation"].size(), 1U);
    ASSERT_LT(before["adaptation"].size(), cycles);
    server.kill_hard();
  }
  EXPECT_EQ(upload_directories(tmp).size(), 1U) << "the killed server's upload directory";
  ServerProcess restarted(database());
  httplib::Client client = restarted.client();
  const std::string path = "/v1/jobs/" + std::to_string(job);
  const json done = wait_for_state(client, job, {"converged", "not_converged", "failed"});
  ASSERT_EQ(done["state"], "converged") << done.dump();
  EXPECT_GE(done["attempts"].get<int>(), 2) << "the kill did not interrupt the run";
  ASSERT_EQ(done["adaptation"].size(), cycles) << done.dump();
  // Every cycle acknowledged before the kill is still there, unchanged (its times included).
  for (std::size_t k = 0; k < before["adaptation"].size(); ++k) {
    EXPECT_EQ(done["adaptation"][k], before["adaptation"][k]) << k;
  }
  EXPECT_EQ(cycle_numbers(done["adaptation"]), cycle_numbers(reference["adaptation"]));
  EXPECT_EQ(numbers(get_json(client, path + "/result")), numbers(reference));
  EXPECT_NE(restarted.log().find("\"adapt_resumed\""), std::string::npos);
  EXPECT_NE(restarted.log().find("\"abandoned_uploads_removed\":1"), std::string::npos) << restarted.log();
  EXPECT_TRUE(upload_directories(tmp).empty()) << upload_directories(tmp).front();
}

/// Cancelled between cycles, resumed: it goes on after the last stored cycle.
TEST_F(AdaptServiceRun, ACancelledJobResumesAfterItsLastCycle) {
  // A target out of reach in two cycles: the loop runs to max_cycles = 2.
  const json assembly = le1({{"target_error", 0.002}, {"max_cycles", 2}});
  ServerProcess server(database());
  httplib::Client client = server.client();
  const std::int64_t job = submit_upload(client, assembly);
  const std::string path = "/v1/jobs/" + std::to_string(job);
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(120);
  json seen;
  while (std::chrono::steady_clock::now() < deadline) {
    seen = get_json(client, path);
    if (seen.value("adaptation", json::array()).size() >= 1) break;
    if (seen["state"] != "running" && seen["state"] != "queued") break;
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  ASSERT_EQ(client.Post(path + "/cancel")->status, 202);
  const json cancelled = wait_for_state(client, job, {"cancelled", "converged", "not_converged", "failed"});
  ASSERT_EQ(cancelled["state"], "cancelled") << cancelled.dump();
  const std::size_t stored = cancelled["adaptation"].size();
  ASSERT_GE(stored, 1U);
  ASSERT_LT(stored, 2U);
  ASSERT_EQ(client.Post(path + "/resume")->status, 202);
  const json done = wait_for_state(client, job, {"converged", "not_converged", "failed"});
  ASSERT_EQ(done["state"], "not_converged") << done.dump();  // stopped at max_cycles
  EXPECT_NE(done["message"].get<std::string>().find("adaptation stopped at the limit max_cycles = 2"), std::string::npos);
  ASSERT_EQ(done["adaptation"].size(), 2U) << done.dump();
  for (std::size_t k = 0; k < stored; ++k) EXPECT_EQ(done["adaptation"][k], cancelled["adaptation"][k]);
}

}  // namespace
}  // namespace saasgaps::testing
