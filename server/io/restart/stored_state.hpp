#pragma once
/// The restart state as the service stores it in its database (and as workers may send it): one
/// pair of functions, so every path that stores or loads a state shares the encoding.
///
/// Encoding (version 2): the 4 bytes "SGZ1", then zlib (level 1) of the CBOR of state_to_json, in
/// which the displacement array, most of the state, is a CBOR byte string of the doubles with their
/// bytes shuffled (all first bytes, then all second bytes, ...): sign and exponent bytes of
/// neighbouring values are alike, so zlib finds them, while the low mantissa bytes are noise
/// whatever is done. Measured on a 149,000-unknown annulus: 0.69 of the plain CBOR, in 70 ms less
/// than JSON-to-CBOR alone. Doubles round-trip exactly, so a resume is still exact.
///
/// Version 1, still read: plain CBOR of state_to_json (a CBOR map, first byte 0xa0-0xbf, never "S").
/// (These are versions of the storage encoding; the state inside has its own version, state_codec.hpp:
/// 2 for a stepped model, whose position on the load path rides along as a plain array.)

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "solver/state/restart_state.hpp"

namespace saasgaps::io {

std::vector<std::uint8_t> encode_stored_state(const RestartState& state, const std::string& digest);

/// The most a compressed state may inflate to (1 GiB): the displacements of 10^7 unknowns are 80 MB, and
/// a state comes from a worker's request, so a zlib bomb (zlib reaches about 1000:1) must not be
/// able to take the service's memory.
inline constexpr std::size_t max_inflated_state_bytes = std::size_t{1} << 30;

/// Either encoding. Throws SolverError for a damaged or foreign state (see state_from_json), or one
/// that inflates beyond `max_inflated` bytes.
RestartState decode_stored_state(std::span<const std::uint8_t> bytes, const std::string& expected_digest,
                                 std::size_t max_inflated = max_inflated_state_bytes);

}  // namespace saasgaps::io
