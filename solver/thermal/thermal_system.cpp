#include "solver/thermal/thermal_system.hpp"

#include <algorithm>
#include <cassert>
#include <string>
#include <tuple>

#include "solver/assembly/element_data.hpp"
#include "solver/base/errors.hpp"
#include "solver/fe/element_family.hpp"
#include "solver/gaps/gap_faces.hpp"
#include "solver/materials/material.hpp"

namespace saasgaps {

namespace {

std::vector<DofMap::Prescribed> prescribed_temperatures(const Model& model) {
  std::vector<DofMap::Prescribed> fixed;
  for (const ThermalBoundary& b : model.thermal->boundary) {
    if (b.kind != ThermalBoundary::Kind::temperature) continue;
    for (const ThermalEdge& e : b.edges) {
      // From a to b, through the mid-side node of a quadratic element's edge.
      const ElementEdge edge = element_edge(model, static_cast<std::size_t>(e.element), e.node_a, e.node_b);
      for (int k = 0; k < edge.count; ++k) fixed.push_back({edge.node[static_cast<std::size_t>(k)], 0, b.value});
    }
  }
  return fixed;
}

bool conducting_gaps(const Model& model) { return model.gaps && model.gaps->conductance && !model.gaps->elements.empty(); }

/// The mean of an element's corner temperatures: where its properties are taken.
double mean_temperature(std::span<const int> nodes, std::span<const double> T) {
  double sum = 0.0;
  for (const int n : nodes) sum += T[static_cast<std::size_t>(n)];
  return sum / static_cast<int>(nodes.size());
}

/// Position of node n among an element's nodes.
int position_of(const Element& el, int n) {
  for (int k = 0; k < el.node_count; ++k) {
    if (el.nodes[k] == n) return k;
  }
  assert(false && "a thermal edge's node is a node of its element");
  return 0;
}

}  // namespace

double gap_width(const Model& model, const GapElement& gap) {
  return gap_faces(corner_coordinates(model, gap.nodes, gap.node_count), gap.node_count, gap.angle_deg).separation;
}

ThermalSystem::ThermalSystem(const Model& model)
    : model_(model),
      dofs_(model, "T", prescribed_temperatures(model)),
      gaps_conduct_(conducting_gaps(model)),
      contact_(model),
      assembler_(dofs_, model.elements.size() + gap_count() + contact_.row_count(), [this, &model](std::size_t e) {
        if (e < model.elements.size()) {
          const Element& el = model.elements[e];
          return std::span<const int>(el.nodes.data(), static_cast<std::size_t>(el.node_count));
        }
        e -= model.elements.size();
        if (e < gap_count()) {
          const GapElement& g = model.gaps->elements[e];
          return std::span<const int>(g.nodes.data(), static_cast<std::size_t>(g.node_count));
        }
        // A row clique is an element clique over its nodes: prescribed temperatures are lifted.
        return contact_.nodes(e - gap_count());
      }) {
  assert(model.thermal);
  source_.assign(model.elements.size(), 0.0);
  for (const HeatSource& s : model.thermal->sources) {
    for (std::size_t e = 0; e < model.elements.size(); ++e) {
      if (model.elements[e].material == s.material) source_[e] = s.power_density;
    }
  }
  edges_.resize(model.elements.size());
  for (const ThermalBoundary& b : model.thermal->boundary) {
    if (b.kind == ThermalBoundary::Kind::temperature) continue;
    radiates_ = radiates_ || b.kind == ThermalBoundary::Kind::radiation;
    for (const ThermalEdge& e : b.edges) {
      const Element& el = model.elements[static_cast<std::size_t>(e.element)];
      const ElementEdge nodes = element_edge(model, static_cast<std::size_t>(e.element), e.node_a, e.node_b);
      EdgeLoad load{{-1, -1, -1}, nodes.count, b.kind, b.value, b.ambient};
      for (int k = 0; k < nodes.count; ++k) load.at[static_cast<std::size_t>(k)] = position_of(el, nodes.node[static_cast<std::size_t>(k)]);
      edges_[static_cast<std::size_t>(e.element)].push_back(load);
    }
  }
  if (gaps_conduct_) {
    for (const GapElement& g : model.gaps->elements) {
      gap_width_.push_back(gap_width(model, g));
    }
  }
  std::vector<char> in_solid(model.nodes.size(), 0);
  for (const Element& el : model.elements) {
    for (int a = 0; a < el.node_count; ++a) in_solid[static_cast<std::size_t>(el.nodes[a])] = 1;
  }
  std::vector<std::size_t> slot(model.nodes.size(), 0);  // 1 + index into outside_
  for (std::size_t n = 0; n < model.nodes.size(); ++n) {
    const Index eq = dofs_.equation(static_cast<int>(n), 0);
    if (in_solid[n] || eq < 0) continue;
    outside_.push_back({static_cast<int>(n), eq, {}});
    slot[n] = outside_.size();
  }
  for (std::size_t g = 0; g < gap_count(); ++g) {
    const GapElement& gap = model.gaps->elements[g];
    for (int a = 0; a < gap.node_count; ++a) {
      const std::size_t s = slot[static_cast<std::size_t>(gap.nodes[a])];
      if (s > 0) outside_[s - 1].gaps.emplace_back(g, a);
    }
  }
}

IsoConductionData ThermalSystem::iso_data(const Element& el, const Conductivity& k) const {
  IsoConductionData d;
  d.type = el.type;
  d.node_count = el.node_count;
  d.x = node_coordinates(model_, el.node_span());
  d.analysis = model_.analysis;
  d.thickness = model_.thickness;
  d.k = k;
  return d;
}

ConductionData ThermalSystem::data(const Element& el, const Conductivity& k) const {
  ConductionData d;
  d.node_count = el.node_count;
  d.x = corner_coordinates(model_, el.nodes, el.node_count);
  d.analysis = model_.analysis;
  d.thickness = model_.thickness;
  d.k = k;
  return d;
}

std::vector<Conductivity> ThermalSystem::conductivities(std::span<const double> T) const {
  std::vector<Conductivity> k;
  k.reserve(model_.elements.size());
  for (const Element& el : model_.elements) {
    const Material& m = model_.materials[static_cast<std::size_t>(el.material)];
    const ThermalConstants c = interpolate_thermal(m.table, mean_temperature(el.node_span(), T));
    k.push_back({c.k1, c.k2, el.angle_deg});
  }
  return k;
}

std::vector<double> ThermalSystem::capacity_rates(double inverse_dt, std::span<const double> previous) const {
  std::vector<double> rates;
  if (!(inverse_dt > 0.0)) return rates;
  rates.reserve(model_.elements.size());
  for (const Element& el : model_.elements) {
    const Material& m = model_.materials[static_cast<std::size_t>(el.material)];
    const double c = interpolate_thermal(m.table, mean_temperature(el.node_span(), previous)).c;
    rates.push_back(m.density * c * inverse_dt);
  }
  return rates;
}

ConductionLoad ThermalSystem::load(std::size_t e, double rate, std::span<const double> previous) const {
  const Element& el = model_.elements[e];
  ConductionLoad load;
  load.source = source_[e];
  if (rate > 0.0) {
    load.capacity_rate = rate;
    for (int a = 0; a < el.node_count; ++a) load.previous[a] = previous[static_cast<std::size_t>(el.nodes[a])];
  }
  return load;
}

namespace {

/// The film of a radiating edge linearized at its mean current temperature T0 (thermal_system.hpp).
std::pair<double, double> radiation_film(double emission, double T0, double Ta) {
  if (T0 > 0.0) {
    return {4.0 * emission * T0 * T0 * T0, T0 - (T0 * T0 * T0 * T0 - Ta * Ta * Ta * Ta) / (4.0 * T0 * T0 * T0)};
  }
  return {emission * (T0 * T0 + Ta * Ta) * (T0 + Ta), Ta};
}

}  // namespace

template <class Matrix, class Vector>
void ThermalSystem::add_edges(std::size_t e, std::span<const Vec2> x, std::span<const double> current, Matrix& K,
                              Vector& f) const {
  const Element& el = model_.elements[e];
  const auto T_at = [&](int local) { return current[static_cast<std::size_t>(el.nodes[static_cast<std::size_t>(local)])]; };
  for (const EdgeLoad& edge : edges_[e]) {
    if (edge.count == 3) {
      // A quadratic element's edge (a, m, b): integrated along its curve (isoparametric_conduction.hpp).
      const std::array<Vec2, max_edge_nodes> points{x[static_cast<std::size_t>(edge.at[0])],
                                                    x[static_cast<std::size_t>(edge.at[1])],
                                                    x[static_cast<std::size_t>(edge.at[2])]};
      if (edge.kind == ThermalBoundary::Kind::flux) {
        const auto w = edge_flux_weights(points, 3, model_.analysis, model_.thickness);
        for (std::size_t i = 0; i < 3; ++i) f[edge.at[i]] += edge.value * w[i];
        continue;
      }
      double h = edge.value;
      double ambient = edge.ambient;
      if (edge.kind == ThermalBoundary::Kind::radiation) {
        // The edge's mean temperature: its nodal values weighted as on a straight edge, 1/6, 4/6, 1/6.
        const double T0 = (T_at(edge.at[0]) + 4.0 * T_at(edge.at[1]) + T_at(edge.at[2])) / 6.0;
        std::tie(h, ambient) = radiation_film(edge.value, T0, edge.ambient);
      }
      const CurvedEdgeBlock film = curved_film_block(points, 3, model_.analysis, model_.thickness, h, ambient);
      for (std::size_t i = 0; i < 3; ++i) {
        f[edge.at[i]] += film.f[static_cast<Eigen::Index>(i)];
        for (std::size_t j = 0; j < 3; ++j) {
          K(edge.at[i], edge.at[j]) += film.K(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j));
        }
      }
      continue;
    }
    const int a = edge.at[0];
    const int b = edge.at[1];
    const Vec2& xa = x[static_cast<std::size_t>(a)];
    const Vec2& xb = x[static_cast<std::size_t>(b)];
    if (edge.kind == ThermalBoundary::Kind::flux) {
      const auto w = edge_weights(xa, xb, model_.analysis, model_.thickness);
      f[a] += edge.value * w[0];
      f[b] += edge.value * w[1];
      continue;
    }
    double h = edge.value;
    double ambient = edge.ambient;
    if (edge.kind == ThermalBoundary::Kind::radiation) {
      std::tie(h, ambient) = radiation_film(edge.value, 0.5 * (T_at(a) + T_at(b)), edge.ambient);
    }
    const EdgeBlock film = film_block(xa, xb, model_.analysis, model_.thickness, h, ambient);
    const std::array<int, 2> at{a, b};
    for (int i = 0; i < 2; ++i) {
      f[at[i]] += film.f[i];
      for (int j = 0; j < 2; ++j) K(at[i], at[j]) += film.K(i, j);
    }
  }
}

void ThermalSystem::hold_isolated(std::span<const double> gap_conductance, std::span<const double> previous,
                                  std::span<double> values, std::span<double> rhs) const {
  for (const OutsideNode& o : outside_) {
    // Every gap block is positive semidefinite, so the node's row is empty iff each of its gaps
    // adds 0 to its diagonal (at conductance 0, for one).
    const bool conducts = std::ranges::any_of(o.gaps, [&](const std::pair<std::size_t, int>& at) {
      return gap_matrix(at.first, gap_conductance[at.first])(at.second, at.second) != 0.0;
    });
    if (conducts) continue;
    if (!values.empty()) {
      // The diagonal ends its column of the upper-triangular pattern, which holds every diagonal.
      const Index diagonal = assembler_.pattern().colptr[static_cast<std::size_t>(o.equation) + 1] - 1;
      assert(assembler_.pattern().rowind[static_cast<std::size_t>(diagonal)] == o.equation);
      assert(values[static_cast<std::size_t>(diagonal)] == 0.0);
      values[static_cast<std::size_t>(diagonal)] = 1.0;
    }
    rhs[static_cast<std::size_t>(o.equation)] =
        previous.empty() ? model_.reference_temperature : previous[static_cast<std::size_t>(o.node)];
  }
}

Eigen::Matrix4d ThermalSystem::gap_matrix(std::size_t g, double conductance) const {
  // An open gap with no gas conducts nothing; the kernel would divide by its zero centre-node
  // conductance when condensing a quadrilateral.
  if (conductance == 0.0) return Eigen::Matrix4d::Zero();
  const GapElement& gap = model_.gaps->elements[g];
  ConductionData d;
  d.node_count = gap.node_count;
  d.x = corner_coordinates(model_, gap.nodes, gap.node_count);
  d.analysis = model_.analysis;
  d.thickness = model_.thickness;
  d.k = {conductance * gap_width_[g], 0.0, gap.angle_deg};
  return conduction_matrix(d);
}

void ThermalSystem::assemble(std::span<const Conductivity> k, double inverse_dt, std::span<const double> previous,
                             std::span<const double> gap_conductance, std::span<const double> contact_conductance,
                             std::span<const double> current, std::span<double> values, std::span<double> rhs,
                             ConductionLoads* loads) const {
  std::fill(values.begin(), values.end(), 0.0);
  std::fill(rhs.begin(), rhs.end(), 0.0);
  const SystemSink sink{values, rhs};
  const std::vector<double> rates = capacity_rates(inverse_dt, previous);
  if (loads != nullptr) loads->clear();
  for (std::size_t e = 0; e < model_.elements.size(); ++e) {
    const Element& el = model_.elements[e];
    if (conducts_isoparametrically(el.type)) {
      const IsoConductionData d = iso_data(el, k[e]);
      const IsoConductionParts parts = isoparametric_conduction_parts(d);
      IsoConductionBlock block = isoparametric_conduction_block(parts, load(e, rates.empty() ? 0.0 : rates[e], previous));
      if (loads != nullptr) loads->keep(parts.C, parts.source);
      add_edges(e, d.x, current, block.K, block.f);
      assembler_.add(e, ElementBlock::of(block.K, block.f), sink);
      continue;
    }
    const ConductionData d = data(el, k[e]);
    ConductionBlock block = conduction_block(d, load(e, rates.empty() ? 0.0 : rates[e], previous));
    if (loads != nullptr) loads->keep(conduction_load_parts(d, source_[e]));
    add_edges(e, d.x, current, block.K, block.f);
    assembler_.add(e, ElementBlock::of(block.K, block.f), sink);
  }
  const Eigen::Vector4d none = Eigen::Vector4d::Zero();
  assert(gap_conductance.size() == gap_count());
  for (std::size_t g = 0; g < gap_count(); ++g) {
    const Eigen::Matrix4d K = gap_matrix(g, gap_conductance[g]);
    assembler_.add(model_.elements.size() + g, ElementBlock::of(K, none), sink);
  }
  assert(contact_conductance.size() == contact_.row_count());
  for (std::size_t r = 0; r < contact_.row_count(); ++r) {
    const Eigen::MatrixXd K = contact_.block(r, contact_conductance[r]);
    const Eigen::VectorXd zero = Eigen::VectorXd::Zero(K.rows());
    assembler_.add(model_.elements.size() + gap_count() + r, ElementBlock::of(K, zero), sink);
  }
  hold_isolated(gap_conductance, previous, values, rhs);
}

void ThermalSystem::assemble_rhs(std::span<const Conductivity> k, double inverse_dt, std::span<const double> previous,
                                 std::span<const double> gap_conductance,
                                 std::span<const double> contact_conductance, const ConductionLoads& loads,
                                 std::span<double> rhs) const {
  assert(!radiates_ && loads.size() == model_.elements.size());
  std::fill(rhs.begin(), rhs.end(), 0.0);
  const std::vector<double> rates = capacity_rates(inverse_dt, previous);
  // Films add into these; add_rhs reads no K unless the element is lifted.
  Eigen::Matrix4d unused = Eigen::Matrix4d::Zero();
  ConductionMatrix unused_iso;
  // A lifted element's whole block (its K lifts the prescribed temperatures), edges included.
  const auto add_whole = [&](std::size_t e, std::span<const Vec2> x, auto block) {
    add_edges(e, x, {}, block.K, block.f);
    assembler_.add_rhs(e, ElementBlock::of(block.K, block.f), rhs);
  };
  for (std::size_t e = 0; e < model_.elements.size(); ++e) {
    const ConductionLoad element_load = load(e, rates.empty() ? 0.0 : rates[e], previous);
    const Element& el = model_.elements[e];
    const bool lifted = assembler_.lifted(e);
    if (conducts_isoparametrically(el.type)) {
      if (lifted) {
        const IsoConductionData d = iso_data(el, k[e]);
        add_whole(e, d.x, isoparametric_conduction_block(d, element_load));
        continue;
      }
      ConductionVector f = isoparametric_conduction_load(loads.capacity(e), loads.source(e), element_load);
      unused_iso.setZero(f.size(), f.size());
      if (!edges_[e].empty()) add_edges(e, node_coordinates(model_, el.node_span()), {}, unused_iso, f);
      assembler_.add_rhs(e, ElementBlock::of(unused_iso, f), rhs);
      continue;
    }
    if (lifted) {
      const ConductionData d = data(el, k[e]);
      add_whole(e, d.x, conduction_block(d, element_load));
      continue;
    }
    Eigen::Vector4d f = conduction_load(loads.report_parts(e), element_load);
    if (!edges_[e].empty()) add_edges(e, corner_coordinates(model_, el.nodes, el.node_count), {}, unused, f);
    assembler_.add_rhs(e, ElementBlock::of(unused, f), rhs);
  }
  // Gap and contact cliques load the rhs only through their prescribed temperatures; their zeros
  // are added too, as assemble does, so that not even the sign of a zero differs.
  const Eigen::Vector4d none = Eigen::Vector4d::Zero();
  for (std::size_t g = 0; g < gap_count(); ++g) {
    const std::size_t clique = model_.elements.size() + g;
    const Eigen::Matrix4d K = gap_matrix(g, gap_conductance[g]);
    assembler_.add_rhs(clique, ElementBlock::of(K, none), rhs);
  }
  for (std::size_t r = 0; r < contact_.row_count(); ++r) {
    const std::size_t clique = model_.elements.size() + gap_count() + r;
    const Eigen::MatrixXd K = contact_.block(r, contact_conductance[r]);
    const Eigen::VectorXd zero = Eigen::VectorXd::Zero(K.rows());
    assembler_.add_rhs(clique, ElementBlock::of(K, zero), rhs);
  }
  hold_isolated(gap_conductance, previous, {}, rhs);
}

std::vector<double> ThermalSystem::node_temperatures(std::span<const double> x) const {
  std::vector<double> T(model_.nodes.size());
  for (std::size_t n = 0; n < T.size(); ++n) {
    const Index eq = dofs_.equation(static_cast<int>(n), 0);
    T[n] = eq >= 0 ? x[static_cast<std::size_t>(eq)] : dofs_.prescribed(static_cast<int>(n), 0);
  }
  return T;
}

std::vector<Vec2> ThermalSystem::fluxes(std::span<const Conductivity> k, std::span<const double> T) const {
  std::vector<Vec2> q;
  q.reserve(model_.elements.size());
  for (std::size_t e = 0; e < model_.elements.size(); ++e) {
    const Element& el = model_.elements[e];
    std::array<double, max_element_nodes> t{};
    for (int a = 0; a < el.node_count; ++a) t[static_cast<std::size_t>(a)] = T[static_cast<std::size_t>(el.nodes[static_cast<std::size_t>(a)])];
    if (conducts_isoparametrically(el.type)) {
      q.push_back(isoparametric_conduction_flux(iso_data(el, k[e]), t));
      continue;
    }
    q.push_back(conduction_flux(data(el, k[e]), {t[0], t[1], t[2], t[3]}));
  }
  return q;
}

}  // namespace saasgaps
