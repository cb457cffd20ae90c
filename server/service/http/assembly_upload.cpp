#include "service/http/assembly_upload.hpp"

#include <algorithm>
#include <filesystem>

#include "io/import/assembly_reader.hpp"
#include "io/model/model_reader.hpp"
#include "service/http/problem.hpp"
#include "service/ops/private_directory.hpp"

namespace saasgaps::service {

namespace {

namespace fs = std::filesystem;

/// A file name an upload may carry: one plain component, not hidden, no separators.
bool plain_name(const std::string& name) {
  return !name.empty() && name.front() != '.' && name.find('/') == std::string::npos &&
         name.find('\\') == std::string::npos && name.size() <= 255;
}

}  // namespace

AssemblyUpload import_upload(const httplib::Request& req) {
  if (!req.is_multipart_form_data()) {
    throw HttpError(400, "Bad Request",
                    "POST /v1/imports takes multipart/form-data: a part \"assembly\" (the assembly document) and "
                    "one part per file it names, with that file's name as its filename");
  }
  if (!req.has_file("assembly")) throw HttpError(400, "Bad Request", "the upload has no part named \"assembly\"");
  AssemblyUpload upload;
  upload.input.assembly = req.get_file_value("assembly").content;
  upload.assembly = io::parse_document(upload.input.assembly);
  const PrivateDirectory dir("saasgaps-import-");
  for (const auto& [field, part] : req.files) {
    if (field == "assembly") continue;
    if (!plain_name(part.filename)) {
      throw HttpError(400, "Bad Request", "part \"" + field + "\" must carry a plain file name (no directories, not "
                                          "hidden), got \"" + part.filename + "\"");
    }
    if (fs::exists(dir.path() / part.filename)) {
      throw HttpError(400, "Bad Request", "two parts carry the file name \"" + part.filename + "\"");
    }
    dir.write(part.filename, part.content);
    upload.input.files.emplace_back(part.filename, part.content);
  }
  std::sort(upload.input.files.begin(), upload.input.files.end());
  upload.model = io::import_assembly(upload.assembly, dir.path(), io::FileAccess::base_only);
  return upload;
}

}  // namespace saasgaps::service
