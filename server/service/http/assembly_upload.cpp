#include "service/http/assembly_upload.hpp"

#include <algorithm>

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

UploadedFiles::UploadedFiles(const httplib::Request& req, const std::string& document_part, const std::string& route)
    : directory_("import") {
  if (!req.is_multipart_form_data()) {
    throw HttpError(400, "Bad Request",
                    route + " takes multipart/form-data: a part \"" + document_part + "\" (the " + document_part +
                        " document) and one part per file it names, with that file's name as its filename");
  }
  if (!req.has_file(document_part)) {
    throw HttpError(400, "Bad Request", "the upload has no part named \"" + document_part + "\"");
  }
  document_ = req.get_file_value(document_part).content;
  for (const auto& [field, part] : req.files) {
    if (field == document_part) continue;
    if (!plain_name(part.filename)) {
      throw HttpError(400, "Bad Request", "part \"" + field + "\" must carry a plain file name (no directories, not "
                                          "hidden), got \"" + part.filename + "\"");
    }
    if (fs::exists(directory_.path() / part.filename)) {
      throw HttpError(400, "Bad Request", "two parts carry the file name \"" + part.filename + "\"");
    }
    directory_.write(part.filename, part.content);
    files_.emplace_back(part.filename, part.content);
  }
  std::sort(files_.begin(), files_.end());
}

AssemblyUpload import_upload(const httplib::Request& req) {
  const UploadedFiles files(req, "assembly", "POST /v1/imports");
  AssemblyUpload upload;
  upload.input.assembly = files.document();
  upload.input.files = files.files();
  upload.assembly = io::parse_document(upload.input.assembly);
  upload.model = io::import_assembly(upload.assembly, files.directory(), io::FileAccess::base_only);
  return upload;
}

}  // namespace saasgaps::service
