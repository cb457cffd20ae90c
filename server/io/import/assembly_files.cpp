#include "io/import/assembly_files.hpp"

#include <utility>

namespace saasgaps::io::assembly {

namespace fs = std::filesystem;

AssemblyFiles::AssemblyFiles(fs::path base, FileAccess access) : base_(std::move(base)), access_(access) {}

std::optional<fs::path> AssemblyFiles::resolve(const std::string& name, std::string& problem) const {
  const fs::path given(name);
  if (access_ == FileAccess::base_only &&
      (given.filename() != given || name.empty() || name.front() == '.' || name.find('\\') != std::string::npos)) {
    problem = "\"" + name + "\" must be the plain name of an uploaded file (no directories)";
    return std::nullopt;
  }
  if (access_ == FileAccess::base_only && !fs::exists(base_ / given)) {
    problem = "no part of the upload carries the file \"" + name + "\": add a part with filename=\"" + name +
              "\" (curl -F 'file=@" + name + "')";
    return std::nullopt;
  }
  return given.is_absolute() ? given : base_ / given;
}

std::string AssemblyFiles::as_named(std::string detail) const {
  if (access_ == FileAccess::base_only) {
    const std::string directory = (base_ / "").string();
    for (std::size_t at = detail.find(directory); at != std::string::npos; at = detail.find(directory, at)) {
      detail.erase(at, directory.size());
    }
  }
  return detail;
}

}  // namespace saasgaps::io::assembly
