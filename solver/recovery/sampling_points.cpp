#include "solver/recovery/sampling_points.hpp"

#include <cassert>

#include "solver/fe/isoparametric_kernel.hpp"
#include "solver/fe/quadrature.hpp"

namespace saasgaps {

namespace {

/// 1-D Lagrange weights of the 3-point Gauss abscissae evaluated at s.
std::array<double, 3> lagrange3(double s) {
  const auto line = gauss_line(3);
  std::array<double, 3> L{};
  for (std::size_t j = 0; j < 3; ++j) {
    double l = 1.0;
    for (std::size_t k = 0; k < 3; ++k) {
      if (k != j) l *= (s - line[k].s) / (line[j].s - line[k].s);
    }
    L[j] = l;
  }
  return L;
}

std::array<std::array<double, 9>, 4> make_gauss3_to_gauss2() {
  std::array<std::array<double, 9>, 4> W{};
  const auto two = gauss_square(2);
  for (std::size_t q = 0; q < 4; ++q) {
    const auto Lx = lagrange3(two[q].xi);
    const auto Ly = lagrange3(two[q].eta);
    // gauss_square(3) is the product of gauss_line(3), xi fastest: point p = i + 3 j.
    for (std::size_t j = 0; j < 3; ++j) {
      for (std::size_t i = 0; i < 3; ++i) W[q][i + 3 * j] = Lx[i] * Ly[j];
    }
  }
  return W;
}

/// The (r, z) of reference point (xi, eta) of an isoparametric element.
Vec2 position(const ElementData& e, double xi, double eta) {
  ShapeValues v;
  family(e.type).shape(xi, eta, v);
  Vec2 x = Vec2::Zero();
  for (int a = 0; a < e.node_count; ++a) x += v.N[static_cast<std::size_t>(a)] * e.x[static_cast<std::size_t>(a)];
  return x;
}

}  // namespace

const std::array<std::array<double, 9>, 4>& gauss3_to_gauss2() {
  static const auto W = make_gauss3_to_gauss2();
  return W;
}

ElementSamples stress_samples(const ElementData& e, std::span<const ElementState> states) {
  ElementSamples out;
  switch (e.type) {
    case ElementType::saas:
    case ElementType::tri3: {
      // The report's elements keep one material point: a tri3's constant stress at its centroid, a
      // saas quad's at its centre node, the mean of its corners (3 nodes: a tri3 typed saas).
      assert(states.size() == 1);
      Vec2 centre = Vec2::Zero();
      for (int a = 0; a < e.node_count; ++a) centre += e.x[static_cast<std::size_t>(a)];
      out.count = 1;
      out.point[0] = {centre / e.node_count, states[0].stress};
      return out;
    }
    case ElementType::quad8:
    case ElementType::quad9:
      if (states.size() == 9) {
        const auto two = gauss_square(2);
        const auto& W = gauss3_to_gauss2();
        out.count = 4;
        for (std::size_t q = 0; q < 4; ++q) {
          Vec4 s = Vec4::Zero();
          for (std::size_t p = 0; p < 9; ++p) s += W[q][p] * states[p].stress;
          out.point[q] = {position(e, two[q].xi, two[q].eta), s};
        }
        return out;
      }
      [[fallthrough]];
    case ElementType::tri6:
    case ElementType::quad4i: {
      const auto rule = family(e.type).material_points(e.integration);
      assert(rule.size() == states.size() && rule.size() <= max_sampling_points);
      out.count = static_cast<int>(states.size());
      for (std::size_t p = 0; p < rule.size(); ++p) {
        out.point[p] = {position(e, rule[p].xi, rule[p].eta), states[p].stress};
      }
      return out;
    }
  }
  return out;
}

}  // namespace saasgaps
