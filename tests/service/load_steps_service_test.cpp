// A model with load steps through the service: its history rows carry step and increment in the
// store, the iterations route and the event stream; iteration numbers stay the unit of progress
// (unique, 1..N across increments); and a kill -9 of the server in the middle of a step, then a
// restart, gives exactly the result of `saasgaps solve`.
#include <gtest/gtest.h>

#include <thread>

#include "service/long_job_model.hpp"
#include "service/service_fixture.hpp"

namespace saasgaps::testing {
namespace {

using nlohmann::json;
using std::chrono::milliseconds;
using LoadStepsService = ServiceFixture;

/// The tilted block pressed in 4 increments, then held for one more step.
std::string stepped_block(int n) {
  json model = tilted_block_document(n);
  model["steps"] = json::array({{{"name", "press"}, {"increments", 4}}, {{"name", "hold"}, {"increments", 1}}});
  return model.dump();
}

TEST_F(LoadStepsService, RowsCarryStepAndIncrementAndAKillMidStepChangesNoResult) {
  const std::string body = stepped_block(96);
  const json reference = result_numbers(solve_locally(body));
  ASSERT_EQ(reference["steps"].size(), 2U) << reference.dump().substr(0, 400);
  std::int64_t job = 0;
  {
    ServerProcess server(database());
    httplib::Client client = server.client();
    job = submit(client, body);
    // Kill once the run is inside the first step (its 4 increments take several iterations).
    for (int k = 0; k < 12000 && get_json(client, "/v1/jobs/" + std::to_string(job))["iteration"] < 2; ++k) {
      std::this_thread::sleep_for(milliseconds(5));
    }
    const json rows = get_json(client, "/v1/jobs/" + std::to_string(job) + "/iterations")["iterations"];
    ASSERT_FALSE(rows.empty());
    EXPECT_EQ(rows[0]["step"], 1);
    EXPECT_EQ(rows[0]["increment"], 1);
    server.kill_hard();
  }
  ServerProcess restarted(database());
  httplib::Client client = restarted.client();
  const std::string path = "/v1/jobs/" + std::to_string(job);
  const json done = wait_for_state(client, job, {"converged", "not_converged", "failed"});
  EXPECT_EQ(done["state"], reference["status"]) << done.dump();
  EXPECT_GE(done["attempts"].get<int>(), 2) << "the kill did not interrupt the run";
  EXPECT_EQ(result_numbers(get_json(client, path + "/result")), reference);

  // The stored rows: one per iteration, numbered 1..N over the whole run, each with its step and
  // increment, as in the local run's history.
  const json rows = get_json(client, path + "/iterations")["iterations"];
  ASSERT_EQ(rows.size(), reference["history"].size());
  for (std::size_t k = 0; k < rows.size(); ++k) {
    EXPECT_EQ(rows[k]["iteration"], static_cast<int>(k) + 1);
    EXPECT_EQ(rows[k]["step"], reference["history"][k]["step"]) << k;
    EXPECT_EQ(rows[k]["increment"], reference["history"][k]["increment"]) << k;
  }
  // ?after= keys on the global iteration number.
  const json after = get_json(client, path + "/iterations?after=2")["iterations"];
  ASSERT_EQ(after.size(), rows.size() - 2);
  EXPECT_EQ(after[0]["iteration"], 3);
  // The event stream carries the same rows.
  const httplib::Result events = client.Get(path + "/events");
  ASSERT_EQ(events->status, 200);
  EXPECT_NE(events->body.find("\"increment\":"), std::string::npos);
  EXPECT_NE(events->body.find("\"step\":2"), std::string::npos);
}

}  // namespace
}  // namespace saasgaps::testing
