#pragma once
/// What the files of the solver's caches (ordering_cache, symbolic_cache) share: the checksum, the
/// atomic write and the reading of arrays of 64-bit words. Files are little-endian as the machine
/// writes them (their keys name the build anyway).

#include <cstdint>
#include <filesystem>
#include <functional>
#include <istream>
#include <ostream>
#include <span>

#include "solver/lac/csc_pattern.hpp"

namespace saasgaps {

/// A 64-bit mixing hash over 64-bit words (the finalizer of splitmix64 on an FNV-style chain):
/// fast on the large arrays and sensitive to every bit.
struct WordHash {
  std::uint64_t state;
  explicit WordHash(std::uint64_t seed) : state(seed) {}
  void add(std::uint64_t word) {
    std::uint64_t z = (state ^ word) + 0x9e3779b97f4a7c15ULL;
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    state = z ^ (z >> 31);
  }
  template <class T>
  void add_all(std::span<const T> values) {
    add(values.size());
    for (T v : values) add(static_cast<std::uint64_t>(v));
  }
};

/// Reads `count` words into `out` in chunks (one touch of the destination, no zero fill first).
/// False when the stream ends first.
bool read_words(std::istream& in, Index* out, std::size_t count);

/// Writes `target` through a temporary file in the same directory (created if missing), renamed
/// into place once `write` has written it whole: readers see the old file or the new one, never
/// half of it. Unique per process and call, so two workers may store the same file at once. A
/// file that cannot be written is not an error: false, and no file is left behind.
bool write_atomically(const std::filesystem::path& target, const std::function<void(std::ostream&)>& write);

}  // namespace saasgaps
