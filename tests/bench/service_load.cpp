// saasgaps_service_load: how fast status polls stay while a large job solves.
//
//   build/tests/bench/saasgaps_service_load [--size 300] [--clients 4] [--seconds 10]
//
// Starts a real `saasgaps serve` (ephemeral port, fresh database), measures GET /v1/jobs/{id} on an
// idle server (the baseline), then submits a large job (the tilted block of the service tests, size x
// size elements) and measures the same poll from several client threads while the job iterates.
// Reports median and p95 latency of both, and their ratio.
#include <CLI/CLI.hpp>
#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <thread>
#include <vector>

#include "service/long_job_model.hpp"
#include "service/server_process.hpp"

using namespace saasgaps::testing;
using nlohmann::json;

namespace {

struct Latencies {
  std::vector<double> ms;
  void add(double v) { ms.push_back(v); }
  double quantile(double q) {
    if (ms.empty()) return 0.0;
    std::sort(ms.begin(), ms.end());
    return ms[static_cast<std::size_t>(q * static_cast<double>(ms.size() - 1))];
  }
};

/// Polls `path` from `clients` threads until `keep_going` turns false; every request's latency.
Latencies poll(const ServerProcess& server, const std::string& path, int clients, const std::atomic<bool>& keep_going,
               int max_per_client) {
  std::vector<Latencies> per_client(static_cast<std::size_t>(clients));
  std::vector<std::thread> threads;
  for (int c = 0; c < clients; ++c) {
    threads.emplace_back([&, c] {
      httplib::Client client = server.client();
      for (int k = 0; k < max_per_client && keep_going; ++k) {
        const auto start = std::chrono::steady_clock::now();
        const httplib::Result r = client.Get(path);
        const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
        if (r && r->status == 200) per_client[c].add(ms);
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
      }
    });
  }
  for (std::thread& t : threads) t.join();
  Latencies all;
  for (const Latencies& l : per_client) all.ms.insert(all.ms.end(), l.ms.begin(), l.ms.end());
  return all;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Status-poll latency of the SAASGAPS service while a large job solves"};
  int size = 300, clients = 4;
  double seconds = 10.0;
  app.add_option("--size", size, "The job: a size x size element block (2 (size + 1)^2 unknowns)");
  app.add_option("--clients", clients, "Polling client threads");
  app.add_option("--seconds", seconds, "How long to poll while the job runs");
  CLI11_PARSE(app, argc, argv);

  const auto dir = std::filesystem::temp_directory_path() / ("saasgaps-load-" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  {
    ServerProcess server(dir / "jobs.db", {"--workers", "1"});
    httplib::Client client = server.client();

    // Baseline: the same poll on an idle server, against a small finished job.
    const httplib::Result small = client.Post("/v1/jobs", tilted_block_document(20).dump(), "application/json");
    const auto small_id = json::parse(small->body)["id"].get<std::int64_t>();
    wait_for_state(client, small_id, {"converged", "not_converged", "failed"});
    std::atomic<bool> forever{true};
    Latencies idle = poll(server, "/v1/jobs/" + std::to_string(small_id), clients, forever, 100);

    const std::string body = tilted_block_document(size).dump();
    const auto submitted = std::chrono::steady_clock::now();
    const httplib::Result big = client.Post("/v1/jobs", body, "application/json");
    const double submit_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - submitted).count();
    const auto id = json::parse(big->body)["id"].get<std::int64_t>();
    wait_for_state(client, id, {"running"});
    std::atomic<bool> running{true};
    std::thread stopper([&] {
      std::this_thread::sleep_for(std::chrono::duration<double>(seconds));
      running = false;
    });
    Latencies busy = poll(server, "/v1/jobs/" + std::to_string(id), clients, running, 1'000'000);
    stopper.join();
    const json job = get_json(client, "/v1/jobs/" + std::to_string(id));
    client.Post("/v1/jobs/" + std::to_string(id) + "/cancel", "", "application/json");

    std::printf("job: %d x %d block, %d unknowns, %.1f MB model, submitted (validated and stored) in %.2f s; "
                "%d iterations done while polling\n",
                size, size, 2 * (size + 1) * (size + 1), static_cast<double>(body.size()) / 1e6, submit_s,
                job["iteration"].get<int>());
    std::printf("%-34s %8s %10s %10s\n", "GET /v1/jobs/{id}", "polls", "median ms", "p95 ms");
    std::printf("%-34s %8zu %10.2f %10.2f\n", "idle server (baseline)", idle.ms.size(), idle.quantile(0.5), idle.quantile(0.95));
    std::printf("%-34s %8zu %10.2f %10.2f\n", "while the job solves", busy.ms.size(), busy.quantile(0.5), busy.quantile(0.95));
    std::printf("ratio busy / idle: median %.2f, p95 %.2f\n", busy.quantile(0.5) / idle.quantile(0.5),
                busy.quantile(0.95) / idle.quantile(0.95));
    server.stop();
  }
  std::filesystem::remove_all(dir);
  return 0;
}
