// Studies through the service (docs/studies.md): POST /v1/studies runs each point as a job; the
// same study again is answered from the result cache without a new job; a bad study is a 422 with
// its pointers; kill -9 of the server in the middle of a study loses no finished point and the
// study resumes to its end; cancel and resume of a study; its progress as Server-Sent Events.
#include <gtest/gtest.h>

#include <chrono>
#include <map>
#include <string>
#include <vector>
#include <thread>

#include "service/job_client.hpp"
#include "service/long_job_model.hpp"
#include "service/server_process.hpp"
#include "service/service_fixture.hpp"
#include "support/lame_cylinder_document.hpp"

namespace saasgaps::testing {
namespace {

using nlohmann::json;

class StudyService : public ServiceFixture {};

json post_study(httplib::Client& client, const json& study) {
  const httplib::Result r = client.Post("/v1/studies", study.dump(), "application/json");
  EXPECT_TRUE(r);
  if (!r) return nullptr;
  EXPECT_EQ(r->status, 202) << r->body;
  const json body = json::parse(r->body);
  EXPECT_EQ(r->get_header_value("Location"), "/v1/studies/" + std::to_string(body.value("id", 0)));
  return body;
}

/// Polls the study until `done(study)` holds.
template <class Done>
json wait_for_study(httplib::Client& client, std::int64_t id, const Done& done, int seconds = 120) {
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(seconds);
  while (true) {
    const json s = get_json(client, "/v1/studies/" + std::to_string(id));
    if (done(s)) return s;
    if (std::chrono::steady_clock::now() > deadline) {
      ADD_FAILURE() << "the study did not get there: " << s.dump();
      return s;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
}

bool finished(const json& s) { return s["status"] != "running"; }

std::size_t points_with(const json& s, const char* status) {
  std::size_t n = 0;
  for (const json& p : s["points"]) n += p["status"] == status ? 1 : 0;
  return n;
}

/// A study of the tilted block (each point some tenths of a second of iterations) over its pressure.
json long_study(int points) {
  json values = json::array();
  for (int k = 0; k < points; ++k) values.push_back(1000.0 + 50.0 * k);
  return {{"schema_version", 1},
          {"title", "tilted block, pressure"},
          {"model", tilted_block_document(64)},
          {"parameters", {{{"name", "p"}, {"pointer", "/loads/pressures/0/normal"}, {"values", values}}}},
          {"outputs", {{{"name", "closure_max"}, {"of", "gaps.closure"}, {"reduce", "max"}}}}};
}

TEST_F(StudyService, CylinderPointsScaleAsPOverEAndTheSameStudyIsAnsweredFromTheCache) {
  ServerProcess server(database(), {"--workers", "2"});
  httplib::Client client = server.client();
  const json doc = lame_cylinder::study_document({1000.0, 4000.0}, {10.0e6, 30.0e6});
  const json accepted = post_study(client, doc);
  const std::int64_t id = accepted["id"];
  const json done = wait_for_study(client, id, finished);
  ASSERT_EQ(done["status"], "converged") << done.dump();
  EXPECT_EQ(done["solved"], 4);
  double reference = 0.0;
  std::map<std::size_t, json> jobs;
  for (const json& p : done["points"]) {
    const double u = p["outputs"]["u_max"], pressure = p["parameters"]["p"], E = p["parameters"]["E"];
    if (reference == 0.0) reference = u * E / pressure;
    EXPECT_NEAR(u * E / pressure, reference, 1e-9 * reference);
    EXPECT_NEAR(u / lame_cylinder::lame_bore_displacement(pressure, E), 1.0, 5e-4);
    EXPECT_FALSE(p["cached"].get<bool>());
    jobs[p["index"].get<std::size_t>()] = p["job"];
  }

  // Again: answered at once from the cache, each point by the job that solved it; no job is added.
  const json again = post_study(client, doc);
  EXPECT_EQ(again["status"], "converged");
  EXPECT_EQ(again["solved"], 0);
  EXPECT_EQ(again["cached"], 4);
  for (const json& p : again["points"]) {
    EXPECT_TRUE(p["cached"].get<bool>());
    EXPECT_EQ(p["job"], jobs[p["index"].get<std::size_t>()]);
  }
  EXPECT_EQ(get_json(client, "/v1/jobs")["jobs"].size(), 4u);
  const json list = get_json(client, "/v1/studies")["studies"];
  ASSERT_EQ(list.size(), 2u);
  EXPECT_EQ(list[0]["converged"], 4);

  // A bad study: 422, every error at its pointer, nothing queued.
  json bad = doc;
  bad["parameters"][0]["pointer"] = "/loads/pressures/3/normal";
  bad["outputs"][0]["reduce"] = "median";
  const json problem = ServiceFixture::problem(client.Post("/v1/studies", bad.dump(), "application/json"), 422);
  ASSERT_EQ(problem["errors"].size(), 2u) << problem.dump();
  EXPECT_EQ(problem["errors"][0]["pointer"], "/parameters/0/pointer");
  EXPECT_EQ(problem["errors"][1]["pointer"], "/outputs/0/reduce");
  EXPECT_EQ(get_json(client, "/v1/jobs")["jobs"].size(), 4u);
}

TEST_F(StudyService, KillNineInTheMiddleLosesNoFinishedPointAndTheStudyResumes) {
  std::int64_t id = 0;
  json before;
  {
    ServerProcess server(database(), {"--workers", "1"});
    httplib::Client client = server.client();
    id = post_study(client, long_study(6))["id"];
    before = wait_for_study(client, id, [](const json& s) { return points_with(s, "converged") >= 2 || finished(s); });
    ASSERT_EQ(before["status"], "running") << "the study ended before the kill: make its points longer";
    server.kill_hard();
  }
  ServerProcess server(database(), {"--workers", "1"});
  httplib::Client client = server.client();
  const json after = wait_for_study(client, id, finished);
  EXPECT_EQ(after["status"], "converged") << after.dump();
  for (const json& p : before["points"]) {
    if (p["status"] != "converged") continue;
    const json& now = after["points"][p["index"].get<std::size_t>()];
    EXPECT_EQ(now["job"], p["job"]);
    EXPECT_EQ(now["outputs"], p["outputs"]);
  }
}

TEST_F(StudyService, CancelAndResumeAStudyWithItsProgressAsEvents) {
  ServerProcess server(database(), {"--workers", "1"});
  httplib::Client client = server.client();
  const std::int64_t id = post_study(client, long_study(5))["id"];
  wait_for_study(client, id, [](const json& s) { return points_with(s, "running") >= 1 || finished(s); });
  const httplib::Result cancel = client.Post("/v1/studies/" + std::to_string(id) + "/cancel", "", "application/json");
  ASSERT_TRUE(cancel);
  EXPECT_EQ(cancel->status, 202);
  const json cancelled = wait_for_study(client, id, finished);
  EXPECT_EQ(cancelled["status"], "cancelled") << cancelled.dump();
  EXPECT_GE(points_with(cancelled, "cancelled"), 4u);

  const httplib::Result resume = client.Post("/v1/studies/" + std::to_string(id) + "/resume", "", "application/json");
  ASSERT_TRUE(resume);
  EXPECT_EQ(resume->status, 202);
  // The event stream reports progress until no point runs, then ends.
  const httplib::Result events = client.Get("/v1/studies/" + std::to_string(id) + "/events");
  ASSERT_TRUE(events);
  EXPECT_EQ(events->status, 200);
  const std::string& text = events->body;
  ASSERT_NE(text.find("event: progress"), std::string::npos) << text;
  const std::size_t last = text.rfind("data: ");
  const json final_event = json::parse(text.substr(last + 6, text.find('\n', last) - last - 6));
  EXPECT_EQ(final_event["status"], "converged") << text;
  EXPECT_EQ(final_event["converged"], 5);
  const json done = get_json(client, "/v1/studies/" + std::to_string(id));
  EXPECT_EQ(done["status"], "converged");
  EXPECT_EQ(points_with(done, "converged"), 5u);
}

/// POSTs a study of an assembly with its mesh file as multipart/form-data; returns the answer.
httplib::Result post_assembly_study(httplib::Client& client, const json& study, const std::string& mesh_name,
                                    const std::string& mesh) {
  return client.Post("/v1/studies", httplib::MultipartFormDataItems{{"study", study.dump(), "", "application/json"},
                                                                   {"mesh", mesh, mesh_name, "text/plain"}});
}

/// The README's study of the press fit's push-out force (schemas/examples/studies), its .geo named
/// as uploaded.
json push_out_study() {
  json study = json::parse(example_text("studies/press-fit-push-out.study.json"));
  study["assembly"]["mesh"] = "press-fit-push-out.geo";
  return study;
}

/// A study of an assembly through the service: each point imported from the uploaded .geo with its
/// parameter, then run as a job like any point (cancel and resume of the whole study, the push-out
/// force rising with the interference as `saasgaps study` gives it); again, answered from the cache.
TEST_F(StudyService, AnAssemblyStudyImportsEachPointCancelsResumesAndIsCachedTheSecondTime) {
  ServerProcess server(database(), {"--workers", "1"});
  httplib::Client client = server.client();
  // The one worker is held by a long job, so that the study's points (imported when it is posted)
  // are still queued when it is cancelled: each takes a fraction of a second, and a loaded machine
  // once saw all three end before the cancel arrived. Cancelling running points is
  // CancelAndResumeAStudyWithItsProgressAsEvents'.
  const std::int64_t busy = submit(client, tilted_block_document(120).dump());
  wait_for_state(client, busy, {"running"});
  const std::string geo = example_text("assemblies/press-fit-push-out.geo");
  const httplib::Result accepted = post_assembly_study(client, push_out_study(), "press-fit-push-out.geo", geo);
  ASSERT_TRUE(accepted);
  ASSERT_EQ(accepted->status, 202) << accepted->body;
  const std::int64_t id = json::parse(accepted->body)["id"];
  ASSERT_EQ(client.Post("/v1/studies/" + std::to_string(id) + "/cancel", "", "application/json")->status, 202);
  const json cancelled = wait_for_study(client, id, finished);
  EXPECT_EQ(cancelled["status"], "cancelled") << cancelled.dump();
  EXPECT_GE(points_with(cancelled, "cancelled"), 2u);
  ASSERT_EQ(client.Post("/v1/jobs/" + std::to_string(busy) + "/cancel", "", "application/json")->status, 202);
  ASSERT_EQ(client.Post("/v1/studies/" + std::to_string(id) + "/resume", "", "application/json")->status, 202);
  const json done = wait_for_study(client, id, finished);
  ASSERT_EQ(done["status"], "converged") << done.dump();
  std::vector<double> force;
  for (const json& p : done["points"]) force.push_back(p["outputs"]["push_out_force"]);
  ASSERT_EQ(force.size(), 3u);
  EXPECT_LT(force[0], force[1]);
  EXPECT_LT(force[1], force[2]);
  EXPECT_NEAR(force[1], 1474.30, 0.01);  // the plain example's (StudyCommand.PushOut...)

  const httplib::Result again = post_assembly_study(client, push_out_study(), "press-fit-push-out.geo", geo);
  ASSERT_EQ(again->status, 202) << again->body;
  const json cached = json::parse(again->body);
  EXPECT_EQ(cached["status"], "converged");
  EXPECT_EQ(cached["solved"], 0);
  EXPECT_EQ(cached["cached"], 3);
  for (std::size_t i = 0; i < 3; ++i) EXPECT_EQ(cached["points"][i]["outputs"], done["points"][i]["outputs"]);
}

/// A point of an assembly study whose import fails (a value the model reader refuses, a parameter
/// the .geo does not declare) fails alone with its parameter named; a study of an assembly sent as
/// JSON has no mesh to import: 422 at /assembly.
TEST_F(StudyService, AnAssemblyPointThatDoesNotImportFailsAlone) {
  ServerProcess server(database(), {"--workers", "2"});
  httplib::Client client = server.client();
  json study = json::parse(example_text("studies/press-fit-interference.study.json"));
  study["sampling"] = "zip";
  study["parameters"].push_back({{"name", "E"}, {"pointer", "/materials/0/table/0/E"}, {"values", {30e6, -1.0, 30e6}}});
  const std::string geo = example_text("studies/press-fit-rings.geo");
  const httplib::Result accepted = post_assembly_study(client, study, "press-fit-rings.geo", geo);
  ASSERT_EQ(accepted->status, 202) << accepted->body;
  const json first = json::parse(accepted->body);
  EXPECT_EQ(first["points"][1]["status"], "failed");
  EXPECT_NE(first["points"][1]["message"].get<std::string>().find(
                "parameter \"E\" = -1.0 (/parameters/1/values/1): /materials/0/table/0/E"),
            std::string::npos)
      << first["points"][1].dump();
  const json done = wait_for_study(client, first["id"], finished);
  EXPECT_EQ(done["status"], "partial") << done.dump();
  EXPECT_EQ(done["converged"], 2);
  // Lame's interference pressure is proportional to d: 188.5 and 377.1 psi at 1e-4 and 2e-4 in.
  EXPECT_NEAR(done["points"][2]["outputs"]["p_mean"].get<double>() / done["points"][0]["outputs"]["p_mean"].get<double>(),
              2.0, 1e-3);

  study["assembly"]["mesh_parameters"]["wall"] = 1.0;
  const httplib::Result undeclared = post_assembly_study(client, study, "press-fit-rings.geo", geo);
  ASSERT_EQ(undeclared->status, 202) << undeclared->body;
  for (const json& p : json::parse(undeclared->body)["points"]) {
    EXPECT_EQ(p["status"], "failed");
    EXPECT_NE(p["message"].get<std::string>().find("/mesh_parameters/wall: the geometry \"press-fit-rings.geo\" "
                                                   "declares no parameter \"wall\""),
              std::string::npos)
        << p.dump();
  }

  const json as_json = ServiceFixture::problem(client.Post("/v1/studies", study.dump(), "application/json"), 422);
  ASSERT_EQ(as_json["errors"].size(), 1u) << as_json.dump();
  EXPECT_EQ(as_json["errors"][0]["pointer"], "/assembly");
}

}  // namespace
}  // namespace saasgaps::testing
