#include "solver/assembly/element_data.hpp"

namespace saasgaps {

std::array<Vec2, 4> corner_coordinates(const Model& model, const std::array<int, 4>& nodes, int node_count) {
  std::array<Vec2, 4> x{};
  for (int a = 0; a < node_count; ++a) x[a] = Vec2(model.nodes[nodes[a]].r, model.nodes[nodes[a]].z);
  return x;
}

Vec8 element_displacements(std::span<const double> u, const std::array<int, 4>& nodes, int node_count) {
  Vec8 ue = Vec8::Zero();
  for (int a = 0; a < node_count; ++a) {
    ue[2 * a] = u[2 * nodes[a]];
    ue[2 * a + 1] = u[2 * nodes[a] + 1];
  }
  return ue;
}

double element_temperature(const Model& model, const std::array<int, 4>& nodes, int node_count) {
  double sum = 0.0;
  for (int a = 0; a < node_count; ++a) sum += model.loads.node_temperature[nodes[a]];
  return sum / node_count;
}

namespace {

/// What solid and gap elements share: corners, analysis, thickness, law.
ElementData element_geometry(const Model& model, const std::array<int, 4>& nodes, int node_count,
                             const Constitutive& law) {
  ElementData d;
  d.node_count = node_count;
  d.x = corner_coordinates(model, nodes, node_count);
  d.analysis = model.analysis;
  d.thickness = model.thickness;
  d.law = law;
  return d;
}

}  // namespace

ElementData solid_element_data(const Model& model, std::size_t e, const Constitutive& law) {
  const Element& el = model.elements[e];
  ElementData d = element_geometry(model, el.nodes, el.node_count, law);
  for (int a = 0; a < el.node_count; ++a) {
    d.dT[a] = model.loads.node_temperature[el.nodes[a]] - model.reference_temperature;
  }
  const double density = model.materials[el.material].density;
  const BodyForce& b = model.loads.body_force;
  d.body_force = density * Vec2(b.accel_r, b.accel_z);
  d.spin = model.analysis == AnalysisType::axisymmetric ? density * b.omega * b.omega : 0.0;
  return d;
}

ElementData gap_element_data(const Model& model, std::size_t g, const Constitutive& law) {
  const GapElement& gap = model.gaps->elements[g];
  return element_geometry(model, gap.nodes, gap.node_count, law);
}

}  // namespace saasgaps
