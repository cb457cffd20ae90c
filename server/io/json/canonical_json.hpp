#pragma once
/// The canonical form of a JSON document, the key of the result cache (docs/studies.md): two
/// documents that mean the same values have the same canonical text, whatever their key order,
/// number spelling or whitespace; any value that differs gives another text.
///
///   - objects: keys sorted by their UTF-8 bytes (a repeated key is the parser's to refuse);
///   - numbers: every number as the double it denotes (the model reader reads every number as a
///     double), printed as the shortest text that reads back to the same double (std::to_chars):
///     1, 1.0, 1e0 and 10e-1 are all "1"; 0.1 + 2^-55 differs from 0.1 in the 17th digit and stays
///     distinct; -0 stays "-0";
///   - strings: JSON escapes of nlohmann's dump (invalid UTF-8 as U+FFFD, io/json/json_text.hpp);
///   - no whitespace.

#include <cstddef>
#include <string>

#include <nlohmann/json.hpp>

namespace saasgaps::io {

/// The canonical text of a parsed document.
std::string canonical_json(const nlohmann::json& document);

/// The result cache's key of a canonical text: "r<result_version>-<bytes>-<FNV-1a 64 hex>", e.g.
/// "r1-5123-0123456789abcdef". The fingerprint only finds a candidate: a cache compares the
/// canonical texts themselves before it answers (a collision is then a miss, never a false hit).
std::string cache_key(const std::string& canonical_text);

}  // namespace saasgaps::io
