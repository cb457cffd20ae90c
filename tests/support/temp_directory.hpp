#pragma once
/// A directory of a test's own under the system's temporary directory, made empty and removed with
/// everything in it when the object goes: a fixture member declared before what lives in it (a
/// store, a server's database) outlives those, since members go in reverse order.
///
/// Named saasgaps-<purpose>-<pid>[-<test name>]: the process id keeps two test programs apart (ctest
/// runs two at once), the running test's name (when a test is running) two tests of one program.

#include <unistd.h>

#include <filesystem>
#include <string>
#include <system_error>

#include <gtest/gtest.h>

namespace saasgaps::testing {

class TempDirectory {
 public:
  explicit TempDirectory(const std::string& purpose) : path_(std::filesystem::temp_directory_path() / name(purpose)) {
    std::filesystem::remove_all(path_);
    std::filesystem::create_directories(path_);
  }
  ~TempDirectory() {
    std::error_code ignored;  // a destructor does not throw; what is left is the system's to clean
    std::filesystem::remove_all(path_, ignored);
  }
  TempDirectory(const TempDirectory&) = delete;
  TempDirectory& operator=(const TempDirectory&) = delete;

  [[nodiscard]] const std::filesystem::path& path() const { return path_; }

 private:
  static std::string name(const std::string& purpose) {
    std::string n = "saasgaps-" + purpose + "-" + std::to_string(::getpid());
    if (const ::testing::TestInfo* test = ::testing::UnitTest::GetInstance()->current_test_info()) {
      n += "-" + std::string(test->name());
    }
    return n;
  }

  std::filesystem::path path_;
};

}  // namespace saasgaps::testing
