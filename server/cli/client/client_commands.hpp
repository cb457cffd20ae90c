#pragma once
/// The commands that work a `saasgaps serve` from anywhere (docs/cli.md, docs/http-api.md):
///   submit MODEL.json [--watch]     POST /v1/jobs; prints the job id on stdout
///   jobs [--state S] [--limit N]    GET /v1/jobs
///   status ID [--json]              GET /v1/jobs/ID
///   watch ID [--wide]               the job's events until it stops (cli/job_watch.hpp)
///   cancel ID                       POST /v1/jobs/ID/cancel
///   resume ID [READ card] [--watch] POST /v1/jobs/ID/resume with the options of `solve --resume`
///   fetch ID [--result|--vtu|--plot NAME] -o FILE
/// The server is --server, else $SAASGAPS_SERVER, else http://127.0.0.1:8080; the bearer token is
/// the content of --token-file, else $SAASGAPS_TOKEN. Exit codes are solve's: watch (and submit or
/// resume with --watch) ends with 0 converged, 3 not_converged, cancelled or interrupted, 1 failed;
/// a model or resume body the server refuses (422) is 2, every error printed with its pointer; any
/// other refusal or an unreachable server is 1.

#include <CLI/CLI.hpp>

#include <cstdint>
#include <optional>
#include <string>

#include "cli/common/read_card_options.hpp"

namespace saasgaps::cli {

/// The server a client command talks to.
struct ServerOptions {
  std::string server;      ///< empty: $SAASGAPS_SERVER, else the default
  std::string token_file;  ///< empty: $SAASGAPS_TOKEN, else no token
};

inline constexpr const char* default_server_url = "http://127.0.0.1:8080";

class ClientCommands {
 public:
  /// Registers the commands on `app`; the object must outlive the parse (options are bound to it).
  explicit ClientCommands(CLI::App& app);
  ClientCommands(const ClientCommands&) = delete;
  ClientCommands& operator=(const ClientCommands&) = delete;

  /// Runs the client command that was parsed and returns its exit code; nothing when none was.
  /// Throws like every command (cli/common/usage.hpp maps exceptions to exit codes).
  [[nodiscard]] std::optional<int> run() const;

 private:
  int submit() const;
  int jobs() const;
  int status() const;
  int cancel() const;
  int resume() const;
  int fetch() const;

  ServerOptions server_;
  std::string model_path_;
  std::int64_t job_ = 0;
  bool watch_ = false;
  bool wide_ = false;
  bool json_ = false;
  std::string state_filter_;
  int limit_ = 20;
  ResumeOptions changes_;
  bool fetch_result_ = false;
  bool fetch_vtu_ = false;
  std::string fetch_plot_;
  std::string output_;

  CLI::App* submit_ = nullptr;
  CLI::App* jobs_ = nullptr;
  CLI::App* status_ = nullptr;
  CLI::App* watch_cmd_ = nullptr;
  CLI::App* cancel_ = nullptr;
  CLI::App* resume_ = nullptr;
  CLI::App* fetch_ = nullptr;
};

}  // namespace saasgaps::cli
