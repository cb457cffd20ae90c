#include "cli/serve_command.hpp"

#include <httplib.h>
#include <netinet/in.h>
#include <sys/socket.h>

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <iostream>
#include <stdexcept>
#include <thread>

#include "cli/file_io.hpp"
#include "sparse_cholesky.hpp"
#include "service/event_hub.hpp"
#include "service/http_api.hpp"
#include "service/job_runner.hpp"
#include "service/job_store.hpp"

namespace saasgaps::cli {

namespace {

bool is_loopback(const std::string& host) {
  return host == "localhost" || host == "::1" || host.rfind("127.", 0) == 0;
}

std::string read_token(const std::string& path) {
  std::string token = read_file(path);
  const auto last = token.find_last_not_of(" \t\r\n");
  token.erase(last == std::string::npos ? 0 : last + 1);
  token.erase(0, token.find_first_not_of(" \t\r\n"));
  if (token.empty()) throw std::runtime_error("the token file " + path + " is empty");
  return token;
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

}  // namespace

int run_serve(const ServeOptions& options) {
  std::optional<std::string> token;
  if (!options.token_file.empty()) token = read_token(options.token_file);
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

  // Jobs solved side by side share the cores: each factorization then runs its BLAS on one thread.
  if (options.workers > 1) SparseCholesky::set_max_blas_threads(1);

  service::DatabaseLock lock(options.database);
  service::JobStore store(options.database, options.max_interruptions);
  const int recovered = store.recover_interrupted();
  service::EventHub hub;

  httplib::Server server;
  server.set_socket_options(exclusive_port);
  server.set_payload_max_length(options.max_body);
  // Event streams each hold a thread; the pool leaves room for the other routes beyond them.
  const auto threads = static_cast<std::size_t>(options.max_streams + 8);
  server.new_task_queue = [threads] { return new httplib::ThreadPool(threads); };
  service::HttpApi api(store, hub, {token, options.max_streams, options.workers});
  api.install(server);

  const int port = options.port == 0 ? server.bind_to_any_port(options.host)
                                     : (server.bind_to_port(options.host, options.port) ? options.port : -1);
  if (port < 0) {
    throw std::runtime_error("cannot listen on " + options.host + ":" + std::to_string(options.port) +
                             " (is another server using it?)");
  }

  service::JobRunner runner(store, hub, options.workers);
  std::thread signal_waiter([&server, read_end = shutdown_pipe[0]] {
    char byte = 0;
    while (read(read_end, &byte, 1) < 0 && errno == EINTR) {
    }
    server.stop();
  });
  std::cout << "saasgaps serve: listening on http://" << options.host << ":" << port << " (database "
            << options.database << ", " << options.workers << (options.workers == 1 ? " worker" : " workers");
  if (recovered > 0) std::cout << ", " << recovered << " interrupted jobs to resume";
  std::cout << ")" << std::endl;

  const bool clean = server.listen_after_bind();
  // Wake the signal thread if listening ended for another reason.
  request_shutdown(0);
  signal_waiter.join();
  std::cout << "saasgaps serve: stopping; running jobs halt at their next iteration boundary" << std::endl;
  return clean ? 0 : 1;
}

}  // namespace saasgaps::cli
