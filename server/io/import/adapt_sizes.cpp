#include "io/import/adapt_sizes.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "solver/base/errors.hpp"
#include "solver/fe/element_family.hpp"

namespace saasgaps::io {

namespace {

constexpr double max_reduction = 0.25;  ///< h_new >= h / 4 per cycle
constexpr double max_growth = 2.0;      ///< h_new <= 2 h per cycle

/// Area of the polygon of an element's corners (counter-clockwise: positive).
double corner_area(const Model& model, const Element& e, int corners) {
  double twice = 0.0;
  for (int i = 0; i < corners; ++i) {
    const Node& a = model.nodes[static_cast<std::size_t>(e.nodes[static_cast<std::size_t>(i)])];
    const Node& b = model.nodes[static_cast<std::size_t>(e.nodes[static_cast<std::size_t>((i + 1) % corners)])];
    twice += a.r * b.z - b.r * a.z;
  }
  return 0.5 * std::fabs(twice);
}

}  // namespace

AdaptSizes adapt_sizes(const Model& model, const Solution& solution, double target, std::size_t max_nodes) {
  if (!solution.error_estimate || solution.elements.size() != model.elements.size()) {
    throw SolverError("the solution carries no error estimate: nothing to adapt the mesh to");
  }
  const std::size_t count = model.elements.size();
  const ErrorEstimate& est = *solution.error_estimate;
  const double e_bar = target * std::sqrt((est.energy_norm * est.energy_norm + est.error * est.error) /
                                          static_cast<double>(std::max<std::size_t>(count, 1)));
  double rmin = 1e300, rmax = -1e300, zmin = 1e300, zmax = -1e300;
  for (const Node& n : model.nodes) {
    rmin = std::min(rmin, n.r), rmax = std::max(rmax, n.r), zmin = std::min(zmin, n.z), zmax = std::max(zmax, n.z);
  }
  const double extent = std::max(rmax - rmin, zmax - zmin);
  const double h_floor = extent / 2000.0, h_ceiling = extent / 2.0;

  std::vector<double> h_new(count), area(count);
  std::vector<bool> triangle(count);
  for (std::size_t k = 0; k < count; ++k) {
    const Element& e = model.elements[k];
    const ElementFamily& f = family(e.type);
    area[k] = corner_area(model, e, f.corner_count);
    triangle[k] = f.corner_count == 3;
    const double h = triangle[k] ? std::sqrt(4.0 * area[k] / std::numbers::sqrt3) : std::sqrt(area[k]);
    const double p = f.quadratic() ? 2.0 : 1.0;
    const double xi = e_bar > 0.0 ? solution.elements[k].error / e_bar : 0.0;
    // xi = 0 (no error here): as coarse as the clamps allow.
    const double wanted = xi > 0.0 ? h / std::pow(xi, 1.0 / p) : max_growth * h;
    h_new[k] = std::clamp(std::clamp(wanted, max_reduction * h, max_growth * h), h_floor, h_ceiling);
  }
  // Nodes the sizes ask for: a quadrilateral of side h per node, or two triangles of side h
  // (each sqrt 3 / 4 h^2) per node.
  const auto predicted = [&](double scale) {
    double nodes = 0.0;
    for (std::size_t k = 0; k < count; ++k) {
      const double h = scale * h_new[k];
      nodes += triangle[k] ? area[k] / (std::numbers::sqrt3 / 2.0 * h * h) : area[k] / (h * h);
    }
    return nodes;
  };
  AdaptSizes out;
  out.predicted_nodes = predicted(1.0);
  if (out.predicted_nodes > static_cast<double>(max_nodes)) {
    // Nodes scale as 1 / scale^2; a margin of 10 % for the boundary's nodes.
    const double scale = std::sqrt(out.predicted_nodes / (0.9 * static_cast<double>(max_nodes)));
    for (double& h : h_new) h = std::min(h * scale, h_ceiling);
    out.predicted_nodes = predicted(1.0);
    out.bounded_by_nodes = true;
  }

  // Nodal sizes: the mean of the elements around each corner node.
  std::vector<double> sum(model.nodes.size(), 0.0);
  std::vector<int> seen(model.nodes.size(), 0);
  for (std::size_t k = 0; k < count; ++k) {
    const Element& e = model.elements[k];
    for (int i = 0; i < family(e.type).corner_count; ++i) {
      const auto n = static_cast<std::size_t>(e.nodes[static_cast<std::size_t>(i)]);
      sum[n] += h_new[k];
      ++seen[n];
    }
  }
  std::vector<int> index(model.nodes.size(), -1);
  SizeField& field = out.field;
  for (std::size_t n = 0; n < model.nodes.size(); ++n) {
    if (seen[n] == 0) continue;
    index[n] = static_cast<int>(field.size.size());
    field.x.push_back(model.nodes[n].r);
    field.y.push_back(model.nodes[n].z);
    field.size.push_back(sum[n] / seen[n]);
  }
  for (const Element& e : model.elements) {
    const auto at = [&](int i) { return index[static_cast<std::size_t>(e.nodes[static_cast<std::size_t>(i)])]; };
    field.triangles.push_back({at(0), at(1), at(2)});
    if (family(e.type).corner_count == 4) field.triangles.push_back({at(0), at(2), at(3)});
  }
  return out;
}

}  // namespace saasgaps::io
