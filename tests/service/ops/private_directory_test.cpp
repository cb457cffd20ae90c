// Upload directories (server/service/ops/private_directory.hpp): named for the process that made
// them, removed when they go, and removed by the next process to start once their own is gone.
#include "service/ops/private_directory.hpp"

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <string>

#include "support/temp_directory.hpp"

namespace saasgaps::service {
namespace {

namespace fs = std::filesystem;

/// The id of a process that has ended (a child that exits at once, reaped).
pid_t ended_process() {
  const pid_t child = ::fork();
  if (child == 0) ::_exit(0);
  int status = 0;
  ::waitpid(child, &status, 0);
  return child;
}

TEST(PrivateDirectory, IsNamedForItsPurposeAndProcessAndGoesWithItsFiles) {
  fs::path path;
  {
    const PrivateDirectory dir("adapt");
    path = dir.path();
    dir.write("le1.geo", "lc = 0.25;\n");
    EXPECT_EQ(path.parent_path(), fs::temp_directory_path());
    EXPECT_TRUE(std::regex_match(path.filename().string(),
                                 std::regex("saasgaps-upload-adapt-" + std::to_string(::getpid()) + "-[A-Za-z0-9]{6}")))
        << path;
    EXPECT_EQ((fs::status(path).permissions() & fs::perms::all), fs::perms::owner_all);
    EXPECT_TRUE(fs::exists(path / "le1.geo"));
  }
  EXPECT_FALSE(fs::exists(path));
}

TEST(PrivateDirectory, OnlyTheDirectoriesOfEndedProcessesAreRemovedAtStart) {
  const testing::TempDirectory parent("abandoned-uploads");
  const std::string ended = std::to_string(ended_process());
  const std::string own = std::to_string(::getpid());
  const auto make = [&](const std::string& name) {
    fs::create_directories(parent.path() / name);
    std::ofstream(parent.path() / name / "upload.geo") << "Point(1) = {0, 0, 0};\n";
  };
  make("saasgaps-upload-adapt-" + ended + "-a1B2c3");   // killed mid-job: removed
  make("saasgaps-upload-import-" + ended + "-Zz9Yy8");  // killed mid-import: removed
  make("saasgaps-upload-adapt-" + own + "-a1B2c3");     // this process's own, in use: kept
  make("saasgaps-upload-adapt-1-a1B2c3");               // init's: alive, kept
  make("saasgaps-upload-adapt-" + ended + "-abc");      // not mkdtemp's name: kept
  make("saasgaps-upload-" + ended + "-a1B2c3");         // no purpose: kept
  make("saasgaps-le1-" + ended);                        // another program's: kept
  std::ofstream(parent.path() / ("saasgaps-upload-adapt-" + ended + "-fileXX")) << "a file, not a directory";

  EXPECT_EQ(remove_abandoned_uploads(parent.path()), 2);
  EXPECT_FALSE(fs::exists(parent.path() / ("saasgaps-upload-adapt-" + ended + "-a1B2c3")));
  EXPECT_FALSE(fs::exists(parent.path() / ("saasgaps-upload-import-" + ended + "-Zz9Yy8")));
  for (const std::string& kept :
       {"saasgaps-upload-adapt-" + own + "-a1B2c3", std::string("saasgaps-upload-adapt-1-a1B2c3"),
        "saasgaps-upload-adapt-" + ended + "-abc", "saasgaps-upload-" + ended + "-a1B2c3", "saasgaps-le1-" + ended,
        "saasgaps-upload-adapt-" + ended + "-fileXX"}) {
    EXPECT_TRUE(fs::exists(parent.path() / kept)) << kept;
  }
  EXPECT_EQ(remove_abandoned_uploads(parent.path()), 0) << "nothing more to remove";
  EXPECT_EQ(remove_abandoned_uploads(parent.path() / "missing"), 0) << "a parent that is not there";
}

}  // namespace
}  // namespace saasgaps::service
