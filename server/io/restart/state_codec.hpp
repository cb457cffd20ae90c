#pragma once
/// Restart states as documents: JSON for files (`saasgaps solve --state-out`), CBOR (the same
/// structure, binary) for the service's database. Doubles round-trip exactly in both, which is
/// what makes a resumed run identical to the last digit.

#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "io/model/model_digest.hpp"
#include "solver/state/restart_state.hpp"

namespace saasgaps::io {

nlohmann::json state_to_json(const RestartState& state, const std::string& digest);

/// Throws SolverError when the document is not a restart state of a supported version, or was saved
/// for a model with another digest (pass an empty expected_digest to skip that check).
RestartState state_from_json(const nlohmann::json& document, const std::string& expected_digest);

std::vector<std::uint8_t> state_to_cbor(const RestartState& state, const std::string& digest);
/// The CBOR of a restart state as a tree (io/json_limits.hpp's parse_cbor); throws SolverError
/// ("malformed restart state: ...") for bytes that are not CBOR or nest too deep.
nlohmann::json restart_state_tree(std::span<const std::uint8_t> cbor);
RestartState state_from_cbor(const std::vector<std::uint8_t>& bytes, const std::string& expected_digest);

}  // namespace saasgaps::io
