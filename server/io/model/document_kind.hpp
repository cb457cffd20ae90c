#pragma once
/// Which of SAASGAPS's documents a JSON document is: a model (schema_version), a result document
/// (status and history), a restart state (format "saasgaps-restart-state"). Commands that read one
/// kind say so when handed another ("this is a model; run solve first") instead of listing the
/// keys they did not expect.

#include <nlohmann/json.hpp>
#include <string>

#include "solver/base/errors.hpp"

namespace saasgaps::io {

enum class DocumentKind { model, result, restart_state, unknown };

/// The kind of a parsed document by the keys only one kind has; unknown for anything else.
DocumentKind document_kind(const nlohmann::json& document);

/// The model reader's verdict on a document that is not a model: when its issues show the top-level
/// keys of a result (status, history) or of a restart state (format, model_digest) and no
/// schema_version, throws one issue at "" naming the kind instead; otherwise rethrows `error`. The
/// streaming reader keeps no tree, so the kind is read off the issues it found.
[[noreturn]] void rethrow_naming_document(const ModelError& error);

/// Whether the model reader's issues show an assembly document (docs/import.md): unknown top-level
/// keys "mesh" and "regions", which only an assembly has. `saasgaps solve` then imports it.
bool names_assembly(const ModelError& error);

}  // namespace saasgaps::io
