// The service's result cache (docs/studies.md): POST /v1/jobs of a model solved before answers at
// once from the job that solved it (200, `cached: true`, no new job), whatever the key order, number
// spelling or whitespace of the text; ?cache=off solves afresh; another value is another model; the
// cache survives a restart of the server; a deleted job's entry goes with it (a miss, no false hit).
#include <gtest/gtest.h>

#include "service/server_process.hpp"
#include "service/service_fixture.hpp"

namespace saasgaps::testing {
namespace {

using nlohmann::json;

class ResultCacheService : public ServiceFixture {};

/// POST /v1/jobs expecting a cache hit: the job that answers.
std::int64_t cached_answer(httplib::Client& client, const std::string& body) {
  const httplib::Result r = client.Post("/v1/jobs", body, "application/json");
  EXPECT_TRUE(r);
  if (!r) return 0;
  EXPECT_EQ(r->status, 200) << r->body;
  const json job = json::parse(r->body);
  EXPECT_EQ(job.value("cached", false), true) << r->body;
  EXPECT_EQ(job["state"], "converged");
  EXPECT_EQ(r->get_header_value("Location"), "/v1/jobs/" + std::to_string(job["id"].get<std::int64_t>()));
  return job["id"].get<std::int64_t>();
}

TEST_F(ResultCacheService, ASolvedModelIsAnsweredFromItsJobAlsoAfterARestart) {
  const std::string body = example_text("quickstart-plane-strain-block.json");
  json respelled = json::parse(body);
  respelled["materials"][0]["table"][0]["E"] = 3e7;  // 30.0e6 spelled otherwise
  const std::string other_text = respelled.dump(3);  // another layout, keys sorted
  std::int64_t first = 0;
  {
    ServerProcess server(database());
    httplib::Client client = server.client();
    first = submit(client, body);
    EXPECT_EQ(wait_for_state(client, first, {"converged", "failed"})["state"], "converged");
    EXPECT_EQ(cached_answer(client, body), first);
    EXPECT_EQ(cached_answer(client, other_text), first);
    EXPECT_EQ(get_json(client, "/v1/jobs")["jobs"].size(), 1u);  // nothing new was queued or solved

    // Another value is another model.
    json changed = json::parse(body);
    changed["loads"]["pressures"][0]["normal"] = 1000.000001;
    const std::int64_t other = submit(client, changed.dump());
    EXPECT_EQ(wait_for_state(client, other, {"converged", "failed"})["state"], "converged");

    EXPECT_EQ(client.Post("/v1/jobs?cache=maybe", body, "application/json")->status, 400);
  }
  {
    // After a restart: still answered.
    ServerProcess server(database());
    httplib::Client client = server.client();
    EXPECT_EQ(cached_answer(client, body), first);
  }
}

TEST_F(ResultCacheService, CacheOffSolvesAfreshAndADeletedJobAnswersNothing) {
  ServerProcess server(database());
  httplib::Client client = server.client();
  const std::string body = example_text("quickstart-plane-strain-block.json");
  const std::int64_t first = submit(client, body);
  EXPECT_EQ(wait_for_state(client, first, {"converged", "failed"})["state"], "converged");
  const httplib::Result forced = client.Post("/v1/jobs?cache=off", body, "application/json");
  ASSERT_TRUE(forced);
  ASSERT_EQ(forced->status, 202) << forced->body;
  const std::int64_t second = json::parse(forced->body)["id"].get<std::int64_t>();
  EXPECT_NE(second, first);
  EXPECT_EQ(wait_for_state(client, second, {"converged", "failed"})["state"], "converged");
  EXPECT_EQ(cached_answer(client, body), second);  // the newest solve of the model answers

  // Deleting the job deletes its entry (the key's one entry is the newest solve): a miss, solved again.
  ASSERT_EQ(client.Delete("/v1/jobs/" + std::to_string(second))->status, 204);
  const httplib::Result missed = client.Post("/v1/jobs", body, "application/json");  // the cache on
  ASSERT_TRUE(missed);
  ASSERT_EQ(missed->status, 202) << missed->body;
  const std::int64_t third = json::parse(missed->body)["id"].get<std::int64_t>();
  EXPECT_GT(third, second);
  EXPECT_EQ(wait_for_state(client, third, {"converged", "failed"})["state"], "converged");
  EXPECT_EQ(cached_answer(client, body), third);
}

}  // namespace
}  // namespace saasgaps::testing
