#include "cli/commands/serve_command.hpp"

#include <httplib.h>
#include <netinet/in.h>
#include <sys/socket.h>

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <filesystem>
#include <optional>
#include <chrono>
#include <condition_variable>
#include <csignal>
#include <ctime>
#include <iostream>
#include <mutex>
#include <stdexcept>
#include <thread>

#include "cli/common/file_io.hpp"
#include "service/http/guarded_server.hpp"
#include "service/http/http_api.hpp"
#include "service/ops/log.hpp"
#include "service/ops/private_directory.hpp"
#include "service/runs/job_runner.hpp"
#include "service/store/database_lock.hpp"
#include "service/store/event_hub.hpp"
#include "service/store/job_store.hpp"
#include "service/workers/slurm_executor.hpp"
#include "solver/base/index_ranges.hpp"
#include "solver/lac/sparse_cholesky.hpp"

namespace saasgaps::cli {

namespace {

bool is_loopback(const std::string& host) {
  return host == "localhost" || host == "::1" || host.rfind("127.", 0) == 0;
}

/// The write end of the self-pipe that turns SIGINT / SIGTERM into a shutdown. A handler, not a
/// blocked mask and sigwait: libraries (OpenBLAS) start threads before main(), and a signal
/// delivered to one of those would otherwise kill the process instead of stopping it cleanly.
int shutdown_pipe_write = -1;

extern "C" void request_shutdown(int) {
  const char byte = 1;
  [[maybe_unused]] const ssize_t written = write(shutdown_pipe_write, &byte, 1);
}

/// SO_REUSEADDR only: cpp-httplib's default also sets SO_REUSEPORT, which would let a second server
/// share the port (and steal half the connections) instead of failing to start.
void exclusive_port(socket_t sock) {
  int yes = 1;
  setsockopt(sock, SOL_SOCKET, SO_REUSEADDR, &yes, sizeof yes);
}

std::string absolute(const std::string& path) {
  return path.empty() ? path : std::filesystem::absolute(path).lexically_normal().string();
}

service::SlurmOptions slurm_options(const ServeOptions& options, int port) {
  service::SlurmOptions slurm;
  slurm.partition = options.slurm_partition;
  slurm.account = options.slurm_account;
  slurm.time_limit = options.slurm_time_limit;
  slurm.extra = service::split_words(options.slurm_extra);
  slurm.worker_url = options.slurm_worker_url.empty() ? "http://" + options.host + ":" + std::to_string(port)
                                                      : options.slurm_worker_url;
  slurm.token_file = absolute(options.slurm_token_file.empty() ? options.token_file : options.slurm_token_file);
  slurm.worker_binary = options.slurm_worker_binary.empty() ? std::filesystem::read_symlink("/proc/self/exe").string()
                                                            : options.slurm_worker_binary;
  slurm.log_dir = absolute(options.slurm_log_dir);
  slurm.poll = std::chrono::milliseconds(static_cast<long long>(options.slurm_poll * 1000.0));
  slurm.cancel_grace = std::chrono::milliseconds(static_cast<long long>(options.slurm_cancel_grace * 1000.0));
  return slurm;
}

/// utc_now()'s format for a time `days` ago.
std::string days_ago(double days) {
  return service::utc_text(std::chrono::system_clock::now() - std::chrono::duration_cast<std::chrono::system_clock::duration>(
                                                                  std::chrono::duration<double>(days * 86400.0)));
}

/// --keep-finished: deletes finished jobs older than the retention at start-up and then hourly.
class Retention {
 public:
  Retention(service::JobStore& store, std::optional<double> days) : store_(store), days_(days) {
    if (!days_) return;
    sweep();
    thread_ = std::thread([this] {
      std::unique_lock lock(mutex_);
      while (!stop_.wait_for(lock, std::chrono::hours(1), [this] { return stopping_; })) {
        lock.unlock();
        sweep();
        lock.lock();
      }
    });
  }
  ~Retention() {
    {
      std::lock_guard lock(mutex_);
      stopping_ = true;
    }
    stop_.notify_all();
    if (thread_.joinable()) thread_.join();
  }

 private:
  void sweep() {
    try {
      const int removed = store_.remove_finished_before(days_ago(*days_));
      if (removed > 0) service::log_info("retention", {{"deleted_jobs", removed}, {"keep_finished_days", *days_}});
    } catch (const std::exception& e) {
      service::log_error("store_error", {{"operation", "retention"}, {"error", e.what()}});
    }
  }

  service::JobStore& store_;
  std::optional<double> days_;
  std::mutex mutex_;
  std::condition_variable stop_;
  bool stopping_ = false;
  std::thread thread_;
};

/// The authority (host[:port]) of an http://authority/path URL.
std::string url_authority(const std::string& url) {
  const auto scheme = url.find("://");
  const std::string rest = scheme == std::string::npos ? url : url.substr(scheme + 3);
  return rest.substr(0, rest.find('/'));
}

std::chrono::milliseconds milliseconds(double seconds) {
  return std::chrono::milliseconds(static_cast<std::int64_t>(seconds * 1000.0));
}

}  // namespace

int run_serve(const ServeOptions& options) {
  std::optional<std::string> token;
  if (!options.token_file.empty()) token = read_token_file(options.token_file);
  if (!is_loopback(options.host) && !token) {
    throw std::runtime_error("refusing to listen on " + options.host +
                             " without authentication: give --token-file, or listen on 127.0.0.1");
  }

  int shutdown_pipe[2];
  if (pipe2(shutdown_pipe, O_CLOEXEC) != 0) throw std::runtime_error("cannot create the shutdown pipe");
  shutdown_pipe_write = shutdown_pipe[1];
  struct sigaction action {};
  action.sa_handler = request_shutdown;
  sigemptyset(&action.sa_mask);
  action.sa_flags = SA_RESTART;
  sigaction(SIGINT, &action, nullptr);
  sigaction(SIGTERM, &action, nullptr);

  // Jobs solved side by side share the cores: each factorization then runs its BLAS on one thread,
  // and the setup and result passes stay on the job's own thread.
  if (options.workers > 1) {
    SparseCholesky::set_max_blas_threads(1);
    set_parallel_threads(1);
  }

  const bool slurm = options.executor == "slurm";
  if (slurm && options.slurm_worker_url.empty() && (options.host == "0.0.0.0" || options.host == "::")) {
    throw std::runtime_error("with --host " + options.host + ", give --slurm-worker-url: the URL workers use");
  }
  service::DatabaseLock lock(options.database);
  service::JobStore store(options.database, options.max_interruptions);
  // Runs handed to Slurm outlive the server: the monitor checks whether their Slurm jobs still run.
  const int recovered = store.recover_interrupted(slurm);
  // Upload directories of servers and workers killed (kill -9, a crash) before they could remove them.
  const int abandoned = service::remove_abandoned_uploads();
  service::EventHub hub;

  Retention retention(store, options.keep_finished_days);

  // Each connection gets a thread of its own (event streams and slow clients included), with
  // deadlines that drop clients too slow to send a request.
  service::ConnectionLimits limits;
  limits.head_deadline = milliseconds(options.header_timeout);
  limits.keep_alive_timeout = milliseconds(options.keep_alive);
  service::GuardedServer server(limits);
  server.set_socket_options(exclusive_port);
  server.set_payload_max_length(options.max_body);
  io::set_mesh_limits(options.mesh);
  // Workers send the Host of --slurm-worker-url: the Host check (without a token) must accept it.
  std::vector<std::string> allowed_hosts = options.allowed_hosts;
  if (slurm && !options.slurm_worker_url.empty()) allowed_hosts.push_back(url_authority(options.slurm_worker_url));
  // Models submitted to the local pool go to their worker already read (up to one per worker).
  service::ModelHandoff handoff(static_cast<std::size_t>(options.workers));
  service::HttpApi api(store, hub, {token, options.max_streams, options.workers, options.host, allowed_hosts,
                                    slurm ? nullptr : &handoff, options.max_body, slurm});
  api.install(server);

  const int port = options.port == 0 ? server.bind_to_any_port(options.host)
                                     : (server.bind_to_port(options.host, options.port) ? options.port : -1);
  if (port < 0) {
    throw std::runtime_error("cannot listen on " + options.host + ":" + std::to_string(options.port) +
                             " (is another server using it?)");
  }

  std::optional<service::JobRunner> runner;
  std::optional<service::SlurmExecutor> slurm_executor;
  if (slurm) {
    slurm_executor.emplace(store, hub, slurm_options(options, port));
  } else {
    // Orderings live beside the database: resumes and jobs on a mesh solved before skip METIS.
    runner.emplace(store, hub, options.workers, options.database + ".orderings", &handoff);
  }
  std::thread signal_waiter([&server, read_end = shutdown_pipe[0]] {
    char byte = 0;
    while (read(read_end, &byte, 1) < 0 && errno == EINTR) {
    }
    server.stop();
  });
  std::cout << "saasgaps serve: listening on http://" << options.host << ":" << port << " (database "
            << options.database << ", ";
  if (slurm) {
    std::cout << "executor slurm";
  } else {
    std::cout << options.workers << (options.workers == 1 ? " worker" : " workers");
  }
  if (recovered > 0) std::cout << ", " << recovered << " interrupted jobs to resume";
  std::cout << ")" << std::endl;
  service::log_info("server_started", {{"version", SAASGAPS_VERSION}, {"host", options.host}, {"port", port},
                                       {"database", options.database}, {"executor", options.executor}, {"workers", options.workers},
                                       {"recovered_jobs", recovered}, {"authentication", token.has_value()},
                                       {"abandoned_uploads_removed", abandoned}});
  if (!store.writable()) service::log_error("database_read_only", {{"reason", store.why_not_writable()}});

  const bool clean = server.listen_after_bind();
  // Wake the signal thread if listening ended for another reason.
  request_shutdown(0);
  signal_waiter.join();
  std::cout << "saasgaps serve: stopping; running jobs halt at their next iteration boundary" << std::endl;
  service::log_info("server_stopping", {{"clean", clean}});
  return clean ? 0 : 1;
}

}  // namespace saasgaps::cli
