#pragma once
/// A directory only this process can use (mkdtemp: mode 0700) under the system's temporary
/// directory, removed with everything in it when destroyed: where uploaded assembly files are
/// imported from (POST /v1/imports, and each cycle of an adaptive job).
///
/// Its name, saasgaps-upload-<purpose>-<pid>-XXXXXX, carries the process that made it: a process
/// killed (kill -9, a crash, a node lost) runs no destructor, so the next server or worker to start
/// removes the directories of processes that no longer exist (remove_abandoned_uploads).

#include <filesystem>
#include <string>

namespace saasgaps::service {

class PrivateDirectory {
 public:
  /// `purpose`: lower-case letters naming the use ("import", "adapt"). Throws std::system_error.
  explicit PrivateDirectory(const std::string& purpose);
  ~PrivateDirectory();
  PrivateDirectory(const PrivateDirectory&) = delete;
  PrivateDirectory& operator=(const PrivateDirectory&) = delete;
  [[nodiscard]] const std::filesystem::path& path() const { return path_; }
  /// Writes `content` as the file `name` (one plain component) in the directory.
  void write(const std::string& name, const std::string& content) const;

 private:
  std::filesystem::path path_;
};

/// Removes the PrivateDirectory directories in `parent` (the system's temporary directory by
/// default) whose process no longer exists (kill(pid, 0) answers ESRCH); returns how many. A
/// directory of a live process, this one's included, and every other name are left alone. Errors
/// (a directory that cannot be read or removed) are skipped: this is tidying, not a precondition.
int remove_abandoned_uploads(const std::filesystem::path& parent = std::filesystem::temp_directory_path());

}  // namespace saasgaps::service
