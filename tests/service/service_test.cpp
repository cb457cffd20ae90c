// The HTTP job service, driven like a user drives it: a real `saasgaps serve` process on an
// ephemeral loopback port with a real SQLite file; bad requests; kill -9 in the middle of a long job
// and a restart; cancel and resume; several jobs at once; event streams.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <set>
#include <thread>

#include "service/job_client.hpp"
#include "service/long_job_model.hpp"
#include "service/server_process.hpp"
#include "service/service_fixture.hpp"

namespace saasgaps::testing {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

/// The shared fixture (a directory per test, submit, problem, solve_locally); the job helpers of
/// job_client.hpp are shared with the worker and Slurm tests.
class Service : public ServiceFixture {};

TEST_F(Service, ReportProblem3GivesTheSameResultAsSolve) {
  ServerProcess server(database());
  httplib::Client client = server.client();
  const std::string body = example_text("report-problem3-case3.json");
  const std::int64_t job = submit(client, body);
  const json done = wait_for_state(client, job, {"converged", "not_converged", "failed"});
  EXPECT_EQ(done["state"], "converged");
  EXPECT_EQ(done["attempts"], 1);
  EXPECT_EQ(done["iteration"], done["last_row"]["iteration"]);
  const json result = get_json(client, "/v1/jobs/" + std::to_string(job) + "/result");
  EXPECT_EQ(result_numbers(result), result_numbers(solve_locally(body)));
  // Streamed from the database (64 KiB pieces), its length known up front; compact text.
  const httplib::Result raw = client.Get("/v1/jobs/" + std::to_string(job) + "/result");
  ASSERT_TRUE(raw);
  EXPECT_EQ(raw->get_header_value("Content-Length"), std::to_string(raw->body.size()));
  EXPECT_GT(raw->body.size(), std::size_t{50000});
  EXPECT_EQ(raw->body.find('\n'), std::string::npos);
  EXPECT_EQ(json::parse(client.Get("/v1/jobs/" + std::to_string(job) + "/model")->body), json::parse(body));
  const json rows = get_json(client, "/v1/jobs/" + std::to_string(job) + "/iterations?after=10")["iterations"];
  ASSERT_FALSE(rows.empty());
  EXPECT_EQ(rows.front()["iteration"], 11);
}

/// POST /v1/imports: an assembly and its mesh as multipart/form-data give the model document that
/// `saasgaps import` writes; with ?submit=true a job; a bad group is a 422 naming its pointer.
TEST_F(Service, ImportsAnUploadedAssembly) {
  ServerProcess server(database());
  httplib::Client client = server.client();
  const std::string assembly = example_text("assemblies/ring-fit.assembly.json");
  const std::string geo = example_text("assemblies/ring-fit.geo");
  const httplib::MultipartFormDataItems upload{{"assembly", assembly, "", "application/json"},
                                              {"mesh", geo, "ring-fit.geo", "text/plain"}};
  const httplib::Result imported = client.Post("/v1/imports", upload);
  ASSERT_TRUE(imported);
  ASSERT_EQ(imported->status, 200) << imported->body;
  const fs::path model = dir_ / "model.json";
  const CommandResult cli = run_command({SAASGAPS_BINARY, "import",
                                         std::string(SAASGAPS_EXAMPLES_DIR) + "/assemblies/ring-fit.assembly.json",
                                         "-o", model.string()});
  ASSERT_EQ(cli.exit_code, 0) << cli.output;
  std::ifstream in(model);
  EXPECT_EQ(json::parse(imported->body), json::parse(in));

  const httplib::Result queued = client.Post("/v1/imports?submit=true", upload);
  ASSERT_TRUE(queued);
  ASSERT_EQ(queued->status, 202) << queued->body;
  const std::int64_t job = json::parse(queued->body)["id"].get<std::int64_t>();
  EXPECT_EQ(wait_for_state(client, job, {"converged", "not_converged", "failed"})["state"], "converged");

  json bad = json::parse(assembly);
  bad["regions"][0]["group"] = "inner_rin";
  const json invalid = problem(client.Post("/v1/imports", httplib::MultipartFormDataItems{
                                                              {"assembly", bad.dump(), "", "application/json"},
                                                              {"mesh", geo, "ring-fit.geo", "text/plain"}}),
                               422);
  ASSERT_EQ(invalid["errors"].size(), 1u) << invalid.dump();
  EXPECT_EQ(invalid["errors"][0]["pointer"], "/regions/0/group");
  // Titled by what was uploaded, not "Invalid model".
  EXPECT_EQ(invalid["title"], "Invalid assembly");
  EXPECT_EQ(invalid["detail"], "1 error in the assembly document");

  // A file the assembly names but no part carries: named as the client knows it, not by a path on
  // the server.
  const json missing = problem(client.Post("/v1/imports", httplib::MultipartFormDataItems{
                                                              {"assembly", assembly, "", "application/json"}}),
                               422);
  ASSERT_EQ(missing["errors"].size(), 1u) << missing.dump();
  EXPECT_EQ(missing["errors"][0]["pointer"], "/mesh");
  const std::string detail = missing["errors"][0]["detail"];
  EXPECT_NE(detail.find("no part of the upload carries the file \"ring-fit.geo\""), std::string::npos) << detail;
  EXPECT_EQ(detail.find("saasgaps-upload-"), std::string::npos) << detail;
  EXPECT_EQ(detail.find('/'), std::string::npos) << detail;

  bad = json::parse(assembly);
  bad["mesh"] = "../../etc/passwd.msh";
  const json escaped = problem(client.Post("/v1/imports", httplib::MultipartFormDataItems{
                                                              {"assembly", bad.dump(), "", "application/json"},
                                                              {"mesh", geo, "ring-fit.geo", "text/plain"}}),
                               422);
  EXPECT_EQ(escaped["errors"][0]["pointer"], "/mesh");
  // JSON (curl --json) is not an upload: 415 as for any POST body of the wrong type.
  const json not_upload = problem(client.Post("/v1/imports", assembly, "application/json"), 415);
  EXPECT_NE(not_upload["detail"].get<std::string>().find("multipart/form-data"), std::string::npos) << not_upload.dump();
}

TEST_F(Service, PlotsAndVtuOfAStoredResult) {
  ServerProcess server(database());
  httplib::Client client = server.client();
  const std::int64_t job = submit(client, example_text("report-problem3-case1.json"));
  wait_for_state(client, job, {"converged"});
  const std::string path = "/v1/jobs/" + std::to_string(job);
  const httplib::Result png = client.Get(path + "/plots/effective.png?deformed=auto&width=640&height=400");
  ASSERT_EQ(png->status, 200) << png->body;
  EXPECT_EQ(png->get_header_value("Content-Type"), "image/png");
  EXPECT_EQ(png->body.substr(1, 3), "PNG");
  const httplib::Result svg = client.Get(path + "/plots/closure.svg");
  ASSERT_EQ(svg->status, 200) << svg->body;
  EXPECT_EQ(svg->get_header_value("Content-Type"), "image/svg+xml");
  EXPECT_NE(svg->body.find("<svg"), std::string::npos);
  EXPECT_EQ(client.Get(path + "/plots/convergence.png")->status, 200);
  const httplib::Result vtu = client.Get(path + "/result.vtu");
  ASSERT_EQ(vtu->status, 200);
  EXPECT_NE(vtu->body.find("<UnstructuredGrid>"), std::string::npos);
  // An unknown field is a 404 that lists the fields; bad options are a 400.
  const json unknown = problem(client.Get(path + "/plots/stress_of_doom.png"), 404);
  EXPECT_NE(unknown["detail"].get<std::string>().find("sigma_theta"), std::string::npos) << unknown.dump();
  problem(client.Get(path + "/plots/effective.png?deformed=lots"), 400);
  problem(client.Get(path + "/plots/effective.png?width=5"), 400);
  // The command line's limit (saasgaps plot --width): one range, plot::Canvas::max_side.
  const json wide = problem(client.Get(path + "/plots/effective.png?width=4001"), 400);
  EXPECT_NE(wide["detail"].get<std::string>().find("4000"), std::string::npos) << wide.dump();
  // Cylindrical components about a centre (the beam is plane stress); a bad centre or colour map
  // is a 400 naming the parameter.
  const httplib::Result hoop = client.Get(path + "/plots/sigma_hoop.csv?centre=10,-5&path=0.5,0.5;8.5,0.5&samples=3");
  ASSERT_EQ(hoop->status, 200) << hoop->body;
  EXPECT_NE(hoop->body.find("(10, -5)"), std::string::npos) << hoop->body;
  EXPECT_NE(problem(client.Get(path + "/plots/sigma_hoop.png?centre=10"), 400)["detail"].get<std::string>().find("centre"),
            std::string::npos);
  problem(client.Get(path + "/plots/effective.png?colormap=jet"), 400);
  EXPECT_EQ(client.Get(path + "/plots/sigma_r.png?colormap=diverging&levels=quantile")->status, 200);
  // The heat flux of a run without heat: a 409 (the result does not fit the plot) that says why.
  const json no_heat = problem(client.Get(path + "/plots/heat_flux.png"), 409);
  EXPECT_NE(no_heat["detail"].get<std::string>().find("thermal"), std::string::npos) << no_heat.dump();
  // The dashboard is served from the binary.
  const httplib::Result page = client.Get("/");
  ASSERT_EQ(page->status, 200);
  EXPECT_NE(page->body.find("SAASGAPS"), std::string::npos);
  EXPECT_EQ(client.Get("/app.js")->status, 200);
}

TEST_F(Service, ThermalRunPlotsTemperatureAndHeatFlux) {
  ServerProcess server(database());
  httplib::Client client = server.client();
  // The quickstart block with its temperatures computed: bottom held at 500, a source in the steel.
  json model = json::parse(example_text("quickstart-plane-strain-block.json"));
  model["loads"].erase("temperatures");
  model["materials"][0]["table"][0]["k"] = 0.6;
  model["thermal"] = json::parse(R"({"type": "steady",
    "boundary": [{"edges": [[1, 2], [2, 3]], "temperature": 500}],
    "sources": [{"material": 1, "power_density": 2.0}]})");
  const std::int64_t job = submit(client, model.dump());
  wait_for_state(client, job, {"converged"});
  const std::string path = "/v1/jobs/" + std::to_string(job);
  for (const char* field : {"temperature", "heat_flux"}) {
    const httplib::Result png = client.Get(path + "/plots/" + field + ".png");
    ASSERT_EQ(png->status, 200) << field << ": " << png->body;
    EXPECT_EQ(png->body.substr(1, 3), "PNG") << field;
  }
}

TEST_F(Service, EveryBadRequestClassGetsItsStatusAndAPointer) {
  ServerProcess server(database(), {"--max-body", "65536"});
  httplib::Client client = server.client();
  // 400: not JSON.
  EXPECT_NE(problem(client.Post("/v1/jobs", "{not json", "application/json"), 400)["detail"].get<std::string>().find("not JSON"),
            std::string::npos);
  // 422: an invalid model, with every error's pointer.
  json model = json::parse(example_text("report-problem1.json"));
  model["elements"][0]["nodes"] = {2, 3, 15, 14};  // clockwise
  model["gaps"]["extrapolation_factor"] = 1.5;
  const json invalid = problem(client.Post("/v1/jobs", model.dump(), "application/json"), 422);
  std::set<std::string> pointers;
  for (const json& e : invalid["errors"]) pointers.insert(e["pointer"].get<std::string>());
  EXPECT_TRUE(pointers.count("/elements/0/nodes")) << invalid.dump();
  EXPECT_TRUE(pointers.count("/gaps/extrapolation_factor")) << invalid.dump();
  // 413: over --max-body.
  EXPECT_EQ(problem(client.Post("/v1/jobs", std::string(100000, ' ') + "{}", "application/json"), 413)["status"], 413);
  // 404: unknown job, unknown route, result before any exists.
  problem(client.Get("/v1/jobs/424242"), 404);
  problem(client.Get("/v1/nothing-here"), 404);
  // 400: bad query parameters.
  problem(client.Get("/v1/jobs?page_size=0"), 400);
  problem(client.Get("/v1/jobs?state=sleeping"), 400);
  // 422: a resume body with bad values, each with its pointer.
  const std::int64_t job = submit(client, example_text("report-problem1.json"));
  wait_for_state(client, job, {"converged"});
  const json bad_resume = problem(
      client.Post("/v1/jobs/" + std::to_string(job) + "/resume", R"({"tensile_schedule": [5, -1], "speed": 3})", "application/json"),
      422);
  pointers.clear();
  for (const json& e : bad_resume["errors"]) pointers.insert(e["pointer"].get<std::string>());
  EXPECT_TRUE(pointers.count("/tensile_schedule/1")) << bad_resume.dump();
  EXPECT_TRUE(pointers.count("/speed")) << bad_resume.dump();
  EXPECT_EQ(bad_resume["title"], "Invalid resume settings");
  EXPECT_EQ(bad_resume["detail"], "2 errors in the resume settings");
  // 409: resuming a converged job.
  problem(client.Post("/v1/jobs/" + std::to_string(job) + "/resume", "{}", "application/json"), 409);
  // 409: cancelling a finished job.
  problem(client.Post("/v1/jobs/" + std::to_string(job) + "/cancel", "", "application/json"), 409);
}

/// Issue 22: a body pulled off its gaps is a failed job saying why, never a green "converged"; a gap
/// angle along the gap is refused with 422 at its pointer.
TEST_F(Service, APulledOffBodyFailsAndAGapAngleAlongTheGapIs422) {
  ServerProcess server(database());
  httplib::Client client = server.client();
  json pulled = json::parse(example_text("report-problem1.json"));
  for (auto& p : pulled["loads"]["pressures"]) p["normal"] = -p["normal"].get<double>();
  const std::int64_t job = submit(client, pulled.dump());
  const json done = wait_for_state(client, job, {"converged", "not_converged", "failed"});
  EXPECT_EQ(done["state"], "failed") << done.dump();
  EXPECT_NE(done["error"].get<std::string>().find("the contact problem has no solution"), std::string::npos)
      << done.dump();

  json along = json::parse(example_text("report-problem1.json"));
  along["gaps"]["elements"][3]["angle"] = 0.0;
  const json refused = problem(client.Post("/v1/jobs", along.dump(), "application/json"), 422);
  ASSERT_EQ(refused["errors"].size(), 1U) << refused.dump();
  EXPECT_EQ(refused["errors"][0]["pointer"], "/gaps/elements/3/angle");
  EXPECT_NE(refused["errors"][0]["detail"].get<std::string>().find("angle 0 does not run across gap element 13"),
            std::string::npos)
      << refused.dump();
}

TEST_F(Service, ConflictsWhileAJobRuns) {
  ServerProcess server(database());
  httplib::Client client = server.client();
  const std::int64_t job = submit(client, tilted_block_document(120).dump());
  wait_for_state(client, job, {"running"});
  const std::string path = "/v1/jobs/" + std::to_string(job);
  problem(client.Get(path + "/result"), 409);
  problem(client.Post(path + "/resume", "{}", "application/json"), 409);
  problem(client.Delete(path), 409);
  EXPECT_EQ(client.Post(path + "/cancel", "", "application/json")->status, 202);
  EXPECT_EQ(wait_for_state(client, job, {"cancelled", "converged"})["state"], "cancelled");
  EXPECT_EQ(client.Delete(path)->status, 204);
  problem(client.Get(path), 404);
}

TEST_F(Service, KillNineMidJobThenRestartResumesToTheUninterruptedResult) {
  const std::string body = tilted_block_document(160).dump();
  const json reference = solve_locally(body);
  ASSERT_GE(reference["iterations"].get<int>(), 8);
  std::int64_t job = 0;
  {
    ServerProcess server(database());
    httplib::Client client = server.client();
    job = submit(client, body);
    // Kill while iteration 3 or later is committed and the job still runs.
    wait_for_running_iteration(client, job, 3);
    server.kill_hard();
  }
  ServerProcess restarted(database());
  httplib::Client client = restarted.client();
  const json done = wait_for_state(client, job, {"converged", "not_converged", "failed"});
  EXPECT_EQ(done["state"], "converged") << done.dump();
  EXPECT_EQ(done["attempts"], 2);
  EXPECT_EQ(done["interruptions"], 1);
  // Each iteration exactly once, in order.
  const std::vector<int> numbers = iteration_numbers(client, job);
  ASSERT_EQ(static_cast<int>(numbers.size()), reference["iterations"].get<int>());
  for (std::size_t k = 0; k < numbers.size(); ++k) EXPECT_EQ(numbers[k], static_cast<int>(k) + 1);
  // The rows after the restart say so; the result equals the uninterrupted run's to the last digit.
  const json result = get_json(client, "/v1/jobs/" + std::to_string(job) + "/result");
  EXPECT_EQ(result["history"].back()["attempt"], 2);
  EXPECT_EQ(result["history"].front()["attempt"], 1);
  EXPECT_EQ(result_numbers(result), result_numbers(reference));
}

TEST_F(Service, CancelThenResumeWithANewSchedule) {
  ServerProcess server(database());
  httplib::Client client = server.client();
  cancel_then_resume_with_a_new_schedule(client, submit(client, tilted_block_document(120).dump()));
}

TEST_F(Service, SeveralJobsQueuedAtOnce) {
  ServerProcess server(database(), {"--workers", "2"});
  httplib::Client client = server.client();
  const std::vector<std::string> names = {"report-problem1.json", "report-problem2.json", "report-problem3-case1.json",
                                          "report-problem3-case2.json", "report-problem3-case3.json",
                                          "report-beam-model-b.json"};
  std::vector<std::int64_t> jobs;
  for (const std::string& name : names) jobs.push_back(submit(client, example_text(name)));
  for (std::size_t k = 0; k < jobs.size(); ++k) {
    const json done = wait_for_state(client, jobs[k], {"converged", "not_converged", "failed"});
    EXPECT_EQ(done["state"], "converged") << names[k];
    EXPECT_EQ(result_numbers(get_json(client, "/v1/jobs/" + std::to_string(jobs[k]) + "/result")),
              result_numbers(solve_locally(example_text(names[k]))))
        << names[k];
  }
  // Newest first, filtered by state, paginated.
  const json first = get_json(client, "/v1/jobs?page_size=4&state=converged");
  ASSERT_EQ(first["jobs"].size(), 4U);
  EXPECT_EQ(first["jobs"][0]["id"], jobs.back());
  const json second = get_json(client, "/v1/jobs?page_size=4&state=converged&page_token=" +
                                           first["next_page_token"].get<std::string>());
  EXPECT_EQ(second["jobs"].size(), 2U);
  EXPECT_TRUE(second["next_page_token"].is_null());
  EXPECT_EQ(get_json(client, "/healthz")["queue_length"], 0);
}

TEST_F(Service, EventStreamFollowsAJobAndResumesWithLastEventId) {
  ServerProcess server(database());
  httplib::Client client = server.client();
  const std::int64_t job = submit(client, example_text("report-problem2.json"));
  wait_for_state(client, job, {"converged"});
  const std::string path = "/v1/jobs/" + std::to_string(job) + "/events";
  const httplib::Result all = client.Get(path);
  ASSERT_EQ(all->status, 200);
  EXPECT_EQ(all->get_header_value("Content-Type"), "text/event-stream");
  // queued, running, 5 iterations, converged; each with an id.
  std::vector<std::int64_t> ids;
  std::vector<std::string> kinds;
  std::istringstream lines(all->body);
  for (std::string line; std::getline(lines, line);) {
    if (line.rfind("id: ", 0) == 0) ids.push_back(std::stoll(line.substr(4)));
    if (line.rfind("event: ", 0) == 0) kinds.push_back(line.substr(7));
  }
  ASSERT_EQ(kinds.size(), 8U) << all->body;
  EXPECT_EQ(std::count(kinds.begin(), kinds.end(), "iteration"), 5);
  EXPECT_EQ(kinds.back(), "state");
  EXPECT_NE(all->body.find("\"state\":\"converged\""), std::string::npos);
  // Reconnecting after the fourth event gives the rest only.
  const httplib::Result rest = client.Get(path, {{"Last-Event-ID", std::to_string(ids[3])}});
  EXPECT_EQ(std::count(rest->body.begin(), rest->body.end(), '\n') / 4, 4) << rest->body;
  EXPECT_EQ(rest->body.find("id: " + std::to_string(ids[3]) + "\n"), std::string::npos);
}

TEST_F(Service, EventStreamsAreCappedSoOtherRoutesStayAvailable) {
  ServerProcess server(database(), {"--max-streams", "1"});
  httplib::Client client = server.client();
  const std::int64_t job = submit(client, tilted_block_document(120).dump());
  wait_for_state(client, job, {"running"});
  std::atomic<bool> streaming{true};
  std::thread watcher([&] {
    httplib::Client c = server.client();
    c.Get("/v1/jobs/" + std::to_string(job) + "/events",
          [&](const char*, std::size_t) { return streaming.load(); });
  });
  for (int attempt = 0; attempt < 600 && get_json(client, "/healthz")["event_streams"] != 1; ++attempt) {
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  ASSERT_EQ(get_json(client, "/healthz")["event_streams"], 1);
  const json busy = problem(client.Get("/v1/jobs/" + std::to_string(job) + "/events"), 503);
  EXPECT_NE(busy["detail"].get<std::string>().find("too many"), std::string::npos);
  EXPECT_EQ(client.Get("/healthz")->status, 200);
  client.Post("/v1/jobs/" + std::to_string(job) + "/cancel", "", "application/json");
  streaming = false;
  watcher.join();
}

TEST_F(Service, IdempotencyKeyReplaysTheSameJob) {
  ServerProcess server(database());
  httplib::Client client = server.client();
  const std::string body = example_text("report-problem1.json");
  const std::int64_t first = submit(client, body, {{"Idempotency-Key", "abc-123"}});
  const httplib::Result again = client.Post("/v1/jobs", {{"Idempotency-Key", "abc-123"}}, body, "application/json");
  ASSERT_EQ(again->status, 202);
  EXPECT_EQ(json::parse(again->body)["id"], first);
  EXPECT_EQ(again->get_header_value("Idempotent-Replayed"), "true");
  problem(client.Post("/v1/jobs", {{"Idempotency-Key", "abc-123"}}, example_text("report-problem2.json"), "application/json"), 409);
  EXPECT_EQ(get_json(client, "/v1/jobs")["jobs"].size(), 1U);
}

TEST_F(Service, TokenFileTurnsOnBearerAuthentication) {
  const fs::path token = dir_ / "token";
  std::ofstream(token) << "s3cret-token\n";
  ServerProcess server(database(), {"--token-file", token.string()});
  httplib::Client client = server.client();
  problem(client.Get("/v1/jobs"), 401);
  EXPECT_EQ(client.Get("/healthz")->status, 200);
  client.set_bearer_token_auth("s3cret-token");
  EXPECT_EQ(client.Get("/v1/jobs")->status, 200);
  client.set_bearer_token_auth("wrong");
  problem(client.Get("/v1/jobs"), 401);
}

TEST_F(Service, RefusesUnsafeOrDoubleStarts) {
  // Beyond loopback only with a token.
  const CommandResult open = run_command({SAASGAPS_BINARY, "serve", "--host", "0.0.0.0", "--port", "0", "--db",
                                          (dir_ / "open.db").string()});
  EXPECT_NE(open.exit_code, 0);
  EXPECT_NE(open.output.find("token"), std::string::npos) << open.output;
  ServerProcess server(database());
  // A second server on the same port fails instead of sharing it.
  const CommandResult same_port = run_command({SAASGAPS_BINARY, "serve", "--port", std::to_string(server.port()),
                                               "--db", (dir_ / "other.db").string()});
  EXPECT_NE(same_port.exit_code, 0);
  EXPECT_NE(same_port.output.find("cannot listen"), std::string::npos) << same_port.output;
  // A second server on the same database fails instead of corrupting its jobs.
  const CommandResult same_db = run_command({SAASGAPS_BINARY, "serve", "--port", "0", "--db", database().string()});
  EXPECT_NE(same_db.exit_code, 0);
  EXPECT_NE(same_db.output.find("in use"), std::string::npos) << same_db.output;
}

TEST_F(Service, GracefulStopInterruptsAndTheNextServerResumes) {
  const std::string body = tilted_block_document(120).dump();
  std::int64_t job = 0;
  {
    ServerProcess server(database());
    httplib::Client client = server.client();
    job = submit(client, body);
    wait_for_running_iteration(client, job, 2);
    EXPECT_EQ(server.stop(), 0);
  }
  ServerProcess restarted(database());
  httplib::Client client = restarted.client();
  const json done = wait_for_state(client, job, {"converged", "not_converged", "failed"});
  EXPECT_EQ(done["state"], "converged");
  EXPECT_EQ(done["interruptions"], 0);  // a clean stop is not a crash
  EXPECT_EQ(result_numbers(get_json(client, "/v1/jobs/" + std::to_string(job) + "/result")),
            result_numbers(solve_locally(body)));
}

}  // namespace
}  // namespace saasgaps::testing
