#include "solver/assembly/element_data.hpp"

#include <cassert>

namespace saasgaps {

std::array<Vec2, max_element_nodes> node_coordinates(const Model& model, std::span<const int> nodes) {
  std::array<Vec2, max_element_nodes> x;
  for (Vec2& p : x) p.setZero();
  for (std::size_t a = 0; a < nodes.size(); ++a) {
    x[a] = Vec2(model.nodes[static_cast<std::size_t>(nodes[a])].r, model.nodes[static_cast<std::size_t>(nodes[a])].z);
  }
  return x;
}

ElementVector element_displacements(std::span<const double> u, std::span<const int> nodes) {
  ElementVector ue(static_cast<Eigen::Index>(2 * nodes.size()));
  for (std::size_t a = 0; a < nodes.size(); ++a) {
    const auto n = static_cast<std::size_t>(nodes[a]);
    ue[static_cast<Eigen::Index>(2 * a)] = u[2 * n];
    ue[static_cast<Eigen::Index>(2 * a + 1)] = u[2 * n + 1];
  }
  return ue;
}

ElementEdge element_edge(const Model& model, std::size_t e, int node_a, int node_b) {
  const Element& el = model.elements[e];
  for (const EdgeNodes& local : family(el.type).edges) {
    const int first = el.nodes[static_cast<std::size_t>(local.first())];
    const int last = el.nodes[static_cast<std::size_t>(local.last())];
    if (!((first == node_a && last == node_b) || (first == node_b && last == node_a))) continue;
    ElementEdge edge;
    edge.count = local.count;
    for (int k = 0; k < local.count; ++k) {
      // Run from node_a to node_b: reversed when the element's edge runs the other way.
      const int from = first == node_a ? k : local.count - 1 - k;
      edge.node[static_cast<std::size_t>(k)] = el.nodes[static_cast<std::size_t>(local.node[static_cast<std::size_t>(from)])];
    }
    return edge;
  }
  assert(false && "the reader checked that the element has this edge");
  return {};
}

double element_temperature(const Model& model, std::span<const int> nodes) {
  double sum = 0.0;
  for (const int n : nodes) sum += model.loads.node_temperature[static_cast<std::size_t>(n)];
  return sum / static_cast<double>(nodes.size());
}

namespace {

/// What solid and gap elements share: nodes, analysis, thickness.
ElementData element_geometry(const Model& model, std::span<const int> nodes) {
  ElementData d;
  d.node_count = static_cast<int>(nodes.size());
  d.x = node_coordinates(model, nodes);
  d.analysis = model.analysis;
  d.thickness = model.thickness;
  return d;
}

}  // namespace

ElementData solid_element_geometry(const Model& model, std::size_t e) {
  const Element& el = model.elements[e];
  ElementData d = element_geometry(model, el.node_span());
  d.type = el.type;
  d.integration = el.integration;
  return d;
}

namespace {

ElementData solid_data(const Model& model, std::size_t e) {
  const Element& el = model.elements[e];
  ElementData d = solid_element_geometry(model, e);
  for (int a = 0; a < el.node_count; ++a) {
    d.dT[static_cast<std::size_t>(a)] =
        model.loads.node_temperature[static_cast<std::size_t>(el.nodes[static_cast<std::size_t>(a)])] -
        model.reference_temperature;
  }
  const double density = model.materials[static_cast<std::size_t>(el.material)].density;
  const BodyForce& b = model.loads.body_force;
  d.body_force = density * Vec2(b.accel_r, b.accel_z);
  d.spin = model.analysis == AnalysisType::axisymmetric ? density * b.omega * b.omega : 0.0;
  return d;
}

}  // namespace

ElementData solid_element_data(const Model& model, std::size_t e, const Constitutive& law) {
  ElementData d = solid_data(model, e);
  d.law = law;
  return d;
}

ElementData solid_element_data(const Model& model, std::size_t e, std::span<const Constitutive> point_laws) {
  ElementData d = solid_data(model, e);
  // One law is the law of every point, held by value (as the report's elements always had it).
  if (point_laws.size() == 1) {
    d.law = point_laws.front();
  } else {
    d.point_laws = point_laws;
  }
  return d;
}

ElementData gap_element_data(const Model& model, std::size_t g, const Constitutive& law) {
  const GapElement& gap = model.gaps->elements[g];
  ElementData d = element_geometry(model, std::span<const int>(gap.nodes).first(static_cast<std::size_t>(gap.node_count)));
  d.type = gap.node_count == 3 ? ElementType::tri3 : ElementType::saas;
  d.law = law;
  return d;
}

}  // namespace saasgaps
