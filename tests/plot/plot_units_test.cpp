// The pieces of the plot library that need no image: band clipping, round levels, number labels,
// field catalogue and nodal averaging, on small hand-made result documents.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>

#include "plot/band_levels.hpp"
#include "plot/contour_bands.hpp"
#include "plot/field.hpp"
#include "plot/nice_scale.hpp"
#include "plot/number_format.hpp"
#include "plot/point_locator.hpp"
#include "plot/plot_request.hpp"
#include "plot/result_mesh.hpp"

namespace saasgaps::plot {
namespace {

using nlohmann::json;

TEST(ContourBands, BandsBetweenLevelsTileTheTriangle) {
  const ValuePolygon tri{{0.0, 0.0, 0.0}, {4.0, 0.0, 10.0}, {0.0, 3.0, 5.0}};
  const std::vector<double> levels{-1.0, 2.0, 4.0, 6.0, 8.0, 11.0};
  double area = 0.0;
  for (std::size_t k = 0; k + 1 < levels.size(); ++k) {
    const ValuePolygon b = band(tri, levels[k], levels[k + 1]);
    for (const ValuePoint& p : b) {
      EXPECT_GE(p.v, levels[k] - 1e-12);
      EXPECT_LE(p.v, levels[k + 1] + 1e-12);
      // v is linear: v = 2.5 x + 5/3 y on this triangle; the cut points must lie on that plane.
      EXPECT_NEAR(p.v, 2.5 * p.x + 5.0 / 3.0 * p.y, 1e-12);
    }
    area += signed_area(b);
  }
  EXPECT_NEAR(area, signed_area(tri), 1e-12);
  EXPECT_NEAR(signed_area(tri), 6.0, 1e-12);
}

TEST(ContourBands, ClipKeepsTheSideAtOrAboveTheLevel) {
  const ValuePolygon tri{{0.0, 0.0, 0.0}, {1.0, 0.0, 1.0}, {0.0, 1.0, 0.0}};
  // v = x: the part x >= 0.5 is the small triangle (0.5, 0) (1, 0) (0.5, 0.5), area 1/8.
  EXPECT_NEAR(signed_area(clip_at_least(tri, 0.5)), 0.125, 1e-12);
  EXPECT_NEAR(signed_area(clip_at_most(tri, 0.5)), 0.375, 1e-12);
  EXPECT_TRUE(clip_at_least(tri, 2.0).empty());
  EXPECT_NEAR(signed_area(clip_at_least(tri, -1.0)), 0.5, 1e-12);
}

TEST(ContourBands, QuadSplitsAlongTheShorterDiagonal) {
  // A kite: diagonal 0-2 is long (4), 1-3 short (2).
  const std::vector<ValuePoint> quad{{0.0, 0.0, 0.0}, {2.0, -1.0, 0.0}, {4.0, 0.0, 0.0}, {2.0, 1.0, 0.0}};
  const std::vector<ValuePolygon> tris = triangulate(quad);
  ASSERT_EQ(tris.size(), 2U);
  EXPECT_NEAR(signed_area(tris[0]) + signed_area(tris[1]), 4.0, 1e-12);
  for (const ValuePolygon& t : tris) {
    EXPECT_GT(signed_area(t), 0.0);  // still counter-clockwise
    const bool uses_1 = std::any_of(t.begin(), t.end(), [](const ValuePoint& p) { return p.x == 2.0 && p.y == -1.0; });
    const bool uses_3 = std::any_of(t.begin(), t.end(), [](const ValuePoint& p) { return p.x == 2.0 && p.y == 1.0; });
    EXPECT_TRUE(uses_1 && uses_3);
  }
}

TEST(NiceScale, RoundLevelsEnclosingTheData) {
  const Scale s = nice_scale(787.2, 7754.0, 12, level_mantissas);
  EXPECT_DOUBLE_EQ(s.step, 600.0);
  EXPECT_DOUBLE_EQ(s.lo, 600.0);
  EXPECT_DOUBLE_EQ(s.hi, 7800.0);
  EXPECT_EQ(s.intervals(), 12);
  const Scale t = nice_scale(-91532.0, 6556.0, 12, level_mantissas);
  EXPECT_LE(t.intervals(), 12);
  EXPECT_LE(t.lo, -91532.0);
  EXPECT_GE(t.hi, 6556.0);
  const std::vector<double> v = t.values();
  EXPECT_NE(std::find(v.begin(), v.end(), 0.0), v.end()) << "an exact zero level where the scale crosses it";
}

TEST(NiceScale, UniformValueGetsOneInterval) {
  const Scale s = nice_scale(0.0, 0.0, 12, level_mantissas);
  EXPECT_EQ(s.intervals(), 1);
  EXPECT_LT(s.lo, 0.0);
  EXPECT_GT(s.hi, 0.0);
  EXPECT_EQ(nice_scale(-1000.0, -1000.0, 12, level_mantissas).intervals(), 1);
  // Round-off on a uniform stress (report problem 2) is not a pattern to contour.
  EXPECT_TRUE(is_uniform(10005.8265, 10005.8295));
  EXPECT_EQ(nice_scale(10005.8265, 10005.8295, 12, level_mantissas).intervals(), 1);
  EXPECT_FALSE(is_uniform(1.0, 1.001));
  EXPECT_THROW(nice_scale(0.0, NAN, 12, level_mantissas), std::invalid_argument);
}

TEST(NumberFormat, EngineeringLabels) {
  const TickFormat stress(600.0, 7800.0);
  EXPECT_EQ(stress(7200.0), "7200");
  EXPECT_EQ(stress(0.0), "0");
  EXPECT_EQ(stress(-1e-13), "0");
  EXPECT_EQ(TickFormat(2.5, 10.0)(7.5), "7.5");
  EXPECT_EQ(TickFormat(0.001, 0.009)(0.004), "0.004");
  EXPECT_EQ(TickFormat(2e5, 1.2e6)(-1.2e6), "-1.2e+06");
  EXPECT_EQ(TickFormat(1e-4, 8e-4)(5e-4), "5e-04");
  EXPECT_EQ(TickFormat(2.5e-4, 1e-3 - 1e-9)(7.5e-4), "7.5e-04");
  EXPECT_EQ(format_value(12519.3), "12519");
  EXPECT_EQ(format_value(50.0, 3), "50");
  EXPECT_EQ(format_value(0.0093879), "0.009388");
  EXPECT_EQ(format_value(-2.5e7), "-2.500e+07");
}

/// Two solid elements side by side, 1 x 1 and 2 x 1 (areas 1 and 2), and a gap element under the
/// first one, down to two wall nodes that no solid element uses.
json two_squares() {
  json nodes = json::array();
  const double coords[][2] = {{0, 0}, {1, 0}, {3, 0}, {0, 1}, {1, 1}, {3, 1}, {0, -0.01}, {1, -0.01}};
  for (int i = 0; i < 8; ++i) {
    nodes.push_back({{"id", i + 1}, {"r", coords[i][0]}, {"z", coords[i][1]}, {"T", 10.0 * i}, {"u_r", 0.003 * i},
                     {"u_z", -0.004 * i}});
  }
  const auto element = [](int id, std::vector<int> n, double s) {
    return json{{"id", id}, {"nodes", n}, {"material", 1}, {"sigma_r", s}, {"sigma_z", 0.0}, {"tau_rz", 0.0},
                {"sigma_theta", 0.0}, {"sigma_1", s}, {"sigma_2", 0.0}, {"angle", 0.0}, {"effective", std::abs(s)},
                {"eps_r", 0.0}, {"eps_z", 0.0}, {"gamma_rz", 0.0}, {"eps_theta", 0.0}, {"yield", false},
                {"plastic_converged", true}};
  };
  return {{"status", "converged"},
          {"iterations", 1},
          {"title", "two squares"},
          {"analysis", "plane_stress"},
          {"history", json::array()},
          {"nodes", nodes},
          {"elements", {element(1, {1, 2, 5, 4}, 10.0), element(2, {2, 3, 6, 5}, 40.0)}},
          {"gaps", {{{"id", 3}, {"nodes", {7, 8, 2, 1}}, {"angle", 90.0}, {"eps_m", -0.5}, {"closure", 50.0},
                     {"modulus", 1.0}, {"sigma_m", -1e6}, {"state", "partial"}, {"converged", true}}}}};
}

TEST(Field, ElementValuesAreAreaWeightedAtTheNodesWithoutGaps) {
  const json result = two_squares();
  const ResultMesh mesh = ResultMesh::from_result(result);
  const std::vector<double> v = nodal_values(result, mesh, find_field("sigma_r"));
  ASSERT_EQ(v.size(), 8U);
  EXPECT_DOUBLE_EQ(v[0], 10.0);                              // node 1: element 1 only
  EXPECT_DOUBLE_EQ(v[1], (1.0 * 10.0 + 2.0 * 40.0) / 3.0);  // node 2: shared, areas 1 and 2
  EXPECT_DOUBLE_EQ(v[2], 40.0);
  EXPECT_TRUE(std::isnan(v[6])) << "a wall node of the gap only has no element value";
  const std::vector<double> d = nodal_values(result, mesh, find_field("displacement"));
  EXPECT_DOUBLE_EQ(d[3], std::hypot(0.009, -0.012));
  EXPECT_DOUBLE_EQ(nodal_values(result, mesh, find_field("temperature"))[5], 50.0);
  EXPECT_THROW(nodal_values(result, mesh, find_field("closure")), std::invalid_argument);
  EXPECT_DOUBLE_EQ(gap_values(mesh, find_field("closure")).at(0), 50.0);
}

TEST(Field, UnknownNamesListTheValidOnes) {
  try {
    find_field("sigma_x");
    FAIL() << "no exception";
  } catch (const std::invalid_argument& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("unknown field 'sigma_x'"), std::string::npos) << what;
    for (const char* name : {"sigma_r", "sigma_theta", "effective", "temperature", "displacement", "closure"}) {
      EXPECT_NE(what.find(name), std::string::npos) << name;
    }
  }
  try {
    require_plot_name("stress");
    FAIL() << "no exception";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("convergence"), std::string::npos) << e.what();
  }
}

TEST(ResultMesh, ReadsConnectivityAndRefusesFailedRuns) {
  const ResultMesh mesh = ResultMesh::from_result(two_squares());
  EXPECT_EQ(mesh.solids.size(), 2U);
  ASSERT_EQ(mesh.gaps.size(), 1U);
  EXPECT_EQ(mesh.gaps[0].state, GapState::partial);
  EXPECT_DOUBLE_EQ(mesh.area(mesh.solids[1]), 2.0);
  EXPECT_TRUE(mesh.plane());
  EXPECT_THROW(ResultMesh::from_result(json{{"status", "failed"}, {"message", "singular"}}), std::invalid_argument);
  json broken = two_squares();
  broken["elements"][0]["nodes"][0] = 99;
  EXPECT_THROW(ResultMesh::from_result(broken), std::invalid_argument);
}

TEST(RenderPlot, SmallDocumentDrawsEveryKindOfPlot) {
  PlotRequest request;
  request.width = 400;
  request.height = 300;
  for (const std::string& name : plot_names()) {
    request.name = name;
    if (name == "convergence") continue;  // two_squares has no history; see the next test
    for (const ImageFormat format : {ImageFormat::png, ImageFormat::svg}) {
      request.format = format;
      const std::string image = render_plot(two_squares(), request);
      EXPECT_GT(image.size(), 1000U) << name;
    }
  }
  request.name = "convergence";
  EXPECT_THROW(render_plot(two_squares(), request), std::invalid_argument);
  request.name = "effective";
  request.width = 5;
  EXPECT_THROW(render_plot(two_squares(), request), std::invalid_argument);
}

TEST(RenderPlot, BadOptionsAreInvalidArguments) {
  PlotRequest request;
  request.contour.color_map = "jet";
  EXPECT_THROW(render_plot(two_squares(), request), std::invalid_argument);
  request.contour.color_map = "viridis";
  request.contour.deformation_scale = -3.0;
  EXPECT_THROW(render_plot(two_squares(), request), std::invalid_argument);
  EXPECT_THROW(image_format_for_path("plot.jpg"), std::invalid_argument);
  EXPECT_THROW(image_format_for_path("png"), std::invalid_argument);
  EXPECT_EQ(image_format_for_path("out/Plot.SVG"), ImageFormat::svg);
}

}  // namespace
}  // namespace saasgaps::plot

namespace saasgaps::plot {
namespace {

TEST(BandLevels, QuantileLevelsSplitTheAreaNotTheRange) {
  // 90 % of the area between 0 and 9, a peak at 1000 on the rest: even levels put the 90 % in one
  // band; quantile levels give it all bands but the last.
  std::vector<double> values, weights;
  for (int i = 0; i < 90; ++i) {
    values.push_back(i * 0.1);
    weights.push_back(1.0);
  }
  for (int i = 0; i < 10; ++i) {
    values.push_back(900.0 + 10.0 * i);
    weights.push_back(1.0);
  }
  const BandLevels even = band_levels(values, weights, 10, LevelRule::even);
  const BandLevels quantile = band_levels(values, weights, 10, LevelRule::quantile);
  const auto bands_below = [](const BandLevels& b, double v) {
    return std::count_if(b.levels.begin(), b.levels.end(), [v](double l) { return l <= v; });
  };
  EXPECT_LE(bands_below(even, 9.0), 1) << "even: the 90 % sits in the first band";
  EXPECT_GE(bands_below(quantile, 9.0), 8) << "quantile: the 90 % gets most bands";
  EXPECT_LE(quantile.levels.front(), 0.0);
  EXPECT_GE(quantile.levels.back(), 990.0);
  EXPECT_TRUE(std::is_sorted(quantile.levels.begin(), quantile.levels.end()));
  EXPECT_EQ(std::adjacent_find(quantile.levels.begin(), quantile.levels.end()), quantile.levels.end());
}

TEST(BandLevels, ATwoValuedFieldGetsALevelBetweenItsValues) {
  const BandLevels b = band_levels({0.0, 0.0, 0.0, 400.0, 400.0, NAN}, {1.0, 1.0, 1.0, 1.0, 1.0, 1.0}, 12,
                                   LevelRule::quantile);
  ASSERT_EQ(b.levels.size(), 3U);
  EXPECT_EQ(b.levels[0], 0.0);
  EXPECT_GT(b.levels[1], 0.0);
  EXPECT_LT(b.levels[1], 400.0);
  EXPECT_EQ(b.levels[2], 400.0);
  EXPECT_TRUE(band_levels({5.0, 5.0}, {1.0, 1.0}, 12, LevelRule::quantile).uniform);
  EXPECT_THROW(band_levels({NAN}, {1.0}, 12, LevelRule::quantile), std::invalid_argument);
}

}  // namespace
}  // namespace saasgaps::plot

namespace saasgaps::plot {
namespace {

TEST(GapRow, IdsRangesAxesAndErrors) {
  EXPECT_EQ(parse_gap_ids("3,5-7,2"), (std::vector<int>{3, 5, 6, 7, 2}));
  for (const char* bad : {"", "3,,4", "a", "5-", "0", "7-5", "1-99999999"}) {
    EXPECT_THROW(parse_gap_ids(bad), std::invalid_argument) << bad;
  }
  EXPECT_EQ(row_axis("position"), RowAxis::position);
  EXPECT_THROW(row_axis("arc"), std::invalid_argument);
  const ResultMesh mesh = ResultMesh::from_result(two_squares());
  const GapRow row = select_gap_row(mesh, {{3}, RowAxis::r});
  ASSERT_EQ(row.gaps.size(), 1U);
  EXPECT_DOUBLE_EQ(row.x[0], 0.5) << "the gap centre's r";
  EXPECT_THROW(select_gap_row(mesh, {{4}, RowAxis::index}), std::invalid_argument) << "4 is no gap";
  EXPECT_DOUBLE_EQ(mesh.gaps[0].contact_pressure, 1e6) << "max(0, -sigma_m) when the document lacks it";
}

TEST(PointLocator, FindsTheElementAndItsWeights) {
  const ResultMesh mesh = ResultMesh::from_result(two_squares());
  const PointLocator locator(mesh);
  const std::optional<Location> in_second = locator.locate(2.0, 0.25);
  ASSERT_TRUE(in_second);
  EXPECT_EQ(mesh.solids[in_second->element].id, 2);
  double r = 0.0, z = 0.0, sum = 0.0;
  for (int c = 0; c < 3; ++c) {
    r += in_second->weights[c] * mesh.nodes[in_second->nodes[c]].r;
    z += in_second->weights[c] * mesh.nodes[in_second->nodes[c]].z;
    sum += in_second->weights[c];
  }
  EXPECT_NEAR(r, 2.0, 1e-12);
  EXPECT_NEAR(z, 0.25, 1e-12);
  EXPECT_NEAR(sum, 1.0, 1e-12);
  EXPECT_EQ(mesh.solids[locator.locate(0.5, 0.5)->element].id, 1);
  EXPECT_TRUE(locator.locate(3.0, 1.0)) << "a corner belongs to its element";
  EXPECT_FALSE(locator.locate(0.5, -0.005)) << "inside the gap, outside every solid";
  EXPECT_FALSE(locator.locate(-1.0, 0.5));
}

TEST(PathPlot, PathsParseAndTablesRoundTrip) {
  const auto points = parse_path("0,0.5;3,0.5");
  ASSERT_EQ(points.size(), 2U);
  EXPECT_EQ(points[1][0], 3.0);
  for (const char* bad : {"1,2", "1,2;3", "a,b;1,1", "1,1;1,1", "1,2;3,4;"}) {
    EXPECT_THROW(parse_path(bad), std::invalid_argument) << bad;
  }
  PlotRequest request;
  request.name = "sigma_r";
  request.width = 600;
  request.height = 400;
  request.path = PathOptions{points, 7};
  const std::string csv = render_table(two_squares(), request);
  // s = 0, 0.5, .., 3 along z = 0.5: element 1 (sigma_r 10) up to r = 1, then element 2 (40).
  EXPECT_NE(csv.find("\n0,0,0.5,1,10,"), std::string::npos) << csv;
  EXPECT_NE(csv.find("\n3,3,0.5,2,40,"), std::string::npos) << csv;
  EXPECT_EQ(DataTable::number(0.1), "0.1");
  EXPECT_EQ(DataTable::number(NAN), "");
  request.path.reset();
  EXPECT_THROW(render_table(two_squares(), request), std::invalid_argument) << "a contour plot has no table";
}

}  // namespace
}  // namespace saasgaps::plot
