// The field pictures and probes read inside the elements (plot/result/element_field.hpp): point
// location by each element's own map, interpolation with its shape functions, material sides, and
// the contour plot's legend read from the same field.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <vector>

#include <nlohmann/json.hpp>

#include "plot/draw/canvas.hpp"
#include "plot/pictures/contour_plot.hpp"
#include "plot/result/element_field.hpp"
#include "plot/result/element_map.hpp"
#include "plot/result/point_locator.hpp"

namespace saasgaps::plot {
namespace {

using nlohmann::json;

/// A complete quadratic in x, y: what a quad8 or tri6 on straight-sided (affine) elements
/// interpolates exactly.
double quadratic(double x, double y) { return 1.0 + 2.0 * x - 3.0 * y + 4.0 * x * x + 5.0 * x * y - 6.0 * y * y; }

/// A result of the given elements (corner and mid-side points per element, in the family's order),
/// nodes shared by position, the recovered stresses at the nodes from `stress(x, y)`.
class Builder {
 public:
  int node(double x, double y) {
    const auto key = std::make_pair(std::lround(x * 1e6), std::lround(y * 1e6));
    if (const auto found = ids_.find(key); found != ids_.end()) return found->second;
    const int id = static_cast<int>(points_.size()) + 1;
    ids_.emplace(key, id);
    points_.push_back({x, y});
    return id;
  }
  void element(const std::vector<std::array<double, 2>>& points, int material = 1) {
    std::vector<int> ids;
    for (const auto& p : points) ids.push_back(node(p[0], p[1]));
    elements_.push_back({{"id", static_cast<int>(elements_.size()) + 1}, {"nodes", ids}, {"material", material}});
  }
  template <class F>
  json result(const F& stress) const {
    json nodes = json::array();
    for (std::size_t n = 0; n < points_.size(); ++n) {
      const auto [x, y] = points_[n];
      nodes.push_back({{"id", static_cast<int>(n) + 1}, {"r", x}, {"z", y}, {"u_r", 0.0}, {"u_z", 0.0},
                       {"sigma_r", stress(x, y)}, {"sigma_z", 2.0 * stress(x, y)}, {"tau_rz", 0.5},
                       {"sigma_theta", 0.0}});
    }
    return {{"status", "converged"}, {"iterations", 1},   {"title", "patch"},
            {"analysis", "plane_stress"}, {"nodes", nodes}, {"elements", elements_}};
  }

 private:
  std::map<std::pair<long, long>, int> ids_;
  std::vector<std::array<double, 2>> points_;
  json elements_ = json::array();
};

/// A quad8 on the parallelogram with corners a, a + u, a + u + v, a + v.
std::vector<std::array<double, 2>> quad8(std::array<double, 2> a, std::array<double, 2> u, std::array<double, 2> v) {
  const auto at = [&](double s, double t) { return std::array<double, 2>{a[0] + s * u[0] + t * v[0], a[1] + s * u[1] + t * v[1]}; };
  return {at(0, 0), at(1, 0), at(1, 1), at(0, 1), at(0.5, 0), at(1, 0.5), at(0.5, 1), at(0, 0.5)};
}

json quad8_patch() {
  Builder b;
  b.element(quad8({0.0, 0.0}, {2.0, 0.0}, {0.5, 1.0}));
  b.element(quad8({2.0, 0.0}, {2.0, 0.3}, {0.5, 1.0}));
  b.element(quad8({0.5, 1.0}, {2.0, 0.0}, {-0.2, 1.2}));
  return b.result(quadratic);
}

TEST(ElementField, AQuadraticRecoveredOnQuad8sIsInterpolatedExactly) {
  const json document = quad8_patch();
  const PlotResult result(document);
  const ResultMesh& mesh = result.mesh();
  const PointLocator locator(mesh);
  const ElementField sigma_r(result, find_field("sigma_r"));
  const ElementField sigma_z(result, find_field("sigma_z"));
  ASSERT_EQ(sigma_r.source(), FieldSource::recovered);
  int found = 0;
  for (double x = 0.05; x < 4.5; x += 0.173) {
    for (double y = 0.02; y < 2.2; y += 0.111) {
      const std::optional<Location> at = locator.locate(x, y);
      if (!at) continue;
      ++found;
      const PlanePoint p = located_point(mesh, *at);
      EXPECT_NEAR(p[0], x, 1e-12);
      EXPECT_NEAR(p[1], y, 1e-12);
      EXPECT_NEAR(sigma_r.value(*at), quadratic(x, y), 1e-10) << x << ", " << y;
      EXPECT_NEAR(sigma_z.value(*at), 2.0 * quadratic(x, y), 2e-10);
    }
  }
  EXPECT_GT(found, 100);
}

TEST(ElementField, APointOnASharedEdgeHasOneValueWhicheverElementHoldsIt) {
  const json document = quad8_patch();
  const PlotResult result(document);
  const PointLocator locator(result.mesh());
  const ElementField effective(result, find_field("effective"));
  // On the edge (2, 0) - (2.5, 1) that elements 1 and 2 share, and on the edge (0.5, 1) - (2.5, 1)
  // of elements 1 and 3.
  for (const PlanePoint p : {PlanePoint{2.15, 0.3}, PlanePoint{2.4, 0.8}, PlanePoint{1.3, 1.0}}) {
    const std::vector<Location> all = locator.locate_all(p[0], p[1]);
    ASSERT_EQ(all.size(), 2U) << p[0] << ", " << p[1];
    EXPECT_NE(all[0].element, all[1].element);
    EXPECT_NEAR(effective.value(all[0]), effective.value(all[1]), 1e-10);
    const double s = quadratic(p[0], p[1]);
    // von Mises of (s, 2 s, 0.5, 0) in plane stress: sqrt(s^2 - 2 s^2 + 4 s^2 + 3 * 0.25).
    EXPECT_NEAR(effective.value(all[0]), std::sqrt(3.0 * s * s + 0.75), 1e-9);
  }
  EXPECT_FALSE(locator.locate(0.2, 0.9)) << "left of the first parallelogram";
}

TEST(ElementField, CurvedQuad8EdgesHoldThePointsOnTheirCurve) {
  Builder b;
  // One quad8 whose top edge bulges up through (1, 1.3): the point (1, 1.25) lies inside it.
  b.element({{0, 0}, {2, 0}, {2, 1}, {0, 1}, {1, 0}, {2, 0.5}, {1, 1.3}, {0, 0.5}});
  const json document = b.result(quadratic);
  const PlotResult result(document);
  const PointLocator locator(result.mesh());
  const std::optional<Location> at = locator.locate(1.0, 1.25);
  ASSERT_TRUE(at);
  const PlanePoint p = located_point(result.mesh(), *at);
  EXPECT_NEAR(p[0], 1.0, 1e-12);
  EXPECT_NEAR(p[1], 1.25, 1e-12);
  EXPECT_FALSE(locator.locate(1.0, 1.31));
}

TEST(ElementField, LinearFieldsAreExactInSaasElementsAndTriangles) {
  const auto linear = [](double x, double y) { return 3.0 - x + 2.0 * y; };
  Builder b;
  b.element({{0, 0}, {1.2, 0.1}, {1.0, 1.0}, {-0.1, 0.8}});  // saas: four triangles around the mean
  b.element({{1.2, 0.1}, {2.0, 0.5}, {1.0, 1.0}});           // tri3
  const json document = b.result(linear);
  const PlotResult result(document);
  const PointLocator locator(result.mesh());
  const ElementField field(result, find_field("sigma_r"));
  for (const PlanePoint p : {PlanePoint{0.5, 0.5}, PlanePoint{0.1, 0.05}, PlanePoint{1.1, 0.55}, PlanePoint{1.4, 0.5}}) {
    const std::optional<Location> at = locator.locate(p[0], p[1]);
    ASSERT_TRUE(at);
    EXPECT_NEAR(field.value(*at), linear(p[0], p[1]), 1e-12);
  }
}

TEST(ElementField, EachElementReadsItsOwnMaterialsSide) {
  Builder b;
  b.element(quad8({0.0, 0.0}, {1.0, 0.0}, {0.0, 1.0}), 1);
  b.element(quad8({1.0, 0.0}, {1.0, 0.0}, {0.0, 1.0}), 2);
  json document = b.result([](double, double) { return 10.0; });
  // The interface x = 1 (nodes at (1, 0), (1, 0.5), (1, 1)): material 1's side 10, material 2's 30.
  for (const json& n : document["nodes"]) {
    if (n["r"].get<double>() != 1.0) continue;
    for (const int material : {1, 2}) {
      const double s = material == 1 ? 10.0 : 30.0;
      document["node_sides"].push_back({{"node", n["id"]}, {"material", material}, {"sigma_r", s},
                                        {"sigma_z", 2.0 * s}, {"tau_rz", 0.5}, {"sigma_theta", 0.0},
                                        {"effective", 0.0}});
    }
  }
  const PlotResult result(document);
  const PointLocator locator(result.mesh());
  const ElementField field(result, find_field("sigma_r"));
  const std::vector<Location> on_interface = locator.locate_all(1.0, 0.3);
  ASSERT_EQ(on_interface.size(), 2U);
  EXPECT_NEAR(field.value(on_interface[0]), 10.0, 1e-12);
  EXPECT_NEAR(field.value(on_interface[1]), 30.0, 1e-12);
  EXPECT_NEAR(field.value(*locator.locate(0.5, 0.5)), 10.0, 1e-12);
  // Inside element 2 the side 30 at x = 1 falls to 10 at x = 1.5 and x = 2 along the quadratic
  // Lagrange weights in xi (at eta = 0 the serendipity functions of each column of nodes sum to them).
  const double xi = -0.5;  // x = 1.25
  const double corner = 0.5 * xi * (xi - 1.0), middle = 1.0 - xi * xi, far = 0.5 * xi * (xi + 1.0);
  EXPECT_NEAR(field.value(*locator.locate(1.25, 0.5)), 30.0 * corner + 10.0 * middle + 10.0 * far, 1e-12);
}

TEST(ContourPlot, TheColourBarAndTheMaxLabelReadTheRecoveredField) {
  const json document = quad8_patch();
  const PlotResult result(document);
  double top = -1e300, bottom = 1e300;
  for (const json& n : document["nodes"]) {
    top = std::max(top, n["sigma_r"].get<double>());
    bottom = std::min(bottom, n["sigma_r"].get<double>());
  }
  const Canvas canvas(ImageFormat::png, 800, 600);
  ContourOptions options;
  options.field = "sigma_r";
  const ContourLegend legend = draw_contour_plot(canvas, result, options);
  EXPECT_EQ(legend.source, FieldSource::recovered);
  // The quadratic's extremes on this patch lie at nodes, which the drawing samples.
  EXPECT_DOUBLE_EQ(legend.max, top);
  EXPECT_DOUBLE_EQ(legend.min, bottom);
  EXPECT_NEAR(quadratic(legend.max_at[0], legend.max_at[1]), top, 1e-9);
  ASSERT_GE(legend.levels.size(), 2U);
  const double step = legend.levels[1] - legend.levels[0];
  EXPECT_GE(legend.levels.back(), top);
  EXPECT_LT(legend.levels.back() - step, top) << "the top band holds the max";
  EXPECT_LE(legend.levels.front(), bottom);
  EXPECT_GT(legend.levels.front() + step, bottom);
}

TEST(ContourPlot, TheErrorMapGivesEachElementItsOwnError) {
  json document = quad8_patch();
  const std::array<double, 3> errors{0.25, 0.75, 0.5};
  for (std::size_t e = 0; e < errors.size(); ++e) document["elements"][e]["error"] = errors[e];
  const PlotResult result(document);
  const ElementField field(result, find_field("error"));
  EXPECT_EQ(field.source(), FieldSource::element);
  const PointLocator locator(result.mesh());
  // On the edge elements 1 and 2 share, each keeps its own value: the map is not averaged.
  const std::vector<Location> edge = locator.locate_all(2.15, 0.3);
  ASSERT_EQ(edge.size(), 2U);
  EXPECT_EQ(field.value(edge[0]), 0.25);
  EXPECT_EQ(field.value(edge[1]), 0.75);
  const Canvas canvas(ImageFormat::png, 800, 600);
  ContourOptions options;
  options.field = "error";
  const ContourLegend legend = draw_contour_plot(canvas, result, options);
  EXPECT_EQ(legend.source, FieldSource::element);
  EXPECT_EQ(legend.max, 0.75);
  EXPECT_EQ(legend.max_element, 2);
  EXPECT_EQ(legend.min, 0.25);
  EXPECT_EQ(legend.min_element, 1);
  // A result without estimates says so.
  document = quad8_patch();
  const PlotResult without(document);
  try {
    (void)ElementField(without, find_field("error"));
    ADD_FAILURE() << "no error without estimates";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("this result has none"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace saasgaps::plot
