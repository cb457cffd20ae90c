#pragma once
/// Restart states as documents: JSON for files (`saasgaps solve --state-out`), CBOR (the same
/// structure, binary) for the service's database. Doubles round-trip exactly in both, which is
/// what makes a resumed run identical to the last digit.

#include <cstdint>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "restart_state.hpp"

namespace saasgaps::io {

/// Digest of the parts of a model document that a restart state depends on (everything except
/// title, description and output): a resume against another model is refused.
std::string model_digest(const nlohmann::json& model_document);

nlohmann::json state_to_json(const RestartState& state, const std::string& digest);

/// Throws SolverError when the document is not a restart state of a supported version, or was saved
/// for a model with another digest (pass an empty expected_digest to skip that check).
RestartState state_from_json(const nlohmann::json& document, const std::string& expected_digest);

std::vector<std::uint8_t> state_to_cbor(const RestartState& state, const std::string& digest);
RestartState state_from_cbor(const std::vector<std::uint8_t>& bytes, const std::string& expected_digest);

}  // namespace saasgaps::io
