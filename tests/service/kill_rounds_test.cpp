// Twenty kill -9 instants, drawn from a fixed seed, over a mix of submissions, cancels and resumes:
// nothing acknowledged is lost (every accepted job exists, every acknowledged cancel holds), each
// iteration is stored once, and every job, resumed to its end, has exactly the result of
// `saasgaps solve`.
#include <gtest/gtest.h>

#include <map>
#include <random>
#include <thread>

#include "service/long_job_model.hpp"
#include "service/service_fixture.hpp"

namespace saasgaps::testing {
namespace {

using nlohmann::json;
using KillRounds = ServiceFixture;

TEST_F(KillRounds, TwentyRandomKillsLoseNothingAndChangeNoResult) {
  // Jobs of 0.05-0.15 s of iterations, so that kills (0-250 ms after each round's requests) land in
  // the middle of runs: with iteration commits overlapping the next iteration, the smaller blocks
  // used before finished so fast that some seeds' rounds interrupted as few as 2 runs.
  const std::vector<std::string> models = {tilted_block_document(32).dump(), tilted_block_document(48).dump(),
                                           example_text("report-problem2.json")};
  std::vector<json> references;
  for (std::size_t m = 0; m < models.size(); ++m) {
    references.push_back(result_numbers(solve_locally(models[m], "model" + std::to_string(m))));
  }
  std::mt19937 random(20261123);
  std::map<std::int64_t, std::size_t> model_of;  // every job the server acknowledged (202)
  std::map<std::int64_t, bool> cancel_acknowledged;
  int cancels = 0;  // acknowledged cancels over all rounds
  const auto pick = [&](int n) { return std::uniform_int_distribution<int>(0, n - 1)(random); };

  for (int round = 0; round < 20; ++round) {
    SCOPED_TRACE("round " + std::to_string(round));
    ServerProcess server(database(), {"--max-interruptions", "100"});
    httplib::Client client = server.client();
    // What the last server acknowledged still holds.
    for (const auto& [id, model] : model_of) {
      const json job = get_json(client, "/v1/jobs/" + std::to_string(id));
      if (cancel_acknowledged[id]) {
        EXPECT_TRUE(job["state"] == "cancelled" || job["state"] == "converged") << job.dump();
      }
    }
    const int actions = 1 + pick(3);
    for (int a = 0; a < actions; ++a) {
      const int what = pick(4);
      if (what <= 1 || model_of.empty()) {
        const std::size_t m = static_cast<std::size_t>(pick(static_cast<int>(models.size())));
        const std::int64_t id = submit(client, models[m]);
        if (id > 0) model_of[id] = m;
      } else {
        // A cancel goes to the newest job, the one most likely still running; a resume to any.
        auto it = std::prev(model_of.end());
        if (what == 3) {
          it = model_of.begin();
          std::advance(it, pick(static_cast<int>(model_of.size())));
        }
        const std::string path = "/v1/jobs/" + std::to_string(it->first);
        if (what == 2) {
          const httplib::Result r = client.Post(path + "/cancel", "", "application/json");
          if (r && r->status == 202) {
            cancel_acknowledged[it->first] = true;
            ++cancels;
          }
        } else {
          const httplib::Result r = client.Post(path + "/resume", "", "application/json");
          if (r && r->status == 202) cancel_acknowledged[it->first] = false;
        }
      }
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(pick(250)));
    server.kill_hard();
  }

  // The last start: resume whatever was stopped on purpose, and compare every result.
  ServerProcess server(database(), {"--workers", "2", "--max-interruptions", "100"});
  httplib::Client client = server.client();
  EXPECT_EQ(get_json(client, "/v1/jobs?page_size=100")["jobs"].size(), model_of.size());
  int reruns = 0;
  for (const auto& [id, model] : model_of) {
    const std::string path = "/v1/jobs/" + std::to_string(id);
    json job = wait_for_state(client, id, {"converged", "not_converged", "failed", "cancelled"});
    if (job["state"] == "cancelled") {
      EXPECT_TRUE(cancel_acknowledged[id]) << "job " << id << " was cancelled without an acknowledged cancel";
      ASSERT_EQ(client.Post(path + "/resume", "", "application/json")->status, 202);
      job = wait_for_state(client, id, {"converged", "not_converged", "failed"});
    }
    EXPECT_EQ(job["state"], references[model]["status"]) << job.dump();
    reruns += job["attempts"].get<int>() - 1;
    const json rows = get_json(client, path + "/iterations")["iterations"];
    for (std::size_t k = 0; k < rows.size(); ++k) EXPECT_EQ(rows[k]["iteration"], static_cast<int>(k) + 1) << "job " << id;
    EXPECT_EQ(result_numbers(get_json(client, path + "/result")), references[model]) << "job " << id;
  }
  // The rounds did hit jobs in the middle: runs were interrupted and resumed, cancels were taken.
  EXPECT_GE(reruns, 2) << model_of.size() << " jobs";
  EXPECT_GE(cancels, 1);
  std::cout << model_of.size() << " jobs, " << reruns << " resumed runs, " << cancels << " cancels\n";
}

}  // namespace
}  // namespace saasgaps::testing
