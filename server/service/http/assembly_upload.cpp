#include "service/http/assembly_upload.hpp"

#include <stdlib.h>

#include <filesystem>
#include <fstream>
#include <system_error>

#include "io/import/assembly_reader.hpp"
#include "io/model/model_reader.hpp"
#include "service/http/problem.hpp"

namespace saasgaps::service {

namespace {

namespace fs = std::filesystem;

/// A directory only this process can use (mkdtemp: mode 0700), removed with everything in it.
class PrivateDirectory {
 public:
  PrivateDirectory() {
    std::string pattern = (fs::temp_directory_path() / "saasgaps-import-XXXXXX").string();
    if (::mkdtemp(pattern.data()) == nullptr) {
      throw std::system_error(errno, std::generic_category(), "cannot create a directory for the upload");
    }
    path_ = pattern;
  }
  ~PrivateDirectory() {
    std::error_code ignored;
    fs::remove_all(path_, ignored);
  }
  PrivateDirectory(const PrivateDirectory&) = delete;
  PrivateDirectory& operator=(const PrivateDirectory&) = delete;
  [[nodiscard]] const fs::path& path() const { return path_; }

 private:
  fs::path path_;
};

/// A file name an upload may carry: one plain component, not hidden, no separators.
bool plain_name(const std::string& name) {
  return !name.empty() && name.front() != '.' && name.find('/') == std::string::npos &&
         name.find('\\') == std::string::npos && name.size() <= 255;
}

}  // namespace

nlohmann::json import_upload(const httplib::Request& req) {
  if (!req.is_multipart_form_data()) {
    throw HttpError(400, "Bad Request",
                    "POST /v1/imports takes multipart/form-data: a part \"assembly\" (the assembly document) and "
                    "one part per file it names, with that file's name as its filename");
  }
  if (!req.has_file("assembly")) throw HttpError(400, "Bad Request", "the upload has no part named \"assembly\"");
  const nlohmann::json assembly = io::parse_document(req.get_file_value("assembly").content);
  const PrivateDirectory dir;
  for (const auto& [field, part] : req.files) {
    if (field == "assembly") continue;
    if (!plain_name(part.filename)) {
      throw HttpError(400, "Bad Request", "part \"" + field + "\" must carry a plain file name (no directories, not "
                                          "hidden), got \"" + part.filename + "\"");
    }
    const fs::path target = dir.path() / part.filename;
    if (fs::exists(target)) throw HttpError(400, "Bad Request", "two parts carry the file name \"" + part.filename + "\"");
    std::ofstream out(target, std::ios::binary);
    out.write(part.content.data(), static_cast<std::streamsize>(part.content.size()));
    if (!out) throw std::runtime_error("cannot store the uploaded file " + part.filename);
  }
  return io::import_assembly(assembly, dir.path(), io::FileAccess::base_only);
}

}  // namespace saasgaps::service
