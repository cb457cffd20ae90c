#pragma once
/// Runs a program with an argument vector (posix_spawn: no shell, so no quoting or injection, and no
/// fork of a multithreaded server), feeding it standard input and collecting its output, with a time
/// limit and bounds on what it may write. The Slurm executor runs sbatch, squeue and scancel through
/// it; the mesh reader runs the sandboxed mesher (io/gmsh_mesh.cpp).

#include <chrono>
#include <cstddef>
#include <limits>
#include <string>
#include <vector>

namespace saasgaps::io {

struct ProcessResult {
  int exit_code = -1;            ///< -1 when killed (time limit, output limit) or ended by a signal
  int signal = 0;                ///< the signal that ended it, 0 when it exited
  bool timed_out = false;        ///< killed at the time limit
  bool output_exceeded = false;  ///< killed when its standard output passed ProcessSpec::max_output
  std::string out;
  std::string err;  ///< at most ProcessSpec::max_error bytes; the rest is read and dropped
};

struct ProcessSpec {
  std::vector<std::string> argv;  ///< argv[0] is looked up on PATH unless it holds a '/'
  std::string input;              ///< written to its standard input
  /// "NAME=value" entries: added to (overriding) the caller's environment, or the whole
  /// environment when inherit_environment is false.
  std::vector<std::string> environment;
  bool inherit_environment = true;
  std::chrono::milliseconds limit{0};  ///< wall time; then SIGKILL
  std::size_t max_output = std::numeric_limits<std::size_t>::max();
  std::size_t max_error = std::numeric_limits<std::size_t>::max();
};

/// Starts the program with only descriptors 0, 1 and 2 open, and waits for it within the spec's
/// limits. Throws std::runtime_error when it cannot be started.
ProcessResult run_process(const ProcessSpec& spec);

/// run_process with the caller's environment plus `environment` and no output bounds.
ProcessResult run_process(const std::vector<std::string>& argv, const std::string& input,
                          const std::vector<std::string>& environment, std::chrono::milliseconds limit);

}  // namespace saasgaps::io
