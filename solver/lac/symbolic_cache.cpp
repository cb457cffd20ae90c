#include "solver/lac/symbolic_cache.hpp"

#include <cholmod.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstring>
#include <fstream>

#include "solver/lac/cache_file.hpp"

namespace saasgaps {

namespace {

/// File layout, little-endian as the machine writes it (the key names the build anyway):
///   magic[16] | header: 12 x u64 | Perm: n | ColCount: n | super, pi, px: nsuper + 1 each |
///   s: ssize | checksum u64
/// The header: format, key high, key low, n, nsuper, ssize, xsize, maxcsize, maxesize, ordering,
/// flops and nnz(L) (the bits of the doubles). Arrays are int64. The checksum covers the header
/// and every array.
constexpr char magic[16] = "SAASGAPS-SYMBOL";
constexpr std::uint64_t format_version = 1;

enum Field { format, key_high, key_low, size, nsuper, ssize, xsize, maxcsize, maxesize, ordering, flops, lnz, fields };

constexpr std::uintmax_t file_bytes(std::uint64_t n, std::uint64_t supernodes, std::uint64_t s_size) {
  return sizeof magic + 8 * (fields + 2 * n + 3 * (supernodes + 1) + s_size + 1);
}

/// The checksum of the header and the arrays, in file order.
using FactorArrays = std::array<std::span<const Index>, 6>;

std::uint64_t checksum(std::span<const std::uint64_t> header, const FactorArrays& arrays) {
  WordHash h(0x7e57'ab1e'5eed'0001ULL);
  h.add_all(header);
  for (std::span<const Index> a : arrays) h.add_all(a);
  return h.state;
}

template <class T>
std::span<const Index> array(void* data, T count) {
  return {static_cast<const Index*>(data), static_cast<std::size_t>(count)};
}

/// The arrays of a supernodal symbolic factor, in file order.
FactorArrays arrays_of(const SupernodalStructure& f) { return {f.perm, f.colcount, f.super, f.pi, f.px, f.s}; }

}  // namespace

SupernodalStructure supernodal_structure(const cholmod_factor& L) {
  return {array(L.Perm, L.n),        array(L.ColCount, L.n), array(L.super, L.nsuper + 1), array(L.pi, L.nsuper + 1),
          array(L.px, L.nsuper + 1), array(L.s, L.ssize),    L.xsize,
          L.maxcsize,                L.maxesize};
}

bool is_supernodal_structure_of(const SupernodalStructure& f, const CscPattern& pattern) {
  const Index n = pattern.n;
  if (n <= 0 || !is_permutation_of(f.perm, n) || static_cast<Index>(f.colcount.size()) != n) return false;
  if (f.super.size() < 2 || f.pi.size() != f.super.size() || f.px.size() != f.super.size()) return false;
  const std::size_t supernodes = f.super.size() - 1;
  const auto& super = f.super;
  if (super[0] != 0 || super[supernodes] != n || f.pi[0] != 0 || f.px[0] != 0) return false;
  if (f.pi[supernodes] != static_cast<Index>(f.s.size())) return false;

  // Supernodes, their rows and their values. Every later index is bounded by these checks.
  std::vector<Index> supernode_of(static_cast<std::size_t>(n));
  std::uint64_t most_below = 1;
  for (std::size_t k = 0; k < supernodes; ++k) {
    const Index first = super[k], end = super[k + 1];
    if (end <= first) return false;
    const Index columns = end - first;
    // pi[k] is in range already: compare before subtracting, so nothing can overflow.
    if (f.pi[k + 1] < f.pi[k] + columns || f.pi[k + 1] > f.pi[supernodes]) return false;
    const Index rows = f.pi[k + 1] - f.pi[k];
    const Index* row = f.s.data() + f.pi[k];
    for (Index t = 0; t < columns; ++t) {
      if (row[t] != first + t) return false;
      supernode_of[first + t] = static_cast<Index>(k);
    }
    for (Index t = columns; t < rows; ++t) {
      if (row[t] <= row[t - 1] || row[t] >= n) return false;
    }
    // rows <= n - first now, so the product does not overflow.
    if (f.px[k + 1] != f.px[k] + columns * rows) return false;
    most_below = std::max(most_below, static_cast<std::uint64_t>(rows - columns));
    for (Index t = 0; t < columns; ++t) {
      const Index count = f.colcount[first + t];
      if (count < 1 || count > rows - t) return false;
    }
  }
  if (f.px[supernodes] < 0 || static_cast<std::uint64_t>(f.px[supernodes]) != f.xsize || f.maxesize != most_below) {
    return false;
  }

  // The rows below each supernode lie in its parent's rows, and the largest update matrix is the
  // one CHOLMOD computed (the same loop as cholmod_super_symbolic's).
  std::uint64_t largest_update = 1;
  for (std::size_t d = 0; d < supernodes; ++d) {
    const Index* begin = f.s.data() + f.pi[d] + (super[d + 1] - super[d]);
    const Index* end = f.s.data() + f.pi[d + 1];
    if (begin == end) continue;
    const auto parent = static_cast<std::size_t>(supernode_of[*begin]);
    if (!std::includes(f.s.data() + f.pi[parent], f.s.data() + f.pi[parent + 1], begin, end)) return false;
    for (const Index* last = begin; last != end;) {
      const Index target = supernode_of[*last];
      const Index* next = std::find_if(last, end, [&](Index r) { return supernode_of[r] != target; });
      largest_update = std::max(largest_update, static_cast<std::uint64_t>((end - last) * (next - last)));
      last = next;
    }
  }
  if (f.maxcsize != largest_update) return false;

  // Every entry of P A P' (lower triangle: row r >= column c) is a row of the supernode of c.
  std::vector<Index> inverse(static_cast<std::size_t>(n));
  for (Index k = 0; k < n; ++k) inverse[f.perm[k]] = k;
  if (static_cast<Index>(pattern.colptr.size()) != n + 1) return false;
  for (Index j = 0; j < n; ++j) {
    for (Index p = pattern.colptr[j]; p < pattern.colptr[j + 1]; ++p) {
      const Index a = inverse[pattern.rowind[p]], b = inverse[j];
      const Index c = std::min(a, b), r = std::max(a, b);
      const auto k = static_cast<std::size_t>(supernode_of[c]);
      if (r < super[k + 1]) continue;  // inside the supernode's dense triangle
      if (!std::binary_search(f.s.data() + f.pi[k] + (super[k + 1] - super[k]), f.s.data() + f.pi[k + 1], r)) {
        return false;
      }
    }
  }
  return true;
}

SymbolicCache::SymbolicCache(std::filesystem::path directory) : directory_(std::move(directory)) {}

std::filesystem::path SymbolicCache::file(const PatternKey& key) const {
  return directory_ / (key.hex() + ".symbolic");
}

cholmod_factor* SymbolicCache::load(const PatternKey& key, const CscPattern& pattern, SymbolicStatistics& statistics,
                                    cholmod_common& common) const {
  const auto n = static_cast<std::uint64_t>(pattern.n);
  std::error_code error;
  const std::uintmax_t bytes = std::filesystem::file_size(file(key), error);
  if (error || n == 0) return nullptr;
  std::ifstream in(file(key), std::ios::binary);
  char head[sizeof magic];
  std::uint64_t header[fields];
  if (!in.read(head, sizeof head) || std::memcmp(head, magic, sizeof magic) != 0) return nullptr;
  if (!in.read(reinterpret_cast<char*>(header), sizeof header)) return nullptr;
  // The sizes are bounded before anything is allocated: a file of the exact length holds them.
  if (header[format] != format_version || header[key_high] != key.high || header[key_low] != key.low ||
      header[size] != n || header[nsuper] < 1 || header[nsuper] > n || header[ssize] < 1 || header[ssize] > bytes ||
      file_bytes(n, header[nsuper], header[ssize]) != bytes) {
    return nullptr;
  }
  cholmod_factor* L = cholmod_l_allocate_factor(n, &common);
  if (L == nullptr) return nullptr;
  L->nsuper = header[nsuper];
  L->ssize = header[ssize];
  L->xsize = header[xsize];
  // What cholmod_super_symbolic does: sizes first, then CHOLMOD allocates the supernodal arrays
  // (a supernodal symbolic LL' factor, no values).
  bool ok = cholmod_l_change_factor(CHOLMOD_PATTERN, 1, 1, 1, 1, L, &common) && L->is_super;
  if (ok) {
    L->maxcsize = header[maxcsize];
    L->maxesize = header[maxesize];
    const SupernodalStructure f = supernodal_structure(*L);
    const FactorArrays arrays = arrays_of(f);
    for (std::span<const Index> a : arrays) ok = ok && read_words(in, const_cast<Index*>(a.data()), a.size());
    std::uint64_t sum = 0;
    ok = ok && in.read(reinterpret_cast<char*>(&sum), sizeof sum) && in.peek() == std::char_traits<char>::eof();
    ok = ok && sum == checksum(header, arrays) && is_supernodal_structure_of(f, pattern);
  }
  const auto order = static_cast<std::int64_t>(header[ordering]);
  const SymbolicStatistics read{std::bit_cast<double>(header[flops]), std::bit_cast<double>(header[lnz])};
  // NATURAL would make CHOLMOD skip the permutation the structure was checked with.
  ok = ok && order > CHOLMOD_NATURAL && order <= CHOLMOD_POSTORDERED && std::isfinite(read.flops) &&
       read.flops >= 0.0 && std::isfinite(read.factor_entries) && read.factor_entries >= 0.0;
  if (!ok) {
    cholmod_l_free_factor(&L, &common);
    return nullptr;
  }
  L->ordering = static_cast<int>(order);
  statistics = read;
  return L;
}

void SymbolicCache::store(const PatternKey& key, const cholmod_factor& L, const SymbolicStatistics& statistics) const {
  if (!L.is_super || L.itype != CHOLMOD_LONG || L.n == 0) return;
  store(key, supernodal_structure(L), L.ordering, statistics);
}

void SymbolicCache::store(const PatternKey& key, const SupernodalStructure& f, int ordering_method,
                          const SymbolicStatistics& statistics) const {
  if (f.super.empty()) return;
  const std::uint64_t header[fields] = {format_version,
                                        key.high,
                                        key.low,
                                        f.perm.size(),
                                        f.super.size() - 1,
                                        f.s.size(),
                                        f.xsize,
                                        f.maxcsize,
                                        f.maxesize,
                                        static_cast<std::uint64_t>(ordering_method),
                                        std::bit_cast<std::uint64_t>(statistics.flops),
                                        std::bit_cast<std::uint64_t>(statistics.factor_entries)};
  const FactorArrays arrays = arrays_of(f);
  write_atomically(file(key), [&](std::ostream& out) {
    out.write(magic, sizeof magic);
    out.write(reinterpret_cast<const char*>(header), sizeof header);
    for (std::span<const Index> a : arrays) {
      out.write(reinterpret_cast<const char*>(a.data()), static_cast<std::streamsize>(a.size_bytes()));
    }
    const std::uint64_t sum = checksum(header, arrays);
    out.write(reinterpret_cast<const char*>(&sum), sizeof sum);
  });
}

}  // namespace saasgaps
