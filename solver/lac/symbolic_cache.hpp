#pragma once
/// The whole symbolic analysis kept between runs, one file per matrix pattern and CHOLMOD settings:
/// the supernodal symbolic factor CHOLMOD made (the final permutation after postordering, the
/// column counts, the supernodes and their row patterns) and the analysis's statistics. A run that
/// finds it rebuilds the factor with CHOLMOD's own allocation routines and skips the analysis
/// altogether (METIS, permutation, elimination tree, postorder, column counts, supernodes).
///
/// A file is found by its key (ordering_cache.hpp's pattern key, derived further with the CHOLMOD
/// settings that shape the supernodes). On load the file is checked whole (magic, format, key, n,
/// exact length, a checksum over every word) and so is the structure, against the pattern: a file
/// that passes every check, even one written wrongly, cannot make CHOLMOD read or write out of
/// bounds, and its factor holds every entry of the true one. Any failure is a miss.

#include <cstdint>
#include <filesystem>
#include <span>

#include "solver/lac/csc_pattern.hpp"
#include "solver/lac/ordering_cache.hpp"

struct cholmod_factor_struct;
struct cholmod_common_struct;

namespace saasgaps {

/// What the analysis reports beside the factor, kept with it.
struct SymbolicStatistics {
  double flops = 0.0;           ///< of one numeric factorization (CHOLMOD's Common->fl)
  double factor_entries = 0.0;  ///< nnz(L) (Common->lnz)
};

/// A supernodal symbolic factor as plain arrays (CHOLMOD's L->Perm, ColCount, super, pi, px, s).
struct SupernodalStructure {
  std::span<const Index> perm;      ///< n: row k of L is unknown perm[k]
  std::span<const Index> colcount;  ///< n: entries of column k in the simplicial factor
  std::span<const Index> super;     ///< nsuper + 1: first column of each supernode, then n
  std::span<const Index> pi;        ///< nsuper + 1: where each supernode's rows start in s
  std::span<const Index> px;        ///< nsuper + 1: where each supernode's values start in L->x
  std::span<const Index> s;         ///< ssize: rows of each supernode, its own columns first
  std::uint64_t xsize = 0;          ///< values of L: px[nsuper]
  std::uint64_t maxcsize = 0;       ///< largest update matrix (at least 1)
  std::uint64_t maxesize = 0;       ///< most rows below a supernode's triangle (at least 1)
};

/// The arrays of CHOLMOD's supernodal factor L (symbolic or numeric), as views.
SupernodalStructure supernodal_structure(const cholmod_factor_struct& L);

/// Whether `f` is a supernodal symbolic factor of the upper-triangular `pattern` that CHOLMOD can
/// factorize safely: perm a permutation; super strictly increasing from 0 to n; pi and px
/// consistent with each supernode's columns and rows; each supernode's rows strictly increasing in
/// [0, n), starting with its own columns; every entry of P A P' inside the supernode of its column;
/// the rows below each supernode contained in the rows of its parent (the supernode of its first
/// such row), which with the previous condition makes the pattern closed under elimination;
/// maxcsize and maxesize those of the structure; column counts within the supernodal columns.
/// O(nnz(A) log n + ssize).
bool is_supernodal_structure_of(const SupernodalStructure& f, const CscPattern& pattern);

class SymbolicCache {
 public:
  /// The directory is created on the first store.
  explicit SymbolicCache(std::filesystem::path directory);

  /// The factor saved under `key` for `pattern`, allocated in `common`, when a valid one is there;
  /// nullptr otherwise (nothing left allocated).
  [[nodiscard]] cholmod_factor_struct* load(const PatternKey& key, const CscPattern& pattern,
                                            SymbolicStatistics& statistics, cholmod_common_struct& common) const;

  /// Saves a supernodal symbolic (or numeric: the values are not saved) factor atomically. A cache
  /// that cannot be written is not an error.
  void store(const PatternKey& key, const cholmod_factor_struct& factor, const SymbolicStatistics& statistics) const;
  /// The same from plain arrays (ordering_method: CHOLMOD's L->ordering).
  void store(const PatternKey& key, const SupernodalStructure& factor, int ordering_method,
             const SymbolicStatistics& statistics) const;

  [[nodiscard]] std::filesystem::path file(const PatternKey& key) const;

 private:
  std::filesystem::path directory_;
};

}  // namespace saasgaps
