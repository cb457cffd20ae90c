// A finished job's values at a point over HTTP (issue 32): GET /v1/jobs/{id}/probe answers what
// `saasgaps probe --json` prints for the same result, each material's side at an interface; the
// job resource carries the result's error_estimate; a point outside the mesh, a malformed point and
// an unknown field are problems naming what is wrong.
#include <gtest/gtest.h>

#include "service/service_fixture.hpp"
#include "support/two_material_block.hpp"

namespace saasgaps::testing {
namespace {

using nlohmann::json;
using ProbeService = ServiceFixture;

TEST_F(ProbeService, TheProbeRouteAnswersAsTheCommandAndTheJobShowsItsErrorEstimate) {
  const std::string body = two_material_block().dump();
  const json reference = solve_locally(body);
  ServerProcess server(database());
  httplib::Client client = server.client();
  const std::int64_t job = submit(client, body);
  const std::string path = "/v1/jobs/" + std::to_string(job);
  ASSERT_EQ(wait_for_state(client, job, {"converged", "not_converged", "failed"})["state"], "converged");

  const json shown = get_json(client, path);
  ASSERT_TRUE(shown["error_estimate"].is_object()) << shown.dump();
  EXPECT_EQ(shown["error_estimate"], reference["error_estimate"]);

  for (const char* at : {"0.5,1.5", "1,0.5", "2,2"}) {
    const httplib::Result r = client.Get(path + "/probe?at=" + at);
    ASSERT_TRUE(r);
    ASSERT_EQ(r->status, 200) << r->body;
    EXPECT_EQ(r->get_header_value("Content-Type"), "application/json");
    const CommandResult command =
        run_command({SAASGAPS_BINARY, "probe", (dir_ / "reference-result.json").string(), "--at", at, "--json"});
    ASSERT_EQ(command.exit_code, 0) << command.output;
    EXPECT_EQ(json::parse(r->body), json::parse(command.output)) << at;
  }
  const json interface = get_json(client, path + "/probe?at=1,0.5&field=sigma_theta,effective");
  ASSERT_EQ(interface["sides"].size(), 1U) << interface.dump();
  EXPECT_EQ(interface["values"].size(), 2U);
  EXPECT_NE(interface["values"]["sigma_theta"], interface["sides"][0]["values"]["sigma_theta"]);

  // Tagged by the result and the query: a client holding the answer gets 304.
  const httplib::Result first = client.Get(path + "/probe?at=0.5,1.5");
  const httplib::Result again = client.Get(path + "/probe?at=0.5,1.5", {{"If-None-Match", first->get_header_value("ETag")}});
  EXPECT_EQ(again->status, 304);

  EXPECT_NE(problem(client.Get(path + "/probe?at=5,-1"), 422)["detail"].get<std::string>().find("(5, -1)"),
            std::string::npos);
  EXPECT_NE(problem(client.Get(path + "/probe?at=1;2"), 400)["detail"].get<std::string>().find("query parameter at"),
            std::string::npos);
  EXPECT_NE(problem(client.Get(path + "/probe"), 400)["detail"].get<std::string>().find("at is required"),
            std::string::npos);
  EXPECT_NE(problem(client.Get(path + "/probe?at=1,1&field=bogus"), 400)["detail"].get<std::string>().find("bogus"),
            std::string::npos);
  problem(client.Get("/v1/jobs/999/probe?at=1,1"), 404);
}

}  // namespace
}  // namespace saasgaps::testing
