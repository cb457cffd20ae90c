#pragma once
/// `saasgaps serve`: the HTTP job service on one SQLite database file.

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "io/mesher/gmsh_mesh.hpp"

namespace saasgaps::cli {

struct ServeOptions {
  std::string host = "127.0.0.1";
  int port = 8080;              ///< 0: any free port (printed on start)
  std::string database = "saasgaps.db";
  int workers = 1;
  std::size_t max_body = 256UL * 1024 * 1024;
  io::MeshLimits mesh;  ///< what reading one uploaded mesh may cost (POST /v1/imports)
  std::string token_file;       ///< bearer-token authentication when set
  int max_streams = 4;
  int max_interruptions = 3;
  std::string executor = "local";  ///< local: the in-process pool; slurm: sbatch of workers
  std::string slurm_partition;
  std::string slurm_account;
  std::string slurm_time_limit;
  std::string slurm_extra;         ///< further sbatch arguments, split at white space
  std::string slurm_worker_url;    ///< empty: http://HOST:PORT of this server
  std::string slurm_worker_binary; ///< empty: this binary
  std::string slurm_token_file;    ///< empty: --token-file
  std::string slurm_log_dir;
  double slurm_poll = 2.0;          ///< seconds between squeue polls
  double slurm_cancel_grace = 30.0; ///< seconds a cancelled running worker has to stop
  std::vector<std::string> allowed_hosts;  ///< Host names accepted besides loopback and --host
  double header_timeout = 10.0;            ///< seconds to receive a request's head
  double keep_alive = 5.0;                 ///< seconds an idle connection stays open
  std::optional<double> keep_finished_days;  ///< retention of finished jobs
};

/// Runs until SIGINT or SIGTERM; returns the exit code. Throws when it cannot start.
int run_serve(const ServeOptions& options);

}  // namespace saasgaps::cli
