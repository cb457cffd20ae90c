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

namespace saasgaps::testing {

struct Outcome {
  int exit_code = -1;
  std::string out;
  std::string err;
};

class CommandTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = std::filesystem::temp_directory_path() /
           ("saasgaps-cli-" + std::to_string(::getpid()) + "-" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    std::filesystem::create_directories(dir_);
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }

  static std::string example(const std::string& name) { return std::string(SAASGAPS_EXAMPLES_DIR) + "/" + name; }
  [[nodiscard]] std::string path(const std::string& name) const { return (dir_ / name).string(); }

  /// Runs `saasgaps ARGUMENTS` through the shell.
  [[nodiscard]] Outcome saasgaps(const std::string& arguments) const {
    const std::string out = path("stdout.txt");
    const std::string err = path("stderr.txt");
    const std::string command = std::string(SAASGAPS_BINARY) + " " + arguments + " > " + out + " 2> " + err;
    const int status = std::system(command.c_str());
    Outcome r;
    r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    r.out = read(out);
    r.err = read(err);
    return r;
  }

  static std::string read(const std::string& file) {
    std::ifstream in(file);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
  }

  static nlohmann::json json_of(const std::string& file) { return nlohmann::json::parse(read(file)); }

  std::filesystem::path dir_;
};

}  // namespace saasgaps::testing
