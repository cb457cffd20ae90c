#include "friction_models.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>

#include "solver/analysis/solid_materials.hpp"
#include "solver/assembly/assembler.hpp"
#include "solver/assembly/stiffness_system.hpp"
#include "support/mesh_builder.hpp"

namespace saasgaps::testing {

namespace {

void assemble(StiffnessSystem& system, const Model& model) {
  const SolidMaterials materials(model);
  const MaterialState state = materials.initial();
  system.assemble_solids([&](std::size_t e) { return materials.law(e, state); });
}

/// 0, spacing, 2 spacing, ... up to uniform_to, then steps growing by `growth` until past `to`.
std::vector<double> graded(double spacing, double growth, double uniform_to, double to) {
  std::vector<double> x{0.0};
  while (x.back() < uniform_to - 1e-12) x.push_back(x.back() + spacing);
  double step = spacing;
  while (x.back() < to) x.push_back(x.back() + (step *= growth));
  return x;
}

}  // namespace

CoupledSystem::CoupledSystem(const Model& model, const ContactPairs& pairs) : dofs_(model) {
  Cliques couplings;
  for (const ContactPair& p : pairs.pairs) {
    std::vector<Index> eqs(2 * p.node.size());
    dofs_.equations(p.node, eqs);
    couplings.add(eqs);
  }
  const Assembler assembler(
      dofs_, model.elements.size(),
      [&model](std::size_t e) {
        return std::span<const int>(model.elements[e].nodes.data(), static_cast<std::size_t>(model.elements[e].node_count));
      },
      couplings);
  pattern_ = assembler.pattern();
  StiffnessSystem system(model, dofs_);
  assemble(system, model);
  const CscPattern& plain = system.pattern();
  values_.assign(static_cast<std::size_t>(pattern_.nnz()), 0.0);
  for (Index j = 0; j < plain.n; ++j) {
    for (Index k = plain.colptr[j]; k < plain.colptr[j + 1]; ++k) {
      values_[pattern_.find(plain.rowind[k], j)] = system.values()[k];
    }
  }
  cholesky_ = std::make_unique<SparseCholesky>(pattern_, dofs_.node_of_equation());
}

std::vector<double> CoupledSystem::rhs(const Model& state) const {
  const DofMap dofs(state);
  assert(dofs.size() == dofs_.size() && "a load state with the same prescribed components");
  StiffnessSystem system(state, dofs);
  assemble(system, state);
  return {system.rhs().begin(), system.rhs().end()};
}

std::vector<double> CoupledSystem::full(const Model& state, std::span<const double> u) const {
  const DofMap dofs(state);
  std::vector<double> x(2 * state.nodes.size());
  for (std::size_t node = 0; node < state.nodes.size(); ++node) {
    for (int c = 0; c < 2; ++c) {
      const Index eq = dofs.equation(static_cast<int>(node), c);
      x[2 * node + c] = eq >= 0 ? u[eq] : dofs.prescribed(static_cast<int>(node), c);
    }
  }
  return x;
}

double CoupledSystem::imbalance(std::span<const double> u, std::span<const double> f,
                                std::span<const double> contact) const {
  std::vector<double> r(u.size(), 0.0);
  for (Index j = 0; j < pattern_.n; ++j) {
    for (Index k = pattern_.colptr[j]; k < pattern_.colptr[j + 1]; ++k) {
      const Index i = pattern_.rowind[k];
      r[i] += values_[k] * u[j];
      if (i != j) r[j] += values_[k] * u[i];
    }
  }
  double worst = 0.0;
  for (std::size_t i = 0; i < r.size(); ++i) worst = std::max(worst, std::abs(r[i] - f[i] - contact[i]));
  return worst;
}

Cylinders cylinders(double sink, double spacing, double growth) {
  Cylinders c;
  Model& m = c.model;
  m.analysis = AnalysisType::plane_strain;
  m.materials = {isotropic_material(1, Cylinders::E, Cylinders::nu)};
  const std::vector<double> half = graded(spacing, growth, 1.3, 8.0);
  std::vector<double> across(half.rbegin(), half.rend() - 1);
  for (double& v : across) v = -v;
  across.insert(across.end(), half.begin(), half.end());
  const std::vector<double> depth = graded(spacing, growth, 0.5, 8.0);
  const int ni = static_cast<int>(across.size()) - 1;
  const int nj = static_cast<int>(depth.size()) - 1;
  const auto at = [](const std::vector<double>& v, double s) {
    return v[static_cast<std::size_t>(std::lround(s * (static_cast<double>(v.size()) - 1)))];
  };
  const Grid lower = add_grid(m, ni, nj, [&](double s, double t) { return Vec2(at(across, s), -at(depth, 1.0 - t)); }, 0);
  const Grid upper = add_grid(m, ni, nj, [&](double s, double t) { return Vec2(at(across, s), at(depth, t)); }, 0);
  fill_temperatures(m, 0.0);
  for (int i = 0; i <= ni; ++i) {
    constrain(m, lower.at(i, 0), 0.0, 0.0);
    constrain(m, upper.at(i, nj), std::nullopt, -sink);
    c.top.push_back(upper.at(i, nj));
    ContactPair p;
    p.node = {lower.at(i, nj), upper.at(i, 0)};
    p.weight = {-1.0, 1.0};
    p.normal = Vec2(0.0, 1.0);
    p.g0 = across[i] * across[i] / (2 * Cylinders::radius);
    c.pairs.pairs.push_back(p);
    c.x.push_back(across[i]);
  }
  return c;
}

Model sheared(const Cylinders& c, double Q) {
  Model m = c.model;
  const double span = m.nodes[c.top.back()].r - m.nodes[c.top.front()].r;
  for (std::size_t i = 0; i < c.top.size(); ++i) {
    const double left = i == 0 ? 0.0 : m.nodes[c.top[i]].r - m.nodes[c.top[i - 1]].r;
    const double right = i + 1 == c.top.size() ? 0.0 : m.nodes[c.top[i + 1]].r - m.nodes[c.top[i]].r;
    m.loads.nodal_forces.push_back({c.top[i], Q * (left + right) / (2 * span), 0.0});
  }
  return m;
}

}  // namespace saasgaps::testing
