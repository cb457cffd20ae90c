#pragma once
/// The digest of a model document that a restart state carries (io/restart/state_codec.hpp).

#include <string>

#include <nlohmann/json.hpp>

#include "io/json/fingerprint.hpp"

namespace saasgaps::io {

/// Digest of the parts of a model document that a restart state depends on (everything except
/// title, description and output): a resume against another model is refused. It is the
/// Fingerprint of their compact dump, keys sorted; parse_model (io/model_reader.hpp) computes the
/// same from the text without a tree of the whole document.
std::string model_digest(const nlohmann::json& model_document);

}  // namespace saasgaps::io
