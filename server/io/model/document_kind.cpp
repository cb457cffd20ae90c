#include "io/model/document_kind.hpp"

#include <algorithm>

namespace saasgaps::io {

DocumentKind document_kind(const nlohmann::json& document) {
  if (!document.is_object()) return DocumentKind::unknown;
  if (document.contains("format") && document["format"] == "saasgaps-restart-state") return DocumentKind::restart_state;
  if (document.contains("schema_version")) return DocumentKind::model;
  if (document.contains("status") && document.contains("history")) return DocumentKind::result;
  return DocumentKind::unknown;
}

namespace {

/// The reader reported `key` as an unknown top-level key.
bool unknown_top_level_key(const std::vector<InputIssue>& issues, const std::string& key) {
  return std::any_of(issues.begin(), issues.end(), [&](const InputIssue& issue) {
    return issue.pointer == "/" + key && issue.detail.rfind("unknown key", 0) == 0;
  });
}

bool missing_schema_version(const std::vector<InputIssue>& issues) {
  return std::any_of(issues.begin(), issues.end(), [](const InputIssue& issue) {
    return issue.pointer.empty() && issue.detail.find("\"schema_version\"") != std::string::npos;
  });
}

}  // namespace

bool names_assembly(const ModelError& error) {
  return unknown_top_level_key(error.issues(), "mesh") && unknown_top_level_key(error.issues(), "regions");
}

void rethrow_naming_document(const ModelError& error) {
  const std::vector<InputIssue>& issues = error.issues();
  if (missing_schema_version(issues)) {
    if (unknown_top_level_key(issues, "status") && unknown_top_level_key(issues, "history")) {
      throw ModelError(std::vector<InputIssue>{
          {"", "this is a result document (written by saasgaps solve), not a model; give the model it was solved from"}});
    }
    if (unknown_top_level_key(issues, "format") && unknown_top_level_key(issues, "model_digest")) {
      throw ModelError(std::vector<InputIssue>{
          {"", "this is a restart state (written by saasgaps solve --state-out), not a model; give the model, and "
               "the state with --resume"}});
    }
  }
  throw error;
}

}  // namespace saasgaps::io
