// A transient heat conduction run through the service: its thermal rows stored (one per output
// time), served by /thermal and streamed as `thermal` events; a run that ends not converged inside
// its first load step, resumed with more iterations, ends with exactly the result of an
// uninterrupted `saasgaps solve`, and its repeated thermal rows change nothing.
#include <gtest/gtest.h>

#include "service/service_fixture.hpp"
#include "support/transient_heating.hpp"

namespace saasgaps::testing {
namespace {

using nlohmann::json;
using ThermalService = ServiceFixture;

std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

TEST_F(ThermalService, ThermalRowsAreStoredAndStreamedAndAResumeMidWayChangesNoResult) {
  json model = transient_heating("ring-shrink-fit-plane-strain.json");
  const json reference = result_numbers(solve_locally(model.dump()));
  const int iterations = reference["iterations"].get<int>();
  ASSERT_EQ(reference["status"], "converged");
  ASSERT_GT(iterations, 6);
  // max_iterations counts per increment: 5 stops the run inside the first load step (which takes
  // more), with the conduction of every output time done.
  model["solver"]["max_iterations"] = 5;

  ServerProcess server(database());
  httplib::Client client = server.client();
  const std::int64_t job = submit(client, model.dump());
  const std::string path = "/v1/jobs/" + std::to_string(job);
  ASSERT_EQ(wait_for_state(client, job, {"converged", "not_converged", "failed"})["state"], "not_converged");
  const json first = get_json(client, path + "/thermal");
  ASSERT_EQ(first["thermal"].size(), 4U) << first.dump();
  for (std::size_t k = 0; k < 4; ++k) {
    EXPECT_EQ(first["thermal"][k]["index"], static_cast<int>(k) + 1);
    EXPECT_EQ(first["thermal"][k]["kind"], "transient");
    EXPECT_EQ(first["thermal"][k]["time_steps"], 5 * static_cast<int>(k + 1));
  }
  EXPECT_EQ(get_json(client, path + "/thermal?after=3")["thermal"].size(), 1U);

  const httplib::Result resumed = client.Post(path + "/resume", json{{"max_iterations", 40}}.dump(), "application/json");
  ASSERT_TRUE(resumed);
  ASSERT_EQ(resumed->status, 202) << resumed->body;
  const json done = wait_for_state(client, job, {"converged", "not_converged", "failed"});
  ASSERT_EQ(done["state"], "converged") << done.dump();
  const json result = result_numbers(get_json(client, path + "/result"));
  EXPECT_EQ(result["nodes"], reference["nodes"]);
  EXPECT_EQ(result["elements"], reference["elements"]);
  EXPECT_EQ(result["gaps"], reference["gaps"]);
  EXPECT_EQ(result["iterations"], reference["iterations"]);
  // The resumed run computed the same rows again: stored once, announced once.
  EXPECT_EQ(get_json(client, path + "/thermal"), first);
  const httplib::Result events = client.Get(path + "/events");
  ASSERT_EQ(events->status, 200);
  EXPECT_EQ(count(events->body, "event: thermal\n"), 4U);
}

}  // namespace
}  // namespace saasgaps::testing
