#include "cli/serve_command.hpp"

#include <httplib.h>
#include <netinet/in.h>
#include <sys/socket.h>

#include <csignal>
#include <iostream>
#include <stdexcept>
#include <thread>

#include "cli/file_io.hpp"
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

  // Signals go to a dedicated thread: block them before any other thread exists.
  sigset_t signals;
  sigemptyset(&signals);
  sigaddset(&signals, SIGINT);
  sigaddset(&signals, SIGTERM);
  pthread_sigmask(SIG_BLOCK, &signals, nullptr);

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
  std::thread signal_waiter([&server, signals] {
    int received = 0;
    sigwait(&signals, &received);
    server.stop();
  });
  std::cout << "saasgaps serve: listening on http://" << options.host << ":" << port << " (database "
            << options.database << ", " << options.workers << (options.workers == 1 ? " worker" : " workers");
  if (recovered > 0) std::cout << ", " << recovered << " interrupted jobs to resume";
  std::cout << ")" << std::endl;

  const bool clean = server.listen_after_bind();
  // Stop the signal thread if listening ended for another reason.
  pthread_kill(signal_waiter.native_handle(), SIGTERM);
  signal_waiter.join();
  std::cout << "saasgaps serve: stopping; running jobs halt at their next iteration boundary" << std::endl;
  return clean ? 0 : 1;
}

}  // namespace saasgaps::cli
