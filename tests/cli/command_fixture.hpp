#pragma once
/// The saasgaps binary run as a user runs it, in a scratch directory of its own per test: exit code
/// and standard error of each command.

#include <gtest/gtest.h>

#include <unistd.h>
#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

#include "support/captured_command.hpp"
#include "support/temp_directory.hpp"

namespace saasgaps::testing {

class CommandTest : public ::testing::Test {
 protected:
  static std::string example(const std::string& name) { return std::string(SAASGAPS_EXAMPLES_DIR) + "/" + name; }
  [[nodiscard]] std::string path(const std::string& name) const { return (dir_ / name).string(); }

  /// Runs `saasgaps ARGUMENTS` through the shell.
  [[nodiscard]] Outcome saasgaps(const std::string& arguments) const {
    return run_captured(std::string(SAASGAPS_BINARY) + " " + arguments, path("stdout.txt"), path("stderr.txt"));
  }

  static std::string read(const std::string& file) { return read_text(file); }

  static nlohmann::json json_of(const std::string& file) { return nlohmann::json::parse(read(file)); }

  TempDirectory temp_{"cli"};
  std::filesystem::path dir_ = temp_.path();
};

}  // namespace saasgaps::testing
