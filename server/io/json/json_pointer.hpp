#pragma once
/// RFC 6901 JSON Pointers, built one reference token at a time. Every issue the model reader reports
/// is located by one of these, so a user (or a client of the HTTP API) can find the offending value.

#include <cstddef>
#include <string>
#include <string_view>

namespace saasgaps::io {

/// Escapes one reference token: "~" becomes "~0" and "/" becomes "~1" (in that order, as RFC 6901
/// section 4 requires for the reverse direction to be unambiguous).
std::string escape_token(std::string_view key);

/// The pointer to member `key` of the object at `base`: base + "/" + escape_token(key).
/// The document root is the empty pointer "", so pointer_append("", "nodes") == "/nodes".
std::string pointer_append(const std::string& base, std::string_view key);

/// The pointer to element `index` of the array at `base`: base + "/" + decimal index.
std::string pointer_append(const std::string& base, std::size_t index);

}  // namespace saasgaps::io
