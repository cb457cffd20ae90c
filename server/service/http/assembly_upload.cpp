#include "service/http/assembly_upload.hpp"

#include <stdlib.h>

#include <cerrno>
#include <fstream>
#include <system_error>

#include "io/import/assembly_reader.hpp"
#include "io/model/model_reader.hpp"
#include "service/http/problem.hpp"

namespace saasgaps::service {

namespace {

namespace fs = std::filesystem;

/// A file name an upload may carry: one plain component, not hidden, no separators.
bool plain_name(const std::string& name) {
  return !name.empty() && name.front() != '.' && name.find('/') == std::string::npos &&
         name.find('\\') == std::string::npos && name.size() <= 255;
}

}  // namespace

UploadedFiles::UploadedFiles(const httplib::Request& req, const std::string& document_part, const std::string& route) {
  if (!req.is_multipart_form_data()) {
    throw HttpError(400, "Bad Request",
                    route + " takes multipart/form-data: a part \"" + document_part + "\" (the " + document_part +
                        " document) and one part per file it names, with that file's name as its filename");
  }
  if (!req.has_file(document_part)) {
    throw HttpError(400, "Bad Request", "the upload has no part named \"" + document_part + "\"");
  }
  document_ = req.get_file_value(document_part).content;
  std::string pattern = (fs::temp_directory_path() / "saasgaps-import-XXXXXX").string();
  if (::mkdtemp(pattern.data()) == nullptr) {
    throw std::system_error(errno, std::generic_category(), "cannot create a directory for the upload");
  }
  directory_ = pattern;
  try {
    for (const auto& [field, part] : req.files) {
      if (field == document_part) continue;
      if (!plain_name(part.filename)) {
        throw HttpError(400, "Bad Request", "part \"" + field + "\" must carry a plain file name (no directories, not "
                                            "hidden), got \"" + part.filename + "\"");
      }
      const fs::path target = directory_ / part.filename;
      if (fs::exists(target)) throw HttpError(400, "Bad Request", "two parts carry the file name \"" + part.filename + "\"");
      std::ofstream out(target, std::ios::binary);
      out.write(part.content.data(), static_cast<std::streamsize>(part.content.size()));
      if (!out) throw std::runtime_error("cannot store the uploaded file " + part.filename);
    }
  } catch (...) {
    std::error_code ignored;
    fs::remove_all(directory_, ignored);
    throw;
  }
}

UploadedFiles::~UploadedFiles() {
  std::error_code ignored;
  fs::remove_all(directory_, ignored);
}

nlohmann::json import_upload(const httplib::Request& req) {
  const UploadedFiles files(req, "assembly", "POST /v1/imports");
  return io::import_assembly(io::parse_document(files.document()), files.directory(), io::FileAccess::base_only);
}

}  // namespace saasgaps::service
