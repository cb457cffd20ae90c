#pragma once
/// The files an assembly names (its mesh, a temperature file), under the FileAccess it was given:
/// where each is looked up, and how a message names them. No JSON: the importer reports the
/// problems at the pointers of the names.

#include <filesystem>
#include <optional>
#include <string>

#include "io/import/assembly_reader.hpp"

namespace saasgaps::io::assembly {

class AssemblyFiles {
 public:
  AssemblyFiles(std::filesystem::path base, FileAccess access);

  /// The file `name` names: relative names against the base directory. Nullopt and a sentence in
  /// `problem` when it may not be read (with FileAccess::base_only, a name that is not a plain file
  /// name, or no uploaded file by that name).
  std::optional<std::filesystem::path> resolve(const std::string& name, std::string& problem) const;

  /// `detail` with the base directory taken out of the paths in it, for uploads: their files sit in
  /// a private directory the client never saw, so a message names them as uploaded.
  std::string as_named(std::string detail) const;

 private:
  std::filesystem::path base_;
  FileAccess access_;
};

}  // namespace saasgaps::io::assembly
