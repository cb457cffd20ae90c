#include "io/json/fingerprint.hpp"

#include <cstdio>

namespace saasgaps::io {

void Fingerprint::add(std::string_view text) {
  // In a local: the text's chars may alias hash_, which would be stored and reloaded per byte.
  std::uint64_t hash = hash_;
  for (const unsigned char c : text) {
    hash ^= c;
    hash *= 1099511628211ULL;
  }
  hash_ = hash;
}

std::string Fingerprint::hex() const {
  char text[17];
  std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(hash_));
  return text;
}

}  // namespace saasgaps::io
