#include "solver/lac/csc_pattern.hpp"

#include <algorithm>
#include <cassert>

#include "solver/base/index_ranges.hpp"

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

  // Column j holds every i <= j sharing a clique with j; the marker skips repeats without sorting
  // twice. Columns are independent: ranges of them go to the cores (index_ranges.hpp), each with a
  // marker of its own, which the second pass tells apart from the first by an offset of n.
  CscPattern p;
  p.n = n;
  p.colptr.assign(static_cast<std::size_t>(n) + 1, 0);
  const std::size_t columns = static_cast<std::size_t>(n);
  std::vector<std::vector<Index>> markers(range_count(columns));
  const auto visit_column = [&](std::vector<Index>& marker, Index mark, Index j, auto&& emit) {
    // The diagonal is always present, even for an index no clique holds, so that a missing
    // stiffness shows up as a zero pivot rather than as a broken pattern.
    marker[j] = mark;
    emit(j);
    for (Index h = holder_start[j]; h < holder_start[j + 1]; ++h) {
      for (Index i : cliques(static_cast<std::size_t>(holders[h]))) {
        if (i >= 0 && i <= j && marker[i] != mark) {
          marker[i] = mark;
          emit(i);
        }
      }
    }
  };
  const auto marker_of = [&](unsigned range) -> std::vector<Index>& {
    std::vector<Index>& marker = markers[range];
    if (marker.empty()) marker.assign(columns, -1);
    return marker;
  };
  for_each_range(columns, [&](std::size_t begin, std::size_t end, unsigned range) {
    std::vector<Index>& marker = marker_of(range);
    for (auto j = static_cast<Index>(begin); j < static_cast<Index>(end); ++j) {
      Index count = 0;
      visit_column(marker, j, j, [&](Index) { ++count; });
      p.colptr[j + 1] = count;
    }
  });
  for (Index j = 0; j < n; ++j) p.colptr[j + 1] += p.colptr[j];
  p.rowind.resize(static_cast<std::size_t>(p.colptr[n]));
  for_each_range(columns, [&](std::size_t begin, std::size_t end, unsigned range) {
    std::vector<Index>& marker = marker_of(range);
    for (auto j = static_cast<Index>(begin); j < static_cast<Index>(end); ++j) {
      Index at = p.colptr[j];
      visit_column(marker, n + j, j, [&](Index i) { p.rowind[at++] = i; });
      std::sort(p.rowind.begin() + p.colptr[j], p.rowind.begin() + p.colptr[j + 1]);
    }
  });
  return p;
}

IndexGroups IndexGroups::of(std::span<const Index> groups) {
  const Index count = groups.empty() ? 0 : *std::max_element(groups.begin(), groups.end()) + 1;
  IndexGroups g;
  g.start.assign(static_cast<std::size_t>(count) + 1, 0);
  g.members.resize(groups.size());
  for (Index h : groups) ++g.start[h + 1];
  for (Index h = 0; h < count; ++h) g.start[h + 1] += g.start[h];
  std::vector<Index> fill(g.start.begin(), g.start.end() - 1);
  for (std::size_t j = 0; j < groups.size(); ++j) g.members[fill[groups[j]]++] = static_cast<Index>(j);
  return g;
}

CscPattern group_pattern(const CscPattern& pattern, std::span<const Index> groups, const IndexGroups& members) {
  assert(static_cast<Index>(groups.size()) == pattern.n);
  const Index count = members.count();
  // Each index's column holds its couplings to lower indices and the upper ones see it from their
  // own columns, so both directions are covered.
  std::vector<std::vector<Index>> adjacency(static_cast<std::size_t>(count));
  std::vector<Index> marker(static_cast<std::size_t>(count), -1);
  for (Index g = 0; g < count; ++g) {
    marker[g] = g;
    for (Index m = members.start[g]; m < members.start[g + 1]; ++m) {
      const Index j = members.members[m];
      for (Index k = pattern.colptr[j]; k < pattern.colptr[j + 1]; ++k) {
        const Index h = groups[pattern.rowind[k]];
        if (marker[h] == g) continue;
        marker[h] = g;
        if (h < g) adjacency[g].push_back(h); else adjacency[h].push_back(g);
      }
    }
  }
  CscPattern q;
  q.n = count;
  q.colptr.assign(static_cast<std::size_t>(count) + 1, 0);
  for (Index g = 0; g < count; ++g) {
    std::sort(adjacency[g].begin(), adjacency[g].end());
    adjacency[g].erase(std::unique(adjacency[g].begin(), adjacency[g].end()), adjacency[g].end());
    q.colptr[g + 1] = q.colptr[g] + static_cast<Index>(adjacency[g].size());
  }
  q.rowind.reserve(static_cast<std::size_t>(q.colptr[count]));
  for (auto& column : adjacency) {
    q.rowind.insert(q.rowind.end(), column.begin(), column.end());
    std::vector<Index>().swap(column);
  }
  return q;
}

std::vector<Index> expand(std::span<const Index> group_order, const IndexGroups& members) {
  std::vector<Index> order;
  order.reserve(members.members.size());
  for (Index g : group_order) {
    for (Index m = members.start[g]; m < members.start[g + 1]; ++m) order.push_back(members.members[m]);
  }
  return order;
}

}  // namespace saasgaps
