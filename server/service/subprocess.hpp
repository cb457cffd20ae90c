#pragma once
/// Runs a program with an argument vector (posix_spawnp: no shell, so no quoting or injection),
/// feeding it standard input and collecting its output, with a time limit. The Slurm executor runs
/// sbatch, squeue and scancel through it.

#include <chrono>
#include <string>
#include <vector>

namespace saasgaps::service {

struct ProcessResult {
  int exit_code = -1;  ///< -1 when killed (time limit) or ended by a signal
  std::string out;
  std::string err;
};

/// Starts argv[0] (looked up on PATH) with the service's environment plus `environment` entries
/// ("NAME=value", overriding), writes `input` to its standard input, and waits at most `limit`
/// (then kills it). Throws std::runtime_error when it cannot be started.
ProcessResult run_process(const std::vector<std::string>& argv, const std::string& input,
                          const std::vector<std::string>& environment, std::chrono::milliseconds limit);

}  // namespace saasgaps::service
