#pragma once
/// Uploads of an assembly and the files it names, as multipart/form-data (docs/import.md,
/// docs/studies.md): POST /v1/imports (a part `assembly`) and POST /v1/studies of an assembly (a
/// part `study`). Every other part is a file the document names (the mesh, a temperature file),
/// carrying that file's name as its filename. The files are written to a fresh private directory
/// that is removed afterwards; the assembly may name only those files (no paths).

#include <httplib.h>

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "service/ops/private_directory.hpp"
#include "service/store/job_store.hpp"

namespace saasgaps::service {

/// The files of an upload in a directory only this process can use (PrivateDirectory), removed
/// with everything in it when this object ends.
class UploadedFiles {
 public:
  /// Throws HttpError 400 for a request that is not such an upload: not multipart, no part named
  /// `document_part`, a part without a plain file name, two parts with the same file name. `route`
  /// ("POST /v1/imports") names the request in messages.
  UploadedFiles(const httplib::Request& req, const std::string& document_part, const std::string& route);

  /// The text of the document part.
  [[nodiscard]] const std::string& document() const { return document_; }
  /// Where the other parts are, each under its file name.
  [[nodiscard]] const std::filesystem::path& directory() const { return directory_.path(); }
  /// The other parts, (file name, content), in name order.
  [[nodiscard]] const std::vector<std::pair<std::string, std::string>>& files() const { return files_; }

 private:
  PrivateDirectory directory_;
  std::string document_;
  std::vector<std::pair<std::string, std::string>> files_;
};

/// What an upload holds, imported.
struct AssemblyUpload {
  nlohmann::json assembly;  ///< the assembly document
  AdaptiveInput input;      ///< its text and the uploaded files (what an adaptive job keeps)
  nlohmann::json model;     ///< the model document of its (first) mesh
};

/// POST /v1/imports: the upload imported. Throws HttpError 400 for a request that is not such an
/// upload, ModelError (422) with every issue of the assembly, each at its JSON Pointer.
AssemblyUpload import_upload(const httplib::Request& req);

}  // namespace saasgaps::service
