#include "csc_pattern.hpp"

#include <algorithm>
#include <cassert>

namespace saasgaps {

Index CscPattern::find(Index i, Index j) const {
  if (i > j) std::swap(i, j);
  assert(j >= 0 && j < n);
  const auto first = rowind.begin() + colptr[j];
  const auto last = rowind.begin() + colptr[j + 1];
  const auto it = std::lower_bound(first, last, i);
  return (it != last && *it == i) ? static_cast<Index>(it - rowind.begin()) : -1;
}

CscPattern CscPattern::from_cliques(Index n, std::size_t clique_count,
                                    const std::function<std::span<const Index>(std::size_t)>& cliques) {
  // Invert the cliques: for each index, the cliques that hold it (CSR layout).
  std::vector<Index> holder_start(static_cast<std::size_t>(n) + 1, 0);
  for (std::size_t c = 0; c < clique_count; ++c) {
    for (Index k : cliques(c)) {
      if (k >= 0) ++holder_start[k + 1];
    }
  }
  for (Index k = 0; k < n; ++k) holder_start[k + 1] += holder_start[k];
  std::vector<Index> holders(static_cast<std::size_t>(holder_start[n]));
  {
    std::vector<Index> fill(holder_start.begin(), holder_start.end() - 1);
    for (std::size_t c = 0; c < clique_count; ++c) {
      for (Index k : cliques(c)) {
        if (k >= 0) holders[fill[k]++] = static_cast<Index>(c);
      }
    }
  }

  // Column j holds every i <= j sharing a clique with j; the marker skips repeats without sorting twice.
  CscPattern p;
  p.n = n;
  p.colptr.assign(static_cast<std::size_t>(n) + 1, 0);
  std::vector<Index> marker(static_cast<std::size_t>(n), -1);
  const auto visit_column = [&](Index j, auto&& emit) {
    // The diagonal is always present, even for an index no clique holds, so that a missing
    // stiffness shows up as a zero pivot rather than as a broken pattern.
    marker[j] = j;
    emit(j);
    for (Index h = holder_start[j]; h < holder_start[j + 1]; ++h) {
      for (Index i : cliques(static_cast<std::size_t>(holders[h]))) {
        if (i >= 0 && i <= j && marker[i] != j) {
          marker[i] = j;
          emit(i);
        }
      }
    }
  };
  for (Index j = 0; j < n; ++j) {
    Index count = 0;
    visit_column(j, [&](Index) { ++count; });
    p.colptr[j + 1] = p.colptr[j] + count;
  }
  p.rowind.resize(static_cast<std::size_t>(p.colptr[n]));
  std::fill(marker.begin(), marker.end(), -1);
  for (Index j = 0; j < n; ++j) {
    Index at = p.colptr[j];
    visit_column(j, [&](Index i) { p.rowind[at++] = i; });
    std::sort(p.rowind.begin() + p.colptr[j], p.rowind.begin() + p.colptr[j + 1]);
  }
  return p;
}

}  // namespace saasgaps
