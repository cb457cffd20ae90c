// Fuzzing with a fixed seed: 1,000 model documents mutated from the examples, posted as jobs, and
// 1,000 raw HTTP requests built from mangled parts; then models and resume bodies with deep and wide
// nesting spliced in, and multipart imports with fuzzed parts. Whatever arrives: no crash, no 5xx,
// no hang, and every refusal of a document names its places with JSON Pointers.
#include <gtest/gtest.h>

#include <random>

#include "service/raw_http.hpp"
#include "service/service_fixture.hpp"
#include "support/json_mutation.hpp"

namespace saasgaps::testing {
namespace {

using nlohmann::json;
using Fuzz = ServiceFixture;

/// Every error of a 422 has a pointer and a detail.
void expect_pointed_problem(const httplib::Result& r, const std::string& sent) {
  ASSERT_EQ(r->status, 422) << r->body << "\n" << sent.substr(0, 300);
  const json problem = json::parse(r->body);
  ASSERT_FALSE(problem["errors"].empty()) << r->body;
  for (const json& e : problem["errors"]) {
    ASSERT_TRUE(e["pointer"].is_string()) << r->body;
    ASSERT_FALSE(e["detail"].get<std::string>().empty()) << r->body;
  }
}

/// Deep or wide JSON text: nested arrays, objects or both, `levels` deep (open only, when
/// `unclosed`), or an array of `levels` empty containers.
std::string nesting(std::mt19937& random, int levels) {
  const int kind = std::uniform_int_distribution<int>(0, 4)(random);
  std::string text;
  if (kind == 4) {  // wide: [[],{},[],...]
    text = "[";
    for (int k = 0; k < levels; ++k) text += k % 2 == 0 ? "[]," : "{\"k\":{}},";
    text.back() = ']';
    return text;
  }
  std::string closing;
  for (int k = 0; k < levels; ++k) {
    const bool object = kind == 1 || (kind == 2 && random() % 2 == 0);
    text += object ? "{\"n\":" : "[";
    closing += object ? '}' : ']';
  }
  if (kind == 3) return text;  // unclosed: not JSON, but the limit may come first
  return text + "0" + std::string(closing.rbegin(), closing.rend());
}

int random_levels(std::mt19937& random) {
  static const int levels[] = {1, 2, 10, 60, 61, 62, 63, 64, 65, 100, 1000, 100000};
  return levels[random() % std::size(levels)];
}

TEST_F(Fuzz, DeepAndWideNestingInModelsResumesAndImports) {
  ServerProcess server(database(), {"--header-timeout", "2", "--max-body", "4194304"});
  httplib::Client client = server.client();
  std::mt19937 random(1977);
  const json seed = json::parse(example_text("report-problem1.json"));
  std::vector<json::json_pointer> places;
  collect_pointers(seed, json::json_pointer(), places);
  const std::string marker = "\"@nesting@\"";
  for (int k = 0; k < 300; ++k) {
    // A value of the model (or a new member of an object) becomes the nesting.
    json document = seed;
    const json::json_pointer place = places[random() % places.size()];
    if (place.empty()) continue;
    json& parent = document[place.parent_pointer()];
    if (parent.is_object() && random() % 2 == 0) {
      parent["x" + std::to_string(k)] = "@nesting@";
    } else {
      document[place] = "@nesting@";
    }
    std::string text = document.dump();
    text.replace(text.find(marker), marker.size(), nesting(random, random_levels(random)));
    const httplib::Result r = client.Post("/v1/jobs", text, "application/json");
    ASSERT_TRUE(r) << "no answer to nesting " << k << " at " << place.to_string();
    ASSERT_LT(r->status, 500) << r->body;
    if (r->status == 202) {
      client.Post("/v1/jobs/" + json::parse(r->body)["id"].dump() + "/cancel", "", "application/json");
    } else if (r->status != 400) {  // 400: unclosed nesting within the limit is not JSON
      expect_pointed_problem(r, text);
    }
  }
  // Resume bodies: the first job exists (or a 404 answers first; either way not a crash).
  for (int k = 0; k < 50; ++k) {
    const std::string body = "{\"tensile_schedule\": " + nesting(random, random_levels(random)) + "}";
    const httplib::Result r = client.Post("/v1/jobs/1/resume", body, "application/json");
    ASSERT_TRUE(r) << "no answer to resume body " << k;
    ASSERT_LT(r->status, 500) << r->body;
  }
  // Multipart imports: the assembly part mutated or replaced by nesting, the mesh part present,
  // missing or misnamed, extra parts with odd names.
  const json assembly = json::parse(example_text("assemblies/ring-fit.assembly.json"));
  const std::string geo = example_text("assemblies/ring-fit.geo");
  for (int k = 0; k < 60; ++k) {
    httplib::MultipartFormDataItems parts;
    const int shape = static_cast<int>(random() % 4);
    const std::string part = shape == 0 ? nesting(random, random_levels(random))
                             : shape == 1 ? std::string(random() % 200, '\xFF')
                                          : mutate(assembly, random).dump();
    parts.push_back({random() % 10 == 0 ? "assembly2" : "assembly", part, "", "application/json"});
    switch (random() % 4) {
      case 0: break;  // no mesh
      case 1: parts.push_back({"mesh", geo, "other.geo", "text/plain"}); break;
      default: parts.push_back({"mesh", geo, "ring-fit.geo", "text/plain"}); break;
    }
    if (random() % 3 == 0) parts.push_back({"extra", nesting(random, random_levels(random)), "../x.json", ""});
    const httplib::Result r = client.Post("/v1/imports", parts);
    ASSERT_TRUE(r) << "no answer to import " << k;
    ASSERT_LT(r->status, 500) << r->body << "\n" << part.substr(0, 300);
    if (r->status == 422) expect_pointed_problem(r, part);
  }
  EXPECT_EQ(get_json(client, "/healthz")["status"], "ok");
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
    // ?cache=off: a mutation may repeat an earlier document, which the result cache would answer.
    const httplib::Result r = client.Post("/v1/jobs?cache=off", document.dump(), "application/json");
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
