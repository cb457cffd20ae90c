#include "solver/assembly/assembler.hpp"

#include <algorithm>
#include <cassert>

#include "solver/base/index_ranges.hpp"

namespace saasgaps {

Assembler::Assembler(const DofMap& dofs, std::size_t element_count, const NodesOf& nodes_of,
                     const Cliques& couplings) {
  const auto components = static_cast<std::size_t>(dofs.components());
  // Exact sizes first: at 10^6 unknowns a vector grown by doubling would hold up to twice its size.
  std::size_t members = 0;
  std::size_t upper = 0;
  const auto count = [&](std::size_t n) {
    members += n;
    upper += n * (n + 1) / 2;
  };
  for (std::size_t e = 0; e < element_count; ++e) count(components * nodes_of(e).size());
  for (std::size_t c = 0; c < couplings.size(); ++c) count(couplings[c].size());
  const std::size_t cliques = element_count + couplings.size();
  equations_.start.reserve(cliques + 1);
  equations_.members.reserve(members);
  lifted_.assign(cliques, false);

  std::vector<Index> local;
  lift_start_.push_back(0);
  for (std::size_t e = 0; e < element_count; ++e) {
    const std::span<const int> nodes = nodes_of(e);
    local.resize(components * nodes.size());
    dofs.equations(nodes, local);
    equations_.add(local);
    for (std::size_t a = 0; a < local.size(); ++a) {
      if (local[a] != DofMap::prescribed_dof) continue;
      const double u = dofs.prescribed(nodes[a / components], static_cast<int>(a % components));
      if (u == 0.0) continue;
      lift_local_.push_back(static_cast<int>(a));
      lift_value_.push_back(u);
    }
    if (static_cast<Index>(lift_local_.size()) > lift_start_.back()) {
      lifted_[e] = true;
      lift_clique_.push_back(e);
      lift_start_.push_back(static_cast<Index>(lift_local_.size()));
    }
  }
  for (std::size_t c = 0; c < couplings.size(); ++c) equations_.add(couplings[c]);

  pattern_ = CscPattern::from_cliques(dofs.size(), equations_.size(),
                                      [this](std::size_t c) { return equations_[c]; });

  // Each clique's positions have their place known in advance, so ranges of cliques are looked up
  // on the cores at once (index_ranges.hpp).
  positions_.start.resize(cliques + 1);
  for (std::size_t c = 0; c < cliques; ++c) {
    const auto n = static_cast<Index>(equations_[c].size());
    positions_.start[c + 1] = positions_.start[c] + n * (n + 1) / 2;
  }
  positions_.members.resize(upper);
  for_each_range(cliques, [this](std::size_t begin, std::size_t end, unsigned) {
    for (std::size_t c = begin; c < end; ++c) {
      const std::span<const Index> eq = equations_[c];
      Index* position = positions_.members.data() + positions_.start[c];
      for (std::size_t b = 0; b < eq.size(); ++b) {
        for (std::size_t a = 0; a <= b; ++a) {
          *position++ = eq[a] >= 0 && eq[b] >= 0 ? pattern_.find(eq[a], eq[b]) : -1;
        }
      }
    }
  });
}

void Assembler::add(std::size_t clique, const ElementBlock& block, const SystemSink& sink) const {
  const std::span<const Index> eq = equations_[clique];
  const auto n = static_cast<Index>(eq.size());
  assert(block.ld >= n);
  const Index* position = positions_.members.data() + positions_.start[clique];
  for (Index b = 0; b < n; ++b) {
    const double* column = block.K + b * block.ld;
    for (Index a = 0; a <= b; ++a, ++position) {
      if (*position >= 0) sink.values[*position] += column[a];
    }
  }
  add_rhs(clique, block, sink.rhs);
}

void Assembler::add_rhs(std::size_t clique, const ElementBlock& block, std::span<double> rhs) const {
  const std::span<const Index> eq = equations_[clique];
  const auto n = static_cast<Index>(eq.size());
  for (Index a = 0; a < n; ++a) {
    if (eq[a] >= 0) rhs[eq[a]] += block.f[a];
  }
  if (!lifted_[clique]) return;
  // Move K_fp u_p of nonzero prescribed values to the right-hand side.
  const auto at = static_cast<std::size_t>(std::lower_bound(lift_clique_.begin(), lift_clique_.end(), clique) - lift_clique_.begin());
  for (Index k = lift_start_[at]; k < lift_start_[at + 1]; ++k) {
    const double* column = block.K + lift_local_[k] * block.ld;
    const double u = lift_value_[k];
    for (Index a = 0; a < n; ++a) {
      if (eq[a] >= 0) rhs[eq[a]] -= column[a] * u;
    }
  }
}

}  // namespace saasgaps
