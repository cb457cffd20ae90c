// saasgaps_worker_overhead: what a remote worker's iteration costs beyond a local one.
//
//   build/tests/bench/saasgaps_worker_overhead [--size 386] [--iterations 4] [--repeat 3]
//
// Solves two models once, keeping every iteration's history row and restart state as the solver
// hands them over (the bytes both executors send): the report's problem 2 (small) and the tilted
// block of the service tests, size x size elements (386: about 3 x 10^5 unknowns). Then commits those
// iterations to a fresh SQLite job store two ways, each `repeat` times:
//   local:  JobStore::record_iteration, as the local executor's pool does (the baseline);
//   remote: POST /v1/jobs/{id}/work/iterations to an in-process HTTP service on loopback, as
//           `saasgaps worker` does (CBOR encoding, HTTP, lease check, the same commit).
// Reports the median commit time per iteration of both, their ratio, the extra cost, and the extra
// cost as a share of the iteration's own solve time.
#include <CLI/CLI.hpp>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <thread>

#include "io/model/model_reader.hpp"
#include "io/restart/stored_state.hpp"
#include "io/results/history_json.hpp"
#include "service/http/http_api.hpp"
#include "service/long_job_model.hpp"
#include "service/store/job_store.hpp"
#include "service/workers/worker_protocol.hpp"
#include "solver/analysis/analysis.hpp"

#include "stopwatch.hpp"

using namespace saasgaps;
using nlohmann::json;
namespace fs = std::filesystem;

namespace {

using saasgaps::bench::seconds_since;

struct Recorded {
  std::string row;
  std::vector<std::uint8_t> state;
  double solve_seconds = 0;
};

/// Keeps what the executors would send.
class Recorder final : public IterationObserver {
 public:
  explicit Recorder(std::string digest) : digest_(std::move(digest)) {}
  void on_iteration(const IterationRecord& row, const RestartState& state) override {
    iterations.push_back({io::history_row_text(row), io::encode_stored_state(state, digest_), row.seconds});
  }
  bool stop_requested() override { return false; }
  std::vector<Recorded> iterations;

 private:
  std::string digest_;
};

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

void measure(const std::string& name, const json& document, int repeat, service::JobStore& store, int port) {
  const std::string text = document.dump();
  std::string digest;
  const Model model = io::parse_model(text, &digest);
  Recorder recorder(digest);
  solve(model, &recorder);
  const std::vector<Recorded>& its = recorder.iterations;
  std::vector<double> solve_times;
  std::size_t state_bytes = 0;
  for (const Recorded& r : its) {
    solve_times.push_back(r.solve_seconds);
    state_bytes = std::max(state_bytes, r.state.size());
  }
  std::vector<double> local, remote;
  httplib::Client client("127.0.0.1", port);
  client.set_read_timeout(std::chrono::minutes(5));
  client.set_write_timeout(std::chrono::minutes(5));
  for (int k = 0; k < repeat; ++k) {
    // Local: the pool's commit.
    const auto a = store.submit(text, model.title, model.solver.max_iterations, std::nullopt, "bench").job.id;
    if (store.claim("bench local")->job.id != a) throw std::logic_error("the bench's job was not the one queued");
    for (std::size_t i = 0; i < its.size(); ++i) {
      const auto start = std::chrono::steady_clock::now();
      store.record_iteration(a, static_cast<int>(i + 1), its[i].row, its[i].state);
      local.push_back(seconds_since(start));
    }
    // Remote: the worker's request, through the service's route to the same commit.
    const auto b = store.submit(text, model.title, model.solver.max_iterations, std::nullopt, "bench").job.id;
    const service::ClaimedJob handed = *store.claim("bench remote", true);
    if (handed.job.id != b) throw std::logic_error("the bench's job was not the one queued");
    const service::Lease lease = store.redeem_ticket(b, handed.ticket, "bench remote");
    const httplib::Headers headers = {{service::worker_protocol::lease_header, service::worker_protocol::format_lease(lease)}};
    for (std::size_t i = 0; i < its.size(); ++i) {
      const auto start = std::chrono::steady_clock::now();
      const std::string body = service::worker_protocol::encode_iteration(static_cast<int>(i + 1), its[i].row, its[i].state);
      const httplib::Result r = client.Post("/v1/jobs/" + std::to_string(b) + "/work/iterations", headers, body,
                                            service::worker_protocol::cbor_type);
      remote.push_back(seconds_since(start));
      if (!r || r->status != 200) {
        std::fprintf(stderr, "the commit request failed: %s\n", r ? r->body.c_str() : httplib::to_string(r.error()).c_str());
        std::exit(1);
      }
    }
  }
  const double l = median(local), r = median(remote), s = median(solve_times);
  // A share of an iteration that takes under a millisecond says nothing: left out.
  const std::string share = s < 1e-3 ? "-" : std::to_string(100.0 * (r - l) / s).substr(0, 5) + "%";
  std::printf("%-34s %9zu %8zu KB %9.2f ms %9.2f ms %6.2fx %9.2f ms %10.2f ms %7s\n", name.c_str(),
              2 * model.nodes.size(), state_bytes / 1024, 1e3 * l, 1e3 * r, r / l, 1e3 * (r - l), 1e3 * s,
              share.c_str());
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Extra cost per iteration of a remote worker's commit over HTTP against the local executor"};
  int size = 386, iterations = 4, repeat = 3;
  app.add_option("--size", size, "Tilted block elements per side (386: ~3e5 unknowns)")->check(CLI::Range(8, 2000));
  app.add_option("--iterations", iterations, "Iterations of the large model")->check(CLI::Range(1, 100));
  app.add_option("--repeat", repeat, "Commits of each model's iterations per path")->check(CLI::Range(1, 100));
  CLI11_PARSE(app, argc, argv);

  const fs::path dir = fs::temp_directory_path() / ("saasgaps-worker-overhead-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  {
    service::JobStore store((dir / "jobs.db").string(), 3);
    service::EventHub hub;
    httplib::Server server;
    service::ApiOptions options;
    options.remote_workers = true;  // the worker routes, as with --executor slurm
    service::HttpApi api(store, hub, options);
    api.install(server);
    server.set_payload_max_length(std::size_t{1} << 32);
    const int port = server.bind_to_any_port("127.0.0.1");
    std::thread listener([&] { server.listen_after_bind(); });

    std::printf("%-34s %9s %11s %12s %12s %7s %12s %13s %7s\n", "model", "unknowns", "state", "local", "remote", "ratio",
                "extra", "solve/iter", "extra%");
    std::ifstream in(std::string(SAASGAPS_EXAMPLES_DIR) + "/report-problem2.json");
    measure("report problem 2", json::parse(in), repeat * 10, store, port);
    json large = testing::tilted_block_document(size);
    large["solver"]["max_iterations"] = iterations;
    measure("tilted block " + std::to_string(size) + " x " + std::to_string(size), large, repeat, store, port);
    server.stop();
    listener.join();
  }
  fs::remove_all(dir);
  return 0;
}
