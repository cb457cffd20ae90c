#pragma once
/// A restart state through each encoding a resume reads it from, for the restart tests: each resumes
/// from every encoding and expects the uninterrupted run to the last digit.

#include <array>
#include <string>
#include <string_view>

#include "io/restart/state_codec.hpp"
#include "io/restart/stored_state.hpp"
#include "solver/state/restart_state.hpp"

namespace saasgaps::testing {

/// The encodings a resume reads a state from: the JSON and CBOR restart states, the service's stored form.
constexpr std::array<std::string_view, 3> state_codecs{"json", "cbor", "stored"};

/// `state` encoded with `codec` (one of state_codecs) for the model of `digest`, and read back.
inline RestartState through_codec(std::string_view codec, const RestartState& state, const std::string& digest) {
  if (codec == "json") return io::state_from_json(io::state_to_json(state, digest), digest);
  if (codec == "cbor") return io::state_from_cbor(io::state_to_cbor(state, digest), digest);
  return io::decode_stored_state(io::encode_stored_state(state, digest), digest);
}

}  // namespace saasgaps::testing
