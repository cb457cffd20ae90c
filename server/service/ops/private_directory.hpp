#pragma once
/// A directory only this process can use (mkdtemp: mode 0700) under the system's temporary
/// directory, removed with everything in it when destroyed: where uploaded assembly files are
/// imported from (POST /v1/imports, and each cycle of an adaptive job).

#include <filesystem>
#include <string>

namespace saasgaps::service {

class PrivateDirectory {
 public:
  /// `prefix`: the start of the directory's name ("saasgaps-import-"). Throws std::system_error.
  explicit PrivateDirectory(const std::string& prefix);
  ~PrivateDirectory();
  PrivateDirectory(const PrivateDirectory&) = delete;
  PrivateDirectory& operator=(const PrivateDirectory&) = delete;
  [[nodiscard]] const std::filesystem::path& path() const { return path_; }
  /// Writes `content` as the file `name` (one plain component) in the directory.
  void write(const std::string& name, const std::string& content) const;

 private:
  std::filesystem::path path_;
};

}  // namespace saasgaps::service
