// Fuzzing with a fixed seed: 1,000 model documents mutated from the examples, posted as jobs, and
// 1,000 raw HTTP requests built from mangled parts. Whatever arrives: no crash, no 5xx, no hang,
// and every refusal of a model names its places with JSON Pointers.
#include <gtest/gtest.h>

#include <random>

#include "service/raw_http.hpp"
#include "service/service_fixture.hpp"

namespace saasgaps::testing {
namespace {

using nlohmann::json;
using Fuzz = ServiceFixture;

/// Every value's pointer in a document, for picking what to mutate.
void collect_pointers(const json& value, const json::json_pointer& here, std::vector<json::json_pointer>& out) {
  out.push_back(here);
  if (value.is_object()) {
    for (const auto& [key, child] : value.items()) collect_pointers(child, here / key, out);
  } else if (value.is_array()) {
    for (std::size_t i = 0; i < value.size(); ++i) collect_pointers(value[i], here / i, out);
  }
}

json random_value(std::mt19937& random) {
  switch (std::uniform_int_distribution<int>(0, 11)(random)) {
    case 0: return nullptr;
    case 1: return true;
    case 2: return -1;
    case 3: return 0;
    case 4: return 1e308;
    case 5: return -1e-320;
    case 6: return "\xF0\x9F\x92\xA5 text";
    case 7: return json::array();
    case 8: return json::object();
    case 9: return 123456789012345LL;
    case 10: return json::array({1, 2, 3, 4, 5});
    default: return std::uniform_real_distribution<double>(-10.0, 10.0)(random);
  }
}

/// 1-3 mutations: replace a value, delete a member or element, or duplicate an array element.
json mutate(json document, std::mt19937& random) {
  const int count = std::uniform_int_distribution<int>(1, 3)(random);
  for (int m = 0; m < count; ++m) {
    std::vector<json::json_pointer> pointers;
    collect_pointers(document, json::json_pointer(), pointers);
    const json::json_pointer target = pointers[std::uniform_int_distribution<std::size_t>(0, pointers.size() - 1)(random)];
    const int kind = std::uniform_int_distribution<int>(0, 3)(random);
    if (target.empty()) {
      document = kind == 0 ? random_value(random) : document;
      continue;
    }
    json& parent = document[target.parent_pointer()];
    if (kind == 0 || kind == 1) {
      document[target] = random_value(random);
    } else if (kind == 2) {
      if (parent.is_object()) parent.erase(target.back());
      if (parent.is_array()) parent.erase(static_cast<std::size_t>(std::stoul(target.back())));
    } else if (parent.is_array()) {
      parent.push_back(document[target]);
    }
  }
  return document;
}

TEST_F(Fuzz, ThousandMutatedModelsAndThousandRawRequests) {
  ServerProcess server(database(), {"--header-timeout", "2", "--max-body", "1048576"});
  httplib::Client client = server.client();
  std::mt19937 random(1976);
  const std::vector<json> seeds = {json::parse(example_text("report-problem1.json")),
                                   json::parse(example_text("report-problem2.json")),
                                   json::parse(example_text("report-beam-model-a.json")),
                                   json::parse(example_text("quickstart-plane-strain-block.json"))};
  int accepted = 0, refused = 0;
  for (int k = 0; k < 1000; ++k) {
    const json document = mutate(seeds[static_cast<std::size_t>(k) % seeds.size()], random);
    const httplib::Result r = client.Post("/v1/jobs", document.dump(), "application/json");
    ASSERT_TRUE(r) << "no answer to document " << k << ": " << document.dump();
    ASSERT_LT(r->status, 500) << r->body << "\n" << document.dump();
    if (r->status == 202) {
      ++accepted;
      // Mutated models may iterate for long: stop each at once; only the answer matters here.
      client.Post("/v1/jobs/" + json::parse(r->body)["id"].dump() + "/cancel", "", "application/json");
      continue;
    }
    ++refused;
    ASSERT_EQ(r->status, 422) << r->body;
    const json problem = json::parse(r->body);
    ASSERT_FALSE(problem["errors"].empty()) << r->body;
    for (const json& e : problem["errors"]) {
      ASSERT_TRUE(e["pointer"].is_string()) << r->body;
      ASSERT_FALSE(e["detail"].get<std::string>().empty()) << r->body;
    }
  }
  EXPECT_GT(refused, 500);
  EXPECT_GT(accepted, 20);
  // Every accepted job comes to an end.
  for (const json& job : get_json(client, "/v1/jobs?page_size=100")["jobs"]) {
    wait_for_state(client, job["id"].get<std::int64_t>(), {"converged", "not_converged", "failed", "cancelled"},
                   std::chrono::seconds(60));
  }

  const std::vector<std::string> methods = {"GET", "POST", "DELETE", "PUT", "PATCH", "HEAD", "OPTIONS", "FOO", "G\xFF" "T", ""};
  const std::vector<std::string> paths = {"/v1/jobs", "/v1/jobs/1", "/v1/jobs/1/result", "/v1/jobs/1/events",
                                          "/v1/jobs/1/plots/effective.png?width=99999", "/v1/jobs/1/cancel",
                                          "/v1/jobs/1/resume", "/v1/jobs/99999999999999999999", "/healthz",
                                          "/metrics", "/readyz", "/%00%ff", "/v1/jobs?state=\xC3\x28", "*",
                                          "/" + std::string(9000, 'a'), "/v1/jobs/1/plots/x.svg?deformed=-1e999"};
  const std::vector<std::string> headers = {"Host: 127.0.0.1", "Host: evil.example", "Content-Type: application/json",
                                            "Content-Type: text/plain", "Content-Length: 5", "Content-Length: -1",
                                            "Content-Length: 99999999999999999999", "Transfer-Encoding: chunked",
                                            "Transfer-Encoding: gzip, chunked", "Origin: http://evil.example",
                                            "Idempotency-Key: \xFF\xFE", "Authorization: Bearer x",
                                            "Last-Event-ID: 1e9", "If-None-Match: *", "X-Request-Id: \x01\x02",
                                            "Expect: 100-continue", "Range: bytes=5-1", "Connection: close",
                                            "Bad Header Without Colon", ": empty name", "X: " + std::string(9000, 'b')};
  const std::vector<std::string> bodies = {"", "{}", "{\"tensile_schedule\": [1]}", "5\r\nhello\r\n0\r\n\r\n",
                                           "zz\r\n", "{\"schema_version\": 1", std::string(200, '\xFF'), "null"};
  int answered = 0;
  for (int k = 0; k < 1000; ++k) {
    std::string request = methods[random() % methods.size()] + " " + paths[random() % paths.size()] +
                          (random() % 10 == 0 ? " HTTP/1.0" : " HTTP/1.1") + "\r\n";
    const int header_count = static_cast<int>(random() % 5);
    for (int h = 0; h < header_count; ++h) request += headers[random() % headers.size()] + "\r\n";
    request += "\r\n" + bodies[random() % bodies.size()];
    bool timed_out = false;
    const std::string answer = raw_exchange(server.port(), request, std::chrono::seconds(5), &timed_out);
    ASSERT_FALSE(timed_out) << "no end to the answer for:\n" << request;
    const int status = status_of(answer);
    ASSERT_LT(status, 500) << "request:\n" << request << "\nanswer:\n" << answer;
    if (status > 0) ++answered;
  }
  EXPECT_GT(answered, 900);
  EXPECT_EQ(get_json(client, "/healthz")["status"], "ok");
}

}  // namespace
}  // namespace saasgaps::testing
