#pragma once
/// A real `saasgaps serve` process for service tests: started on an ephemeral loopback port with its
/// own database file, stopped gracefully or killed with SIGKILL. Its standard output and error (the
/// JSON-lines log) go to "<database>.log", which log() reads.

#include <httplib.h>
#include <sys/types.h>

#include <chrono>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace saasgaps::testing {

class ServerProcess {
 public:
  /// Starts the server on `database` with extra arguments; waits until it listens. The log goes to
  /// `log_file`, by default "<database>.log".
  ServerProcess(const std::filesystem::path& database, const std::vector<std::string>& arguments = {},
                const std::filesystem::path& log_file = {});
  ~ServerProcess();
  ServerProcess(const ServerProcess&) = delete;
  ServerProcess& operator=(const ServerProcess&) = delete;

  [[nodiscard]] int port() const { return port_; }
  [[nodiscard]] pid_t pid() const { return pid_; }
  /// Everything the server wrote so far (stdout and stderr).
  [[nodiscard]] std::string log() const;
  [[nodiscard]] httplib::Client client() const;
  void kill_hard();  ///< SIGKILL, then reap
  int stop();        ///< SIGTERM, then the exit status

 private:
  pid_t pid_ = -1;
  int port_ = 0;
  std::filesystem::path log_path_;
};

/// A free loopback port, for a program that cannot report one it picked itself (chromedriver) or a
/// server that must come back on the same port after a restart.
int free_port();

/// Runs a command with its arguments and returns its exit status and standard error.
struct CommandResult {
  int exit_code = -1;
  std::string output;
};
CommandResult run_command(const std::vector<std::string>& arguments);

/// GET path as JSON (asserting a 2xx answer).
nlohmann::json get_json(httplib::Client& client, const std::string& path);

/// Polls the job until it is in one of `states` or the timeout passes; returns the job.
nlohmann::json wait_for_state(httplib::Client& client, std::int64_t job, const std::vector<std::string>& states,
                              std::chrono::seconds timeout = std::chrono::seconds(120));

/// The result document without wall times and attempt numbers: what must match between runs.
nlohmann::json result_numbers(nlohmann::json result);

}  // namespace saasgaps::testing
