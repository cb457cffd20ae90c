// saasgaps_orderings: fill-reducing orderings for the symbolic analysis, compared on one model.
//
//   python3 schemas/examples/make_ring_model.py --radial 155 --hoop 1600 -o /tmp/annulus-1m.json
//   build/tests/bench/saasgaps_orderings --model /tmp/annulus-1m.json
//
// Every candidate orders the node graph (one vertex per node's unknowns, as SparseCholesky does) and
// is expanded to the unknowns; CHOLMOD's symbolic analysis of the expanded order then gives nnz(L)
// and the flops of one numeric factorization. Reported per ordering: its own time, nnz(L), flops,
// and the flops against METIS's (the ordering in use). A cheaper ordering pays only when
//   ordering time saved > (flops ratio - 1) x factorization time x iterations.
// Candidates:
//   METIS             METIS_NodeND on the node graph, CHOLMOD's defaults (in use);
//   METIS, coarse     METIS on a graph of node pairs (greedy matching of neighbours), expanded;
//   CHOLMOD NESDIS    CHOLMOD's own nested dissection (METIS bisection, CCOLAMD on the parts);
//   AMD               approximate minimum degree on the node graph;
//   geometric ND      recursive coordinate bisection of the nodes, each cut's separator = the nodes
//                     on one side with a neighbour on the other, ordered last (no graph partitioner).
#include <cholmod.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <functional>
#include <numeric>
#include <vector>

#include "io/model/model_reader.hpp"
#include "solver/assembly/dof_map.hpp"
#include "solver/assembly/stiffness_system.hpp"
#include "solver/lac/cholmod_solve.hpp"

using namespace saasgaps;

namespace {

cholmod_sparse view(CscPattern& p) {
  const auto n = static_cast<std::size_t>(p.n);
  return cholmod_csc_view(n, n, p.rowind.size(), p.colptr.data(), p.rowind.data(), nullptr, 1, CHOLMOD_PATTERN);
}

/// Both triangles of a symmetric pattern without diagonal, as adjacency lists (CSR).
struct Adjacency {
  std::vector<Index> start, next;
  explicit Adjacency(const CscPattern& upper) : start(static_cast<size_t>(upper.n) + 1, 0) {
    for (Index j = 0; j < upper.n; ++j) {
      for (Index k = upper.colptr[j]; k < upper.colptr[j + 1]; ++k) {
        if (upper.rowind[k] == j) continue;
        ++start[j + 1];
        ++start[upper.rowind[k] + 1];
      }
    }
    for (Index j = 0; j < upper.n; ++j) start[j + 1] += start[j];
    next.resize(static_cast<size_t>(start[upper.n]));
    std::vector<Index> fill(start.begin(), start.end() - 1);
    for (Index j = 0; j < upper.n; ++j) {
      for (Index k = upper.colptr[j]; k < upper.colptr[j + 1]; ++k) {
        const Index i = upper.rowind[k];
        if (i == j) continue;
        next[fill[j]++] = i;
        next[fill[i]++] = j;
      }
    }
  }
};

/// Recursive coordinate bisection with vertex separators; leaves of at most `leaf` vertices keep
/// their order. x, y: a coordinate per vertex.
std::vector<Index> geometric_nested_dissection(const Adjacency& g, const std::vector<double>& x,
                                               const std::vector<double>& y, Index leaf) {
  const Index n = static_cast<Index>(x.size());
  std::vector<Index> order;
  order.reserve(static_cast<size_t>(n));
  std::vector<int> side(static_cast<size_t>(n), 0);  // per vertex: the part it is in at this level
  std::vector<Index> all(static_cast<size_t>(n));
  std::iota(all.begin(), all.end(), 0);
  int next_label = 1;
  std::function<void(std::vector<Index>&, int)> dissect = [&](std::vector<Index>& part, int label) {
    if (static_cast<Index>(part.size()) <= leaf) {
      order.insert(order.end(), part.begin(), part.end());
      return;
    }
    double lo_x = 1e300, hi_x = -1e300, lo_y = 1e300, hi_y = -1e300;
    for (Index v : part) {
      lo_x = std::min(lo_x, x[v]); hi_x = std::max(hi_x, x[v]);
      lo_y = std::min(lo_y, y[v]); hi_y = std::max(hi_y, y[v]);
    }
    const std::vector<double>& c = (hi_x - lo_x >= hi_y - lo_y) ? x : y;
    const auto middle = part.begin() + static_cast<long>(part.size() / 2);
    std::nth_element(part.begin(), middle, part.end(), [&](Index a, Index b) { return c[a] < c[b]; });
    const int left = next_label++, right = next_label++;
    for (auto it = part.begin(); it != middle; ++it) side[*it] = left;
    for (auto it = middle; it != part.end(); ++it) side[*it] = right;
    std::vector<Index> left_part, right_part, separator;
    for (auto it = part.begin(); it != middle; ++it) {
      bool cut = false;
      for (Index k = g.start[*it]; k < g.start[*it + 1] && !cut; ++k) cut = side[g.next[k]] == right;
      (cut ? separator : left_part).push_back(*it);
    }
    right_part.assign(middle, part.end());
    std::vector<Index>().swap(part);
    dissect(left_part, left);
    dissect(right_part, right);
    order.insert(order.end(), separator.begin(), separator.end());
    (void)label;
  };
  dissect(all, 0);
  return order;
}

/// Pairs each vertex with an unmatched neighbour (greedy, in index order): a graph about half the size.
std::vector<Index> matching_groups(const Adjacency& g, Index n) {
  std::vector<Index> group(static_cast<size_t>(n), -1);
  Index count = 0;
  for (Index v = 0; v < n; ++v) {
    if (group[v] >= 0) continue;
    group[v] = count;
    for (Index k = g.start[v]; k < g.start[v + 1]; ++k) {
      if (group[g.next[k]] < 0) {
        group[g.next[k]] = count;
        break;
      }
    }
    ++count;
  }
  return group;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Fill-reducing orderings compared on one model"};
  std::string model_path;
  app.add_option("--model", model_path, "Model document")->required();
  CLI11_PARSE(app, argc, argv);

  const Model model = io::read_model(io::parse_document([&] {
    std::FILE* f = std::fopen(model_path.c_str(), "rb");
    if (f == nullptr) throw std::runtime_error("cannot open " + model_path);
    std::string text;
    char buffer[1 << 16];
    for (std::size_t got; (got = std::fread(buffer, 1, sizeof buffer, f)) > 0;) text.append(buffer, got);
    std::fclose(f);
    return text;
  }()));
  const DofMap dofs(model);
  const StiffnessSystem system(model, dofs);
  CscPattern pattern = system.pattern();
  const std::vector<Index>& groups = dofs.node_of_equation();
  const IndexGroups members = IndexGroups::of(groups);
  CscPattern graph = group_pattern(pattern, groups, members);
  const Adjacency adjacency(graph);

  cholmod_common common;
  cholmod_l_start(&common);
  common.print = 0;
  common.supernodal = CHOLMOD_SUPERNODAL;
  common.nmethods = 1;
  common.method[0].ordering = CHOLMOD_GIVEN;
  common.postorder = 1;
  cholmod_sparse A = view(pattern);
  cholmod_sparse G = view(graph);

  struct Result {
    const char* name;
    double seconds, nnz, flops;
  };
  std::vector<Result> results;
  const auto measure = [&](const char* name, const std::function<std::vector<Index>()>& node_order) {
    const auto start = std::chrono::steady_clock::now();
    const std::vector<Index> order = expand(node_order(), members);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    cholmod_factor* L = cholmod_l_analyze_p(&A, const_cast<Index*>(order.data()), nullptr, 0, &common);
    results.push_back({name, seconds, common.lnz, common.fl});
    cholmod_l_free_factor(&L, &common);
  };
  std::vector<Index> perm(static_cast<size_t>(graph.n));
  measure("METIS on the node graph (in use)", [&] {
    cholmod_l_metis(&G, nullptr, 0, 0, perm.data(), &common);
    return perm;
  });
  measure("METIS on a graph of node pairs", [&] {
    const std::vector<Index> pairs = matching_groups(adjacency, graph.n);
    const IndexGroups pair_members = IndexGroups::of(pairs);
    CscPattern coarse = group_pattern(graph, pairs, pair_members);
    cholmod_sparse C = view(coarse);
    std::vector<Index> coarse_perm(static_cast<size_t>(coarse.n));
    cholmod_l_metis(&C, nullptr, 0, 0, coarse_perm.data(), &common);
    return expand(coarse_perm, pair_members);
  });
  measure("CHOLMOD NESDIS on the node graph", [&] {
    std::vector<Index> cparent(static_cast<size_t>(graph.n)), cmember(static_cast<size_t>(graph.n));
    cholmod_l_nested_dissection(&G, nullptr, 0, perm.data(), cparent.data(), cmember.data(), &common);
    return perm;
  });
  measure("AMD on the node graph", [&] {
    cholmod_l_amd(&G, nullptr, 0, perm.data(), &common);
    return perm;
  });
  measure("geometric ND on node coordinates", [&] {
    std::vector<double> x(static_cast<size_t>(graph.n)), y(static_cast<size_t>(graph.n));
    for (Index g = 0; g < graph.n; ++g) {
      x[g] = model.nodes[static_cast<size_t>(g)].r;
      y[g] = model.nodes[static_cast<size_t>(g)].z;
    }
    return geometric_nested_dissection(adjacency, x, y, 64);
  });
  cholmod_l_finish(&common);

  std::printf("model %s: %lld unknowns, node graph %lld vertices\n", model_path.c_str(),
              static_cast<long long>(pattern.n), static_cast<long long>(graph.n));
  std::printf("%-36s %10s %12s %12s %14s\n", "ordering", "seconds", "nnz(L)", "Gflop", "flops / METIS");
  for (const Result& r : results) {
    std::printf("%-36s %10.3f %12.4g %12.3f %14.3f\n", r.name, r.seconds, r.nnz, r.flops / 1e9,
                r.flops / results.front().flops);
  }
  return 0;
}
