#pragma once
/// `saasgaps serve`: the HTTP job service on one SQLite database file.

#include <cstddef>
#include <string>

namespace saasgaps::cli {

struct ServeOptions {
  std::string host = "127.0.0.1";
  int port = 8080;              ///< 0: any free port (printed on start)
  std::string database = "saasgaps.db";
  int workers = 1;
  std::size_t max_body = 256UL * 1024 * 1024;
  std::string token_file;       ///< bearer-token authentication when set
  int max_streams = 4;
  int max_interruptions = 3;
};

/// Runs until SIGINT or SIGTERM; returns the exit code. Throws when it cannot start.
int run_serve(const ServeOptions& options);

}  // namespace saasgaps::cli
