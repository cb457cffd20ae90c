// saasgaps_study_bench: the service's overhead per study point against a direct `saasgaps solve` of
// the same model, and the answer time of a cache hit (docs/performance.md, "Studies").
//
//   build/tests/bench/saasgaps_study_bench --points 200
//
// The model is the quick-start block (schemas/examples/quickstart-plane-strain-block.json), its
// pressure the parameter (points distinct values, so every point is solved). Measured, in turn:
//   solve:   `saasgaps solve MODEL -q -o RESULT` of one point's model, `--solves` times (wall, median);
//   study:   a fresh `saasgaps serve --workers 1`, POST /v1/studies of `points` points, polled every
//            20 ms until no point runs: wall / points is the time per point;
//   cached:  the same study posted again (every point answered from the cache): its POST's wall time;
//   hit:     POST /v1/jobs of one solved model, `--hits` times (median): a plain job's cache hit.
// Reported: the per-point time over the solve time (the overhead ratio), and the hit times.
#include <CLI/CLI.hpp>
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <thread>
#include <vector>

#include "service/server_process.hpp"

#include "stopwatch.hpp"

using namespace saasgaps::testing;
using nlohmann::json;
namespace fs = std::filesystem;

namespace {

using saasgaps::bench::seconds_since;

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"The service's overhead per study point against saasgaps solve, and a cache hit's answer time"};
  int points = 200, solves = 20, hits = 50;
  app.add_option("--points", points, "Points of the study")->capture_default_str();
  app.add_option("--solves", solves, "Direct solves timed")->capture_default_str();
  app.add_option("--hits", hits, "Cache hits timed")->capture_default_str();
  CLI11_PARSE(app, argc, argv);

  const fs::path dir = fs::temp_directory_path() / ("saasgaps-study-bench-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  std::ifstream in(std::string(SAASGAPS_EXAMPLES_DIR) + "/quickstart-plane-strain-block.json");
  const json model = json::parse(in);
  std::ofstream(dir / "model.json") << model.dump();

  std::vector<double> solve_times;
  for (int k = 0; k < solves; ++k) {
    const auto start = std::chrono::steady_clock::now();
    const CommandResult r = run_command({SAASGAPS_BINARY, "solve", (dir / "model.json").string(), "-q", "-o",
                                         (dir / "result.json").string()});
    solve_times.push_back(seconds_since(start));
    if (r.exit_code != 0) {
      std::fprintf(stderr, "solve failed: %s\n", r.output.c_str());
      return 1;
    }
  }
  const double solve = median(solve_times);

  json values = json::array();
  for (int k = 0; k < points; ++k) values.push_back(1000.0 + k);
  const json study = {{"schema_version", 1},
                      {"title", "bench"},
                      {"model", model},
                      {"parameters", {{{"name", "p"}, {"pointer", "/loads/pressures/0/normal"}, {"values", values}}}},
                      {"outputs", {{{"name", "uz"}, {"of", "nodes.u_z"}, {"reduce", "min"}}}}};
  ServerProcess server(dir / "jobs.db", {"--workers", "1"});
  httplib::Client client = server.client();
  auto start = std::chrono::steady_clock::now();
  const httplib::Result posted = client.Post("/v1/studies", study.dump(), "application/json");
  if (!posted || posted->status != 202) {
    std::fprintf(stderr, "POST /v1/studies failed\n");
    return 1;
  }
  const std::string id = std::to_string(json::parse(posted->body)["id"].get<long long>());
  json done;
  do {
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
    done = get_json(client, "/v1/studies/" + id);
  } while (done["status"] == "running");
  const double study_wall = seconds_since(start);
  const double per_point = study_wall / points;

  start = std::chrono::steady_clock::now();
  const httplib::Result again = client.Post("/v1/studies", study.dump(), "application/json");
  const double cached_study = seconds_since(start);
  const json again_body = json::parse(again->body);

  std::vector<double> hit_times;
  const std::string one = model.dump();
  for (int k = 0; k < hits + 1; ++k) {
    start = std::chrono::steady_clock::now();
    const httplib::Result r = client.Post("/v1/jobs", one, "application/json");
    if (k > 0) hit_times.push_back(seconds_since(start));  // the first solves it
    if (k == 0) {
      const std::string job = std::to_string(json::parse(r->body)["id"].get<long long>());
      while (get_json(client, "/v1/jobs/" + job)["state"] != "converged") std::this_thread::sleep_for(std::chrono::milliseconds(10));
    } else if (r->status != 200) {
      std::fprintf(stderr, "not a cache hit: %d\n", r->status);
      return 1;
    }
  }
  server.stop();
  fs::remove_all(dir);

  std::printf("solve (median of %d): %.4f s\n", solves, solve);
  std::printf("study of %d points: %.3f s, %.4f s per point, %s\n", points, study_wall, per_point,
              done["message"].get<std::string>().c_str());
  std::printf("per point / solve: %.3f (overhead %.1f %%)\n", per_point / solve, 100.0 * (per_point / solve - 1.0));
  std::printf("the same study again: %.3f s (%lld cached, %lld solved), %.5f s per point\n", cached_study,
              again_body["cached"].get<long long>(), again_body["solved"].get<long long>(), cached_study / points);
  std::printf("POST /v1/jobs cache hit (median of %d): %.5f s = %.3f of a solve\n", hits, median(hit_times),
              median(hit_times) / solve);
  return 0;
}
