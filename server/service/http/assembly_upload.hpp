#pragma once
/// POST /v1/imports: an assembly and the files it names, uploaded as multipart/form-data, imported
/// into a model document (docs/import.md). Parts: `assembly` (the assembly document, JSON) and one
/// part per file it names (the mesh, a temperature file), each carrying that file's name as its
/// filename. The files are written to a fresh private directory that is removed afterwards; the
/// assembly may name only those files (no paths).

#include <httplib.h>

#include <nlohmann/json.hpp>

#include "service/store/job_store.hpp"

namespace saasgaps::service {

/// What an upload holds, imported.
struct AssemblyUpload {
  nlohmann::json assembly;  ///< the assembly document
  AdaptiveInput input;      ///< its text and the uploaded files (what an adaptive job keeps)
  nlohmann::json model;     ///< the model document of its (first) mesh
};

/// The upload imported. Throws HttpError 400 for a request that is not such an upload, ModelError
/// (422) with every issue of the assembly, each at its JSON Pointer.
AssemblyUpload import_upload(const httplib::Request& req);

}  // namespace saasgaps::service
