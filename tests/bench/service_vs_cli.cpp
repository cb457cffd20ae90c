// saasgaps_service_vs_cli: the service's submit-to-converged time against `saasgaps solve` on the
// same model, and what the service writes to disk for it.
//
//   python3 schemas/examples/make_ring_model.py --radial 61 --hoop 600 -o /tmp/annulus-150k.json
//   build/tests/bench/saasgaps_service_vs_cli --model /tmp/annulus-150k.json --rounds 3
//
// Each round runs, one after the other (interleaved, so both see the same machine load):
//   cli:     saasgaps solve MODEL -q -o RESULT  (wall time of the process);
//   service: a fresh `saasgaps serve --workers 1` on a new database; the wall time from the POST of
//            the model to the job's state reading converged (polled every 20 ms), then the server's
//            written bytes and write calls (/proc/PID/io: wchar, syscw), and the database and WAL
//            sizes once it has stopped.
// Reported per round, and the ratio service / cli (median of the rounds).
#include <CLI/CLI.hpp>
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
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

std::string read_text(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

/// Fields of /proc/PID/io (rchar, wchar, syscr, syscw, read_bytes, write_bytes, ...).
std::map<std::string, double> process_io(pid_t pid) {
  std::map<std::string, double> fields;
  std::ifstream in("/proc/" + std::to_string(pid) + "/io");
  std::string name;
  double value = 0;
  while (in >> name >> value) fields[name.substr(0, name.size() - 1)] = value;
  return fields;
}

double bytes_of(const fs::path& p) {
  std::error_code e;
  const auto size = fs::file_size(p, e);
  return e ? 0.0 : static_cast<double>(size);
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v.empty() ? 0.0 : v[v.size() / 2];
}

struct ServiceRun {
  double wall = 0, iteration_seconds = 0, commit_seconds = 0, written = 0, writes = 0, database = 0, wal = 0;
  int iterations = 0;
};

ServiceRun run_service(const fs::path& dir, const std::string& body) {
  const fs::path db = dir / "jobs.db";
  fs::remove(db);
  fs::remove(dir / "jobs.db-wal");
  fs::remove(dir / "jobs.db-shm");
  ServiceRun r;
  ServerProcess server(db, {"--workers", "1"});
  httplib::Client client = server.client();
  client.set_read_timeout(std::chrono::seconds(600));
  client.set_write_timeout(std::chrono::seconds(600));
  const auto start = std::chrono::steady_clock::now();
  const httplib::Result posted = client.Post("/v1/jobs", body, "application/json");
  if (!posted || posted->status != 202) throw std::runtime_error("submit failed");
  const auto id = json::parse(posted->body)["id"].get<std::int64_t>();
  for (;;) {
    const json job = get_json(client, "/v1/jobs/" + std::to_string(id));
    const std::string state = job["state"].get<std::string>();
    if (state == "converged") break;
    if (state != "queued" && state != "running") throw std::runtime_error("the job ended " + state);
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  r.wall = seconds_since(start);
  const std::map<std::string, double> io = process_io(server.pid());
  r.written = io.count("wchar") ? io.at("wchar") : 0;
  r.writes = io.count("syscw") ? io.at("syscw") : 0;
  const json history = get_json(client, "/v1/jobs/" + std::to_string(id) + "/iterations");
  for (const json& row : history["iterations"]) {
    r.iteration_seconds += row.value("seconds", 0.0);
    r.commit_seconds += row.value("commit_seconds", 0.0);
    ++r.iterations;
  }
  server.stop();
  r.database = bytes_of(db);
  r.wal = bytes_of(dir / "jobs.db-wal");
  return r;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Service submit-to-converged against saasgaps solve on the same model"};
  std::string model_path;
  int rounds = 3;
  app.add_option("--model", model_path, "Model document (make_ring_model.py -o writes large ones)")->required();
  app.add_option("--rounds", rounds, "Interleaved rounds of CLI and service")->check(CLI::Range(1, 20));
  CLI11_PARSE(app, argc, argv);

  const std::string body = read_text(model_path);
  const fs::path dir = fs::temp_directory_path() / ("saasgaps-service-vs-cli-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  std::vector<double> ratios;
  std::printf("model %s: %.1f MB\n", model_path.c_str(), static_cast<double>(body.size()) / 1e6);
  std::printf("%5s %9s %9s %7s %6s %9s %9s %10s %9s %9s %8s\n", "round", "cli s", "service s", "ratio", "iters",
              "iter s", "commit s", "written MB", "writes", "db MB", "wal MB");
  for (int round = 1; round <= rounds; ++round) {
    const auto cli_start = std::chrono::steady_clock::now();
    const CommandResult cli =
        run_command({SAASGAPS_BINARY, "solve", model_path, "-q", "-o", (dir / "cli-result.json").string()});
    const double cli_s = seconds_since(cli_start);
    if (cli.exit_code != 0) {
      std::fprintf(stderr, "saasgaps solve failed (%d): %s\n", cli.exit_code, cli.output.c_str());
      return 1;
    }
    const ServiceRun s = run_service(dir, body);
    ratios.push_back(s.wall / cli_s);
    std::printf("%5d %9.2f %9.2f %7.3f %6d %9.2f %9.2f %10.1f %9.0f %9.1f %8.1f\n", round, cli_s, s.wall,
                s.wall / cli_s, s.iterations, s.iteration_seconds, s.commit_seconds, s.written / 1e6, s.writes,
                s.database / 1e6, s.wal / 1e6);
  }
  std::printf("service submit-to-converged / cli wall: median %.3f over %d rounds\n", median(ratios), rounds);
  fs::remove_all(dir);
  return 0;
}
