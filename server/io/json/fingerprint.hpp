#pragma once
/// A 64-bit fingerprint of text given in pieces (FNV-1a): model digests, lease secrets, request bodies.

#include <cstdint>
#include <string>
#include <string_view>

namespace saasgaps::io {

/// FNV-1a, 64 bit, over text given in pieces: a fingerprint against mix-ups, not a security measure.
class Fingerprint {
 public:
  void add(std::string_view text);
  /// 16 lower-case hex digits.
  [[nodiscard]] std::string hex() const;

 private:
  std::uint64_t hash_ = 1469598103934665603ULL;
};

}  // namespace saasgaps::io
