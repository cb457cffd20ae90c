#pragma once
/// Fill-reducing orderings kept between runs, one file per matrix pattern. Computing the ordering
/// (METIS) is most of the symbolic analysis: 2-3 s at 10^6 unknowns, more than a numeric
/// factorization. Re-runs, resumes and other jobs on the same mesh load it instead.
///
/// A file is found by the pattern's key (a 128-bit fingerprint of n, the pattern, the unknown
/// groups and the method that computed the ordering, CHOLMOD's version included) and holds the
/// ordering with its key, size and a checksum. A file that fails any check (truncated, corrupt,
/// another key or size, not a permutation) is a miss: the ordering is computed again and the file
/// rewritten. Any ordering gives the same factorization's answer up to round-off; the same
/// ordering (computed or loaded) gives the same answer to the last digit.

#include <cstdint>
#include <filesystem>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "solver/lac/csc_pattern.hpp"

namespace saasgaps {

struct PatternKey {
  std::uint64_t high = 0;
  std::uint64_t low = 0;
  [[nodiscard]] std::string hex() const;  ///< 32 hex digits, the file name
  bool operator==(const PatternKey&) const = default;
};

/// The fingerprint of a pattern, its groups of unknowns, and the ordering method (a text naming
/// the method, its options and the library versions). O(nnz), about 10 ms at 10^6 unknowns.
PatternKey pattern_key(const CscPattern& pattern, std::span<const Index> groups, std::string_view method);

/// A key for something more that depends on what `key` names and on `more` (a text naming it and
/// the settings that shape it).
PatternKey derived_key(const PatternKey& key, std::string_view more);

class OrderingCache {
 public:
  /// The directory is created on the first store.
  explicit OrderingCache(std::filesystem::path directory);

  /// The ordering saved under `key` for n unknowns, when a valid one is there.
  [[nodiscard]] std::optional<std::vector<Index>> load(const PatternKey& key, Index n) const;

  /// Saves an ordering (written to a temporary file, then renamed into place). A cache that cannot
  /// be written is not an error: the run goes on, and the next one computes the ordering again.
  void store(const PatternKey& key, std::span<const Index> order) const;

  [[nodiscard]] std::filesystem::path file(const PatternKey& key) const;
  [[nodiscard]] const std::filesystem::path& directory() const { return directory_; }

 private:
  std::filesystem::path directory_;
};

/// True when `order` holds each of 0..n-1 exactly once.
bool is_permutation_of(std::span<const Index> order, Index n);

}  // namespace saasgaps
