#pragma once
/// A shell command run to the end with its standard output and error captured in two files, for
/// the tests that run the saasgaps binary as a user does (tests/cli, tests/service).

#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

namespace saasgaps::testing {

struct Outcome {
  int exit_code = -1;  ///< -1 when the command did not exit (a signal)
  std::string out;
  std::string err;
};

/// The whole text of `file` ("" when it cannot be read).
inline std::string read_text(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), {}};
}

/// Runs `command` with /bin/sh, its standard output to `out` and error to `err`, and reads both back.
inline Outcome run_captured(const std::string& command, const std::filesystem::path& out,
                            const std::filesystem::path& err) {
  const int status = std::system((command + " > " + out.string() + " 2> " + err.string()).c_str());
  Outcome r;
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  r.out = read_text(out);
  r.err = read_text(err);
  return r;
}

}  // namespace saasgaps::testing
