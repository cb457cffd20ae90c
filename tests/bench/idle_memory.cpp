// saasgaps_idle_memory: does an idle server give back the memory of the jobs it ran?
//
//   build/tests/bench/saasgaps_idle_memory [--size 270] [--jobs 10]
//
// Starts a real `saasgaps serve` (ephemeral port, fresh database) and runs the same large job (the
// tilted block of the service tests, size x size elements; 270 is about 146,000 unknowns) `jobs`
// times in a row, fetching each result as a client would. After each job, once the server is idle,
// reads the server's resident set (VmRSS) and its peak (VmHWM) from /proc. It does this twice in
// the same run: the baseline with SAASGAPS_MALLOC_TRIM=0 (the worker does not call malloc_trim after
// a job), then the server as shipped. A leak grows in both series; memory the allocator keeps grows
// in the baseline only.
#include <CLI/CLI.hpp>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <thread>
#include <vector>

#include "service/long_job_model.hpp"
#include "service/server_process.hpp"

using namespace saasgaps::testing;
using nlohmann::json;

namespace {

/// A field of /proc/PID/status in MiB ("VmRSS", "VmHWM").
double status_mib(pid_t pid, const std::string& field) {
  std::ifstream in("/proc/" + std::to_string(pid) + "/status");
  for (std::string line; std::getline(in, line);) {
    if (line.rfind(field + ":", 0) == 0) return std::stod(line.substr(field.size() + 1)) / 1024.0;
  }
  return 0.0;
}

std::vector<double> run_series(const std::filesystem::path& dir, const std::string& model, int jobs, bool trim) {
  if (trim) {
    unsetenv("SAASGAPS_MALLOC_TRIM");
  } else {
    setenv("SAASGAPS_MALLOC_TRIM", "0", 1);
  }
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  ServerProcess server(dir / "jobs.db");
  httplib::Client client = server.client();
  client.set_read_timeout(std::chrono::seconds(600));
  std::printf("%s\n  job  idle RSS MiB  peak MiB  seconds\n", trim ? "as shipped (malloc_trim after each job)"
                                                               : "baseline (SAASGAPS_MALLOC_TRIM=0)");
  std::printf("    0  %12.0f  %8.0f\n", status_mib(server.pid(), "VmRSS"), status_mib(server.pid(), "VmHWM"));
  std::vector<double> idle;
  for (int k = 1; k <= jobs; ++k) {
    const auto start = std::chrono::steady_clock::now();
    const httplib::Result r = client.Post("/v1/jobs", model, "application/json");
    if (!r || r->status != 202) throw std::runtime_error("submit failed");
    const std::int64_t id = json::parse(r->body)["id"];
    const json done = wait_for_state(client, id, {"converged", "not_converged", "failed"}, std::chrono::seconds(1200));
    const std::size_t result_bytes = client.Get("/v1/jobs/" + std::to_string(id) + "/result")->body.size();
    client.Delete("/v1/jobs/" + std::to_string(id));
    std::this_thread::sleep_for(std::chrono::milliseconds(500));  // idle
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    idle.push_back(status_mib(server.pid(), "VmRSS"));
    std::printf("  %3d  %12.0f  %8.0f  %7.1f   (%s, %d iterations, result %.1f MB)\n", k, idle.back(),
                status_mib(server.pid(), "VmHWM"), seconds, done["state"].get<std::string>().c_str(),
                done["iteration"].get<int>(), static_cast<double>(result_bytes) / 1e6);
    std::fflush(stdout);
  }
  server.stop();
  return idle;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Idle memory of saasgaps serve after repeated large jobs"};
  int size = 270, jobs = 10;
  bool baseline = true;
  app.add_option("--size", size, "Elements along each side of the tilted block")->check(CLI::Range(8, 2000));
  app.add_option("--jobs", jobs, "Jobs run one after another")->check(CLI::Range(1, 100));
  app.add_flag("!--no-baseline", baseline, "Skip the series without malloc_trim");
  CLI11_PARSE(app, argc, argv);

  const std::string model = tilted_block_document(size).dump();
  const auto dir = std::filesystem::temp_directory_path() / ("saasgaps-idle-memory-" + std::to_string(::getpid()));
  std::printf("tilted block %d x %d: %zu bytes of model, about %d unknowns\n", size, size, model.size(), 2 * (size + 1) * (size + 2));
  std::vector<double> without;
  if (baseline) without = run_series(dir, model, jobs, false);
  const std::vector<double> with = run_series(dir, model, jobs, true);
  std::filesystem::remove_all(dir);
  const auto growth = [](const std::vector<double>& v) { return v.size() < 2 ? 0.0 : v.back() - v[v.size() / 2 - (v.size() > 2 ? 1 : 0)]; };
  if (baseline) {
    std::printf("idle RSS after the last job: %.0f MiB baseline, %.0f MiB as shipped (ratio %.2f)\n", without.back(),
                with.back(), with.back() / without.back());
    std::printf("growth over the second half: %.0f MiB baseline, %.0f MiB as shipped\n", growth(without), growth(with));
  } else {
    std::printf("idle RSS after the last job: %.0f MiB; growth over the second half: %.0f MiB\n", with.back(), growth(with));
  }
  return 0;
}
