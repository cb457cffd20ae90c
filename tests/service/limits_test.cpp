// Issue 17 items 3 and 5 against a real server: documents nested 10^5 deep (a model's nodes and
// description, a resume body, the assembly part of an import) are refused with 422 at the pointer of
// the limit and the server lives on; a Content-Length beyond --max-body is answered 413 at once; a
// resume body is read as strictly as a model (repeated keys, numbers beyond a double); a job id in a
// path has one spelling.
#include <gtest/gtest.h>

#include <csignal>
#include <string>

#include "service/raw_http.hpp"
#include "service/service_fixture.hpp"

namespace saasgaps::testing {
namespace {

using nlohmann::json;
using Limits = ServiceFixture;

constexpr int deep = 100000;

std::string nested_arrays(int levels) { return std::string(levels, '[') + std::string(levels, ']'); }

std::string nested_objects(int levels) {
  std::string text;
  for (int k = 0; k < levels; ++k) text += "{\"a\":";
  return text + "1" + std::string(levels, '}');
}

std::string repeated(const std::string& token, int count) {
  std::string text;
  for (int k = 0; k < count; ++k) text += token;
  return text;
}

/// The 422 of the nesting limit: one error at `pointer` naming the limit.
void expect_too_deep(const httplib::Result& r, const std::string& pointer) {
  ASSERT_TRUE(r) << "no answer: " << httplib::to_string(r.error());
  ASSERT_EQ(r->status, 422) << r->body;
  const json problem = json::parse(r->body);
  ASSERT_EQ(problem["errors"].size(), 1u) << r->body;
  EXPECT_EQ(problem["errors"][0]["pointer"], pointer) << r->body;
  EXPECT_NE(problem["errors"][0]["detail"].get<std::string>().find("deeper than 64 levels"), std::string::npos) << r->body;
  EXPECT_NE(problem["detail"].get<std::string>().find(pointer), std::string::npos) << r->body;
}

void expect_alive(httplib::Client& client) {
  const httplib::Result r = client.Get("/healthz");
  ASSERT_TRUE(r) << "the server died";
  EXPECT_EQ(r->status, 200);
}

TEST_F(Limits, DeeplyNestedDocumentsAreRefusedAndTheServerLives) {
  ServerProcess server(database());
  httplib::Client client = server.client();
  const std::string model = example_text("report-problem1.json");

  // 10^5 arrays as a node: a 200 KB body.
  std::string deep_nodes = model;
  deep_nodes.replace(deep_nodes.find("\"nodes\": ["), 10, "\"nodes\": [" + nested_arrays(deep) + ",");
  expect_too_deep(client.Post("/v1/jobs", deep_nodes, "application/json"), "/nodes" + repeated("/0", 63));
  expect_alive(client);

  std::string deep_description = model;
  deep_description.replace(0, 1, "{\"description\": " + nested_objects(deep) + ",");
  expect_too_deep(client.Post("/v1/jobs", deep_description, "application/json"), "/description" + repeated("/a", 63));
  expect_alive(client);

  // A resume body, on a job that exists.
  const std::int64_t job = submit(client, model);
  wait_for_state(client, job, {"converged", "not_converged", "failed"});
  const std::string resume = "/v1/jobs/" + std::to_string(job) + "/resume";
  expect_too_deep(client.Post(resume, "{\"tensile_schedule\": " + nested_arrays(deep) + "}", "application/json"),
                  "/tensile_schedule" + repeated("/0", 63));
  expect_alive(client);

  // The assembly part of an import: `[` x 10^5.
  const httplib::MultipartFormDataItems upload{
      {"assembly", std::string(deep, '['), "", "application/json"},
      {"mesh", example_text("assemblies/ring-fit.geo"), "ring-fit.geo", "text/plain"}};
  expect_too_deep(client.Post("/v1/imports", upload), repeated("/0", 64));
  expect_alive(client);
  // Nothing of it was queued.
  EXPECT_EQ(get_json(client, "/v1/jobs")["jobs"].size(), 1u);
}

TEST_F(Limits, AContentLengthBeyondMaxBodyIsAnswered413AtOnce) {
  ServerProcess server(database(), {"--max-body", "1048576"});
  bool timed_out = false;
  // 10^12 bytes announced, one sent: the answer may not wait for the rest.
  const std::string answer = raw_exchange(server.port(),
                                          "POST /v1/jobs HTTP/1.1\r\nHost: 127.0.0.1\r\nContent-Type: application/json\r\n"
                                          "Content-Length: 1000000000000\r\n\r\n{",
                                          std::chrono::seconds(5), &timed_out);
  EXPECT_FALSE(timed_out) << answer;
  ASSERT_EQ(status_of(answer), 413) << answer;
  EXPECT_NE(answer.find("--max-body"), std::string::npos) << answer;
  EXPECT_NE(answer.find("1048576"), std::string::npos) << answer;
  // Beyond 64 bits too.
  EXPECT_EQ(status_of(raw_exchange(server.port(), "POST /v1/jobs HTTP/1.1\r\nHost: 127.0.0.1\r\n"
                                                  "Content-Type: application/json\r\nContent-Length: 99999999999999999999999\r\n\r\n",
                                   std::chrono::seconds(5))),
            413);
  // At the limit, the body is read as before (and judged: not a model).
  httplib::Client client = server.client();
  const httplib::Result at_limit = client.Post("/v1/jobs", std::string(1048576, ' '), "application/json");
  ASSERT_TRUE(at_limit);
  EXPECT_EQ(at_limit->status, 400) << at_limit->body;
  expect_alive(client);
}

TEST_F(Limits, ResumeBodiesAreReadAsStrictlyAsModels) {
  ServerProcess server(database());
  httplib::Client client = server.client();
  const std::int64_t job = submit(client, example_text("report-problem1.json"));
  wait_for_state(client, job, {"converged", "not_converged", "failed"});
  const std::string resume = "/v1/jobs/" + std::to_string(job) + "/resume";

  const json twice = problem(client.Post(resume, "{\"max_iterations\": 5, \"max_iterations\": 7}", "application/json"), 422);
  ASSERT_EQ(twice["errors"].size(), 1u) << twice.dump();
  EXPECT_EQ(twice["errors"][0]["pointer"], "/max_iterations");
  EXPECT_NE(twice["errors"][0]["detail"].get<std::string>().find("more than once"), std::string::npos) << twice.dump();

  const json huge = problem(client.Post(resume, "{\"max_iterations\": 1e999}", "application/json"), 422);
  ASSERT_EQ(huge["errors"].size(), 1u) << huge.dump();
  EXPECT_EQ(huge["errors"][0]["pointer"], "/max_iterations");
  EXPECT_NE(huge["errors"][0]["detail"].get<std::string>().find("number overflow parsing '1e999'"), std::string::npos) << huge.dump();

  // Still 400 for text that is not JSON at all.
  problem(client.Post(resume, "{\"max_iterations\": ", "application/json"), 400);
}

TEST_F(Limits, JobIdsInPathsHaveOneSpelling) {
  ServerProcess server(database());
  httplib::Client client = server.client();
  const std::int64_t job = submit(client, example_text("report-problem1.json"));
  ASSERT_EQ(job, 1);
  wait_for_state(client, job, {"converged", "not_converged", "failed"});
  EXPECT_EQ(client.Get("/v1/jobs/1")->status, 200);
  EXPECT_EQ(client.Get("/v1/jobs/1/iterations?after=0")->status, 200);
  for (const std::string path : {"/v1/jobs/01", "/v1/jobs/%31", "/v1/jobs/0001/iterations", "/v1/jobs/%31/model",
                                 "/v1/jobs/1%30", "/v1/jobs/0"}) {
    // Raw, so that no client library normalizes the target.
    const std::string answer =
        raw_exchange(server.port(), "GET " + path + " HTTP/1.1\r\nHost: 127.0.0.1\r\nConnection: close\r\n\r\n");
    EXPECT_EQ(status_of(answer), 404) << path << "\n" << answer;
  }
  const std::string cancel =
      raw_exchange(server.port(), "POST /v1/jobs/%31/cancel HTTP/1.1\r\nHost: 127.0.0.1\r\nContent-Length: 0\r\n"
                                  "Connection: close\r\n\r\n");
  EXPECT_EQ(status_of(cancel), 404) << cancel;
  expect_alive(client);
}

TEST_F(Limits, ARequestRefusedBeforeItsBodyIsReadStillGetsItsAnswer) {
  std::ofstream(dir_ / "token") << "s3cret\n";
  ServerProcess server(database(), {"--token-file", (dir_ / "token").string()});
  httplib::Client client = server.client();
  // 8 MB, far beyond the socket buffers: the client is still sending when the server answers. The
  // server drains the unread body, so the client reads the answer rather than a reset.
  const std::string body(8u << 20, ' ');
  std::signal(SIGPIPE, SIG_IGN);  // a reset is a failed expectation here, not the end of the test
  for (int round = 0; round < 3; ++round) {
    const httplib::Result unauthorized = client.Post("/v1/jobs", body, "application/json");
    ASSERT_TRUE(unauthorized) << "no answer: " << httplib::to_string(unauthorized.error());
    EXPECT_EQ(unauthorized->status, 401) << unauthorized->body;
  }
  client.set_bearer_token_auth("s3cret");
  const httplib::Result not_json = client.Post("/v1/jobs", body, "text/plain");
  ASSERT_TRUE(not_json) << "no answer: " << httplib::to_string(not_json.error());
  EXPECT_EQ(not_json->status, 415) << not_json->body;
  expect_alive(client);
}

}  // namespace
}  // namespace saasgaps::testing
