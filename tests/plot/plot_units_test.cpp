// The pieces of the plot library that need no image: band clipping, round levels, number labels,
// field catalogue and nodal averaging, on small hand-made result documents.
#include <gtest/gtest.h>

#include <cairo.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <sstream>
#include <utility>
#include <nlohmann/json.hpp>

#include "plot/draw/band_levels.hpp"
#include "plot/draw/band_raster.hpp"
#include "plot/draw/chart.hpp"
#include "plot/draw/color_map.hpp"
#include "plot/draw/contour_bands.hpp"
#include "plot/draw/nice_scale.hpp"
#include "plot/draw/number_format.hpp"
#include "plot/pictures/contour_plot.hpp"
#include "plot/pictures/plot_request.hpp"
#include "plot/result/field.hpp"
#include "plot/result/point_locator.hpp"
#include "plot/result/result_mesh.hpp"

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

TEST(Field, HeatFluxIsTheMagnitudeOfEachElementsFluxAveragedToTheNodes) {
  json result = two_squares();
  EXPECT_THROW(
      {
        try {
          (void)nodal_values(result, ResultMesh::from_result(result), find_field("heat_flux"));
        } catch (const std::invalid_argument& e) {
          EXPECT_NE(std::string(e.what()).find("thermal"), std::string::npos) << e.what();
          throw;
        }
      },
      std::invalid_argument);
  result["elements"][0]["q_r"] = 3.0;
  result["elements"][0]["q_z"] = -4.0;  // |q| = 5
  result["elements"][1]["q_r"] = 0.0;
  result["elements"][1]["q_z"] = 2.0;   // |q| = 2
  const ResultMesh mesh = ResultMesh::from_result(result);
  const std::vector<double> v = nodal_values(result, mesh, find_field("heat_flux"));
  EXPECT_DOUBLE_EQ(v[0], 5.0);
  EXPECT_DOUBLE_EQ(v[1], (1.0 * 5.0 + 2.0 * 2.0) / 3.0);  // areas 1 and 2
  EXPECT_DOUBLE_EQ(v[2], 2.0);
  EXPECT_EQ(element_keys(find_field("heat_flux")), (std::vector<std::string_view>{"q_r", "q_z"}));
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
  json document = two_squares();
  for (json& e : document["elements"]) {  // as a thermal run stores them, for heat_flux
    e["q_r"] = 1.5 * e["id"].get<double>();
    e["q_z"] = -2.0;
    e["error"] = 0.1 * e["id"].get<double>();  // as every solved result stores it, for error
  }
  for (const std::string& name : plot_names()) {
    request.name = name;
    // two_squares has no history (see the next test), no contact pairs (see FrictionPlot) and no
    // named sets (the force plot's tests: tests/cli/solve_command_test.cpp, the press fit).
    // Nor adaptive cycles (AdaptationPlot, below).
    if (name == "convergence" || name == "friction" || name == "force" || name == "adaptation") continue;
    for (const ImageFormat format : {ImageFormat::png, ImageFormat::svg}) {
      request.format = format;
      const std::string image = render_plot(document, request);
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

TEST(PointLocator, FindsTheElementAndWhereInIt) {
  const ResultMesh mesh = ResultMesh::from_result(two_squares());
  const PointLocator locator(mesh);
  const std::optional<Location> in_second = locator.locate(2.0, 0.25);
  ASSERT_TRUE(in_second);
  EXPECT_EQ(mesh.solids[in_second->element].id, 2);
  // Element 2 spans r 1 .. 3, z 0 .. 1: reference (0, -0.5).
  EXPECT_NEAR(in_second->at.xi, 0.0, 1e-12);
  EXPECT_NEAR(in_second->at.eta, -0.5, 1e-12);
  EXPECT_EQ(mesh.solids[locator.locate(0.5, 0.5)->element].id, 1);
  EXPECT_TRUE(locator.locate(3.0, 1.0)) << "a corner belongs to its element";
  EXPECT_EQ(locator.locate_all(1.0, 0.5).size(), 2U) << "a point on the shared edge is in both";
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

namespace saasgaps::plot {
namespace {

/// two_squares with one stress and strain state in both elements (centroids (0.5, 0.5) and
/// (2, 0.5)): sigma_x 100, sigma_y -40, tau_xy 30; eps_x 1e-3, eps_y -2e-4, gamma_xy 6e-4.
json uniform_state() {
  json result = two_squares();
  for (json& e : result["elements"]) {
    e["sigma_r"] = 100.0;
    e["sigma_z"] = -40.0;
    e["tau_rz"] = 30.0;
    e["sigma_theta"] = 18.0;
    e["eps_r"] = 1e-3;
    e["eps_z"] = -2e-4;
    e["gamma_rz"] = 6e-4;
  }
  return result;
}

TEST(CylindricalComponents, RotateTheInPlaneTensorAboutTheCentre) {
  const json result = uniform_state();
  const ResultMesh mesh = ResultMesh::from_result(result);
  const auto at = [&](const char* name, PlanePoint centre) {
    return element_values(result, mesh, find_field(name), centre);
  };
  // About the origin element 1 lies at 45 degrees: sigma_rad = (sx + sy)/2 + txy, sigma_hoop =
  // (sx + sy)/2 - txy, tau = (sy - sx)/2.
  EXPECT_NEAR(at("sigma_radial", {0.0, 0.0})[0], 60.0, 1e-12);
  EXPECT_NEAR(at("sigma_hoop", {0.0, 0.0})[0], 0.0, 1e-12);
  EXPECT_NEAR(at("tau_radial_hoop", {0.0, 0.0})[0], -70.0, 1e-12);
  // About (0.5, -1) element 1 lies straight up (90 degrees): radial = y, hoop = x, shear = -xy.
  EXPECT_NEAR(at("sigma_radial", {0.5, -1.0})[0], -40.0, 1e-12);
  EXPECT_NEAR(at("sigma_hoop", {0.5, -1.0})[0], 100.0, 1e-12);
  EXPECT_NEAR(at("tau_radial_hoop", {0.5, -1.0})[0], -30.0, 1e-12);
  // About (0.5, 0.5) element 2 lies along +x: the components as stored.
  EXPECT_NEAR(at("sigma_radial", {0.5, 0.5})[1], 100.0, 1e-12);
  EXPECT_NEAR(at("sigma_hoop", {0.5, 0.5})[1], -40.0, 1e-12);
  EXPECT_NEAR(at("tau_radial_hoop", {0.5, 0.5})[1], 30.0, 1e-12);
  // Element 2 about the origin (an angle no special case hits): the invariants of a rotation.
  const double r = at("sigma_radial", {0.0, 0.0})[1], h = at("sigma_hoop", {0.0, 0.0})[1];
  const double t = at("tau_radial_hoop", {0.0, 0.0})[1];
  EXPECT_NEAR(r + h, 60.0, 1e-12);
  EXPECT_NEAR(r * h - t * t, 100.0 * -40.0 - 30.0 * 30.0, 1e-9);
  EXPECT_GT(std::abs(r - 100.0), 1.0) << "rotated, not the stored sigma_r";
  // Strains rotate as a tensor with half the engineering shear, which comes back doubled.
  EXPECT_NEAR(at("eps_radial", {0.0, 0.0})[0], (1e-3 - 2e-4) / 2.0 + 3e-4, 1e-15);
  EXPECT_NEAR(at("eps_hoop", {0.0, 0.0})[0], (1e-3 - 2e-4) / 2.0 - 3e-4, 1e-15);
  EXPECT_NEAR(at("gamma_radial_hoop", {0.0, 0.0})[0], -2e-4 - 1e-3, 1e-15);
  EXPECT_NEAR(at("gamma_radial_hoop", {0.5, -1.0})[0], -6e-4, 1e-15);
  // The nodes get the area-weighted mean of the rotated element values.
  const std::vector<double> nodal = nodal_values(result, mesh, find_field("sigma_hoop"), {0.5, -1.0});
  EXPECT_NEAR(nodal[0], 100.0, 1e-12);
}

TEST(CylindricalComponents, NamesSayWhatTheyAreAndPlotsReadTheirInputs) {
  const json plane = uniform_state();
  const ResultMesh mesh = ResultMesh::from_result(plane);
  EXPECT_EQ(field_title(find_field("sigma_theta"), mesh), "sigma_theta (\u03c3z, out of plane)");
  EXPECT_NE(field_label(find_field("sigma_theta"), mesh).find("Out-of-plane"), std::string::npos);
  EXPECT_EQ(field_label(find_field("sigma_theta"), mesh).find("Hoop"), std::string::npos);
  EXPECT_EQ(field_title(find_field("sigma_hoop"), mesh), "sigma_hoop");
  EXPECT_NE(field_label(find_field("sigma_hoop"), mesh, {1.5, -2.0}).find("Hoop stress"), std::string::npos);
  EXPECT_NE(field_label(find_field("sigma_hoop"), mesh, {1.5, -2.0}).find("(1.5, -2)"), std::string::npos);

  json axisymmetric = plane;
  axisymmetric["analysis"] = "axisymmetric";
  const ResultMesh ring = ResultMesh::from_result(axisymmetric);
  EXPECT_EQ(field_title(find_field("sigma_theta"), ring), "sigma_theta");
  EXPECT_NE(field_label(find_field("sigma_theta"), ring).find("Hoop"), std::string::npos);
  try {
    element_values(axisymmetric, ring, find_field("sigma_hoop"));
    FAIL() << "no exception";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("sigma_theta"), std::string::npos) << e.what();
  }
  PlotRequest request;
  request.name = "sigma_hoop";
  EXPECT_THROW(render_plot(axisymmetric, request), std::invalid_argument);

  // A cylindrical component reads the three stored components, and no other stress.
  const io::ResultSelection selection = result_selection_for(request);
  EXPECT_TRUE(selection.mesh);
  EXPECT_EQ(selection.element_keys, (std::vector<std::string>{"sigma_r", "sigma_z", "tau_rz"}));

  PlanePoint centre{};
  set_centre("1.5,-2", centre);
  EXPECT_EQ(centre, (PlanePoint{1.5, -2.0}));
  set_centre("", centre);
  EXPECT_EQ(centre, (PlanePoint{1.5, -2.0})) << "empty: left as it was";
  for (const char* bad : {"1", "1,", "a,2", "1,2,3", "1;2"}) EXPECT_THROW(set_centre(bad, centre), std::invalid_argument) << bad;
}

TEST(ColorMaps, SignedFieldsGetADivergingMapCentredOnZeroByDefault) {
  const std::string chosen = ContourOptions{}.color_map;
  EXPECT_EQ(ColorMap::for_range(chosen, -91529.0, 6556.0), "diverging");
  EXPECT_EQ(ColorMap::for_range(chosen, 0.0, 7754.0), "viridis") << "non-negative: sequential";
  EXPECT_EQ(ColorMap::for_range(chosen, -5.0, -1.0), "viridis") << "one sign: sequential";
  EXPECT_EQ(ColorMap::for_range("cividis", -1.0, 1.0), "cividis") << "--colormap overrides";
  EXPECT_NO_THROW(ColorMap::require_name("auto"));
  EXPECT_THROW(ColorMap::require_name("jet"), std::invalid_argument);

  // Bands of equal magnitude either side of zero: the same lightness, blue below and red above;
  // a band around zero is the near-white centre.
  const ColorMap diverging = ColorMap::named("diverging");
  ASSERT_TRUE(diverging.centred_on_zero());
  const std::vector<Rgb> c = diverging.band_colors({-30.0, -10.0, 10.0, 30.0});
  ASSERT_EQ(c.size(), 3U);
  EXPECT_GT(c[0].b, c[0].r);
  EXPECT_GT(c[2].r, c[2].b);
  EXPECT_NEAR(c[0].r + c[0].g + c[0].b, c[2].r + c[2].g + c[2].b, 0.35);
  EXPECT_GT(std::min({c[1].r, c[1].g, c[1].b}), 0.95);
  // One-sided levels stay on their side of the centre: a compressive field is all blue.
  for (const Rgb& band : diverging.band_colors({-90000.0, -60000.0, -30000.0, 0.0})) EXPECT_GT(band.b, band.r);
  // A sequential map ignores the values.
  const ColorMap viridis = ColorMap::named("viridis");
  EXPECT_FALSE(viridis.centred_on_zero());
  EXPECT_EQ(viridis.band_colors({-1.0, 0.0, 1.0})[1].g, viridis.band(1, 2).g);
}

/// The smallest gap between neighbouring levels, as a share of the levels' span.
double closest_levels(const BandLevels& b) {
  double closest = 1.0;
  for (std::size_t k = 1; k < b.levels.size(); ++k) {
    closest = std::min(closest, (b.levels[k] - b.levels[k - 1]) / (b.levels.back() - b.levels.front()));
  }
  return closest;
}

TEST(BandLevels, NoBandsAreSpentOnRoundOff) {
  // Half the area spread over -91530 .. -40000, half at 6552.8 .. 6555.8 (constant up to
  // discretisation noise): quantile bands used to give the 3 of noise most of the bands.
  // (plot_render_test checks the shrink-fit rings themselves.)
  std::vector<double> values, weights;
  for (int i = 0; i < 200; ++i) {
    values.push_back(-91530.0 + 51530.0 * i / 199.0);
    values.push_back(6552.8 + 3.0 * i / 199.0);
    weights.insert(weights.end(), {1.0, 1.0});
  }
  EXPECT_EQ(ContourOptions{}.levels, LevelRule::even) << "nice round levels over the range by default";
  for (const LevelRule rule : {LevelRule::even, LevelRule::quantile}) {
    const BandLevels b = band_levels(values, weights, 12, rule);
    // Not one band narrower than 1 % of the range (the noise band would be 3e-5 of it).
    EXPECT_GE(closest_levels(b), 0.01) << "rule " << static_cast<int>(rule);
    EXPECT_LE(b.levels.front(), -91530.0);
    EXPECT_GE(b.levels.back(), 6555.8);
  }
  const BandLevels even = band_levels(values, weights, 12, LevelRule::even);
  EXPECT_NE(std::find(even.levels.begin(), even.levels.end(), 0.0), even.levels.end())
      << "a level at zero, where the diverging map turns";
}

/// Two rows of gaps far apart, neither sharing nodes with the other: gaps 1-3 under a strip at z = 0
/// (neighbours share nodes) and gaps 4-5 at z = 4 (each on its own node pairs, abutting).
json two_gap_rows() {
  json nodes = json::array();
  const auto node = [&nodes](int id, double r, double z) {
    nodes.push_back({{"id", id}, {"r", r}, {"z", z}, {"u_r", 0.0}, {"u_z", 0.0}});
  };
  for (int i = 0; i <= 3; ++i) {
    node(1 + i, i, 0.0);
    node(11 + i, i, -0.01);
  }
  for (int i = 0; i < 2; ++i) {  // gap 4 + i on nodes 21 + 4i .. 24 + 4i
    node(21 + 4 * i, i, 4.0);
    node(22 + 4 * i, i + 1.0, 4.0);
    node(23 + 4 * i, i + 1.0, 4.01);
    node(24 + 4 * i, i, 4.01);
  }
  const auto gap = [](int id, std::vector<int> n, double pressure) {
    return json{{"id", id}, {"nodes", n}, {"angle", 90.0}, {"eps_m", -1.0}, {"closure", 100.0}, {"modulus", 1.0},
                {"sigma_m", -pressure}, {"contact_pressure", pressure}, {"state", "closed"}, {"converged", true}};
  };
  json gaps = json::array();
  for (int i = 0; i < 3; ++i) gaps.push_back(gap(1 + i, {11 + i, 12 + i, 2 + i, 1 + i}, 100.0 + 20.0 * i));
  for (int i = 0; i < 2; ++i) gaps.push_back(gap(4 + i, {21 + 4 * i, 22 + 4 * i, 23 + 4 * i, 24 + 4 * i}, 30.0 - 10.0 * i));
  return {{"status", "converged"}, {"iterations", 1}, {"title", "two rows"}, {"analysis", "plane_strain"},
          {"history", json::array()}, {"nodes", nodes}, {"elements", json::array()}, {"gaps", gaps}};
}

TEST(GapRow, ARowFallsIntoItsConnectedParts) {
  const json result = two_gap_rows();
  const ResultMesh mesh = ResultMesh::from_result(result);
  EXPECT_TRUE(gaps_connected(mesh, mesh.gaps[0], mesh.gaps[1])) << "shared nodes";
  EXPECT_TRUE(gaps_connected(mesh, mesh.gaps[3], mesh.gaps[4])) << "abutting, on their own nodes";
  EXPECT_FALSE(gaps_connected(mesh, mesh.gaps[2], mesh.gaps[3])) << "z = 0 and z = 4";
  EXPECT_FALSE(gaps_connected(mesh, mesh.gaps[0], mesh.gaps[2])) << "not neighbours";
  const GapRow all = select_gap_row(mesh, {{}, RowAxis::position});
  EXPECT_EQ(all.part, (std::vector<int>{0, 0, 0, 1, 1}));
  EXPECT_EQ(all.parts(), 2);
  Series s;
  all.set_points(s, {1, 2, 3, 4, 5});
  ASSERT_EQ(s.y.size(), 6U);
  EXPECT_TRUE(std::isnan(s.y[3])) << "the line breaks between the parts";
  EXPECT_EQ(select_gap_row(mesh, {{5, 4}, RowAxis::index}).parts(), 1);
  EXPECT_EQ(select_gap_row(mesh, {{1, 4, 2}, RowAxis::index}).parts(), 3) << "each jump is a break";

  PlotRequest request;
  request.name = "contact_pressure";
  const std::string csv = render_table(result, request);
  EXPECT_NE(csv.find("gap,x,row_part,contact_pressure"), std::string::npos) << csv;
  EXPECT_NE(csv.find("\n3,3,1,140,"), std::string::npos) << csv;
  EXPECT_NE(csv.find("\n4,4,2,30,"), std::string::npos) << csv;
  request.name = "closure";
  EXPECT_NE(render_table(result, request).find("\n5,5,2,100,"), std::string::npos);
}

/// A PNG decoded into a cairo image surface (the caller destroys it).
cairo_surface_t* png_surface(const std::string& png) {
  struct Reader {
    const std::string* data;
    std::size_t at = 0;
  } reader{&png};
  return cairo_image_surface_create_from_png_stream(
      [](void* closure, unsigned char* out, unsigned int length) {
        auto* r = static_cast<Reader*>(closure);
        if (r->at + length > r->data->size()) return CAIRO_STATUS_READ_ERROR;
        std::copy_n(r->data->data() + r->at, length, out);
        r->at += length;
        return CAIRO_STATUS_SUCCESS;
      },
      &reader);
}

/// The colour of pixel (x, y) of a PNG, 0 .. 255 each.
std::array<int, 3> pixel(const std::string& png, double x, double y) {
  cairo_surface_t* image = png_surface(png);
  const unsigned char* data = cairo_image_surface_get_data(image);
  const int stride = cairo_image_surface_get_stride(image);
  const auto value = *reinterpret_cast<const std::uint32_t*>(data + static_cast<std::ptrdiff_t>(std::lround(y)) * stride +
                                                             4 * std::lround(x));
  cairo_surface_destroy(image);
  return {static_cast<int>((value >> 16) & 0xFF), static_cast<int>((value >> 8) & 0xFF), static_cast<int>(value & 0xFF)};
}

/// A PNG's lines break between two curves and join the points of one: midway from `end` (the first
/// curve's last marker, px) to `start` (the second's first) is background, midway between `a` and `b`
/// (neighbours on the first curve, drawn in red) is the line.
void expect_break_between(const std::string& png, std::pair<double, double> end, std::pair<double, double> start,
                          std::pair<double, double> a, std::pair<double, double> b) {
  const std::array<int, 3> across = pixel(png, (end.first + start.first) / 2.0, (end.second + start.second) / 2.0);
  EXPECT_GT(std::min({across[0], across[1], across[2]}), 200) << "background, not a line: " << across[0] << ","
                                                              << across[1] << "," << across[2];
  const std::array<int, 3> within = pixel(png, (a.first + b.first) / 2.0, (a.second + b.second) / 2.0);
  EXPECT_GT(within[0], within[2] + 80) << "the first curve's line, in red";
}

TEST(GapRow, NoLineJoinsTwoSeparateRows) {
  // Between gap 3 (end of the first row, 140) and gap 4 (start of the second, 30) nothing is drawn;
  // within a row, the line between neighbours is.
  PlotRequest request;
  request.name = "contact_pressure";
  request.width = 800;
  request.height = 600;
  const std::string png = render_plot(two_gap_rows(), request);
  const std::string csv = render_table(two_gap_rows(), request);
  std::map<int, std::pair<double, double>> at;  // gap -> (px, py_pressure)
  std::istringstream lines(csv);
  for (std::string line; std::getline(lines, line);) {
    if (line.empty() || line[0] == '#' || line.rfind("gap,", 0) == 0) continue;
    std::vector<std::string> cells;
    std::istringstream fields(line);
    for (std::string cell; std::getline(fields, cell, ',');) cells.push_back(cell);
    at[std::stoi(cells[0])] = {std::stod(cells[7]), std::stod(cells[8])};
  }
  ASSERT_EQ(at.size(), 5U) << csv;
  expect_break_between(png, at[3], at[4], at[1], at[2]);
}

/// Contact surfaces only (no gap elements): two pairs, the first along z = 0 from r = 0 to 3, the
/// second along z = 4 from r = 5 to 7, open at its last point.
json two_contact_pairs() {
  const auto point = [](double r, double z, double gap, double pressure) {
    return json{{"r", r}, {"z", z}, {"gap", gap}, {"pressure", pressure}, {"shear", 0.0},
                {"state", pressure > 0.0 ? "stick" : "open"}, {"slip", 0.0}};
  };
  json first = json::array(), second = json::array();
  for (int i = 0; i <= 3; ++i) first.push_back(point(i, 0.0, 0.0, 100.0 + 20.0 * i));
  second.push_back(point(5.0, 4.0, 0.0, 30.0));
  second.push_back(point(6.0, 4.0, 0.0, 20.0));
  second.push_back(point(7.0, 4.0, 0.002, 0.0));
  json nodes = json::array();
  nodes.push_back({{"id", 1}, {"r", 0.0}, {"z", 0.0}, {"u_r", 0.0}, {"u_z", 0.0}});
  return {{"status", "converged"}, {"iterations", 1}, {"title", "two pairs"}, {"analysis", "plane_strain"},
          {"units", {{"length", "mm"}, {"stress", "MPa"}}},
          {"history", json::array()}, {"nodes", nodes}, {"elements", json::array()}, {"gaps", json::array()},
          {"contact", {{{"surfaces", {"shaft", "hub"}}, {"points", first}},
                       {{"surfaces", {"cap", "rim"}}, {"points", second}}}}};
}

/// The data rows of a plot's CSV, split into cells.
std::vector<std::vector<std::string>> csv_rows(const std::string& csv) {
  std::vector<std::vector<std::string>> rows;
  std::istringstream lines(csv);
  bool header = true;
  for (std::string line; std::getline(lines, line);) {
    if (line.empty() || line[0] == '#') continue;
    if (std::exchange(header, false)) continue;
    std::vector<std::string> cells;
    std::istringstream fields(line);
    for (std::string cell; std::getline(fields, cell, ',');) cells.push_back(cell);
    rows.push_back(std::move(cells));
  }
  return rows;
}

TEST(SurfaceContactPlot, OneCurvePerPairAlongSideA) {
  PlotRequest request;
  request.name = "contact_pressure";
  request.width = 800;
  request.height = 600;
  request.row.along = RowAxis::r;
  const std::string csv = render_table(two_contact_pairs(), request);
  EXPECT_NE(csv.find("pair,point,x,r,z,pressure,gap,state,px,py_pressure,py_gap"), std::string::npos) << csv;
  EXPECT_NE(csv.find("pairs (surfaces A / B): 1 = shaft / hub; 2 = cap / rim;"), std::string::npos) << csv;
  EXPECT_NE(csv.find("x: r [mm]"), std::string::npos) << csv;
  const auto rows = csv_rows(csv);
  ASSERT_EQ(rows.size(), 7U) << csv;
  EXPECT_EQ(rows[3][0] + "," + rows[3][1] + "," + rows[3][2] + "," + rows[3][5] + "," + rows[3][7], "1,4,3,160,stick");
  EXPECT_EQ(rows[6][0] + "," + rows[6][1] + "," + rows[6][2] + "," + rows[6][5] + "," + rows[6][6] + "," + rows[6][7],
            "2,3,7,0,0.002,open");

  // Between the first pair's last point and the second pair's first nothing is drawn; within a
  // pair, the line between neighbours is (in the first pair's colour, red).
  const std::string png = render_plot(two_contact_pairs(), request);
  const auto at = [&rows](std::size_t row) { return std::pair{std::stod(rows[row][8]), std::stod(rows[row][9])}; };
  expect_break_between(png, at(3), at(4), at(0), at(1));

  // Arc length along A restarts at each pair; the index numbers the points.
  request.row.along = RowAxis::position;
  const auto along = csv_rows(render_table(two_contact_pairs(), request));
  EXPECT_EQ(along[4][2], "0");
  EXPECT_EQ(along[6][2], "2");
  request.row.along = RowAxis::index;
  EXPECT_EQ(csv_rows(render_table(two_contact_pairs(), request))[6][2], "3");
}

TEST(SurfaceContactPlot, ClosureAndContactPlotsOfSurfacesOnlyAreDrawnNotRefused) {
  PlotRequest request;
  request.width = 400;
  request.height = 300;
  for (const char* name : {"contact_pressure", "closure"}) {
    request.name = name;
    for (const ImageFormat format : {ImageFormat::png, ImageFormat::svg}) {
      request.format = format;
      EXPECT_GT(render_plot(two_contact_pairs(), request).size(), 1000U) << name;
    }
    request.format = ImageFormat::png;
    EXPECT_EQ(csv_rows(render_table(two_contact_pairs(), request)).size(), 7U) << name;
  }
  // Neither gaps nor contact points: still a clear refusal.
  json none = two_contact_pairs();
  none["contact"] = json::array();
  request.name = "contact_pressure";
  EXPECT_THROW(render_plot(none, request), std::invalid_argument);
  // A gap row asked for by ids draws the gaps, even where there are contact pairs.
  json both = two_gap_rows();
  both["contact"] = two_contact_pairs()["contact"];
  request.row.gap_ids = {1, 2, 3};
  EXPECT_NE(render_table(both, request).find("gap,x,row_part,contact_pressure"), std::string::npos);
  request.row.gap_ids.clear();
  EXPECT_NE(render_table(both, request).find("pair,point,x"), std::string::npos);
}

/// Contact pairs with friction, hand-made: pair 1 (block / base, mu 0.25) along z = 1 from r = 0 to
/// 4: two points stick (shear inside 0.25 p), two slip (shear on +0.25 p and on -0.25 p), the last
/// is open; pair 2 (cap / rim) is frictionless; pair 3 (pin / hole, mu 0.5) sticks then slips.
json friction_pairs() {
  const auto point = [](double r, double z, double pressure, double shear, const char* state, double slip) {
    return json{{"r", r}, {"z", z}, {"gap", 0.0}, {"pressure", pressure}, {"shear", shear}, {"state", state},
                {"slip", slip}};
  };
  json block = json::array(), cap = json::array(), pin = json::array();
  block.push_back(point(0.0, 1.0, 100.0, 10.0, "stick", 0.0));
  block.push_back(point(1.0, 1.0, 100.0, 20.0, "stick", 0.0));
  block.push_back(point(2.0, 1.0, 80.0, 20.0, "slip", 0.125));
  block.push_back(point(3.0, 1.0, 50.0, -12.5, "slip", -0.25));
  block.push_back(point(4.0, 1.0, 0.0, 0.0, "open", 0.0));
  cap.push_back(point(5.0, 4.0, 30.0, 0.0, "stick", 0.0));
  cap.push_back(point(6.0, 4.0, 20.0, 0.0, "stick", 0.0));
  pin.push_back(point(6.0, 0.0, 40.0, 5.0, "stick", 0.0));
  pin.push_back(point(6.0, 1.0, 20.0, 10.0, "slip", 0.5));
  json document = two_contact_pairs();
  document["title"] = "friction pairs";
  document["contact"] = {{{"friction", 0.25}, {"surfaces", {"block", "base"}}, {"points", block}},
                         {{"surfaces", {"cap", "rim"}}, {"points", cap}},
                         {{"friction", 0.5}, {"surfaces", {"pin", "hole"}}, {"points", pin}}};
  return document;
}

/// The value -> px map of a plot's y axis, from its "# ticks NAME:" note.
double y_px(const std::string& csv, const std::string& panel, double value) {
  const std::string key = "# ticks " + panel + ":";
  const std::size_t at = csv.find(key);
  EXPECT_NE(at, std::string::npos) << csv;
  std::istringstream ticks(csv.substr(at + key.size(), csv.find('\n', at) - at - key.size()));
  std::vector<std::pair<double, double>> marks;
  for (std::string mark; ticks >> mark;) {
    const std::size_t sep = mark.find('@');
    marks.emplace_back(std::stod(mark.substr(0, sep)), std::stod(mark.substr(sep + 1)));
  }
  EXPECT_GE(marks.size(), 2U) << csv;
  const auto [v0, p0] = marks.front();
  const auto [v1, p1] = marks.back();
  return p0 + (value - v0) * (p1 - p0) / (v1 - v0);
}

TEST(FrictionPlot, ShearAndTheCoulombBoundOfEachPairWithFriction) {
  PlotRequest request;
  request.name = "friction";
  request.width = 800;
  request.height = 600;
  const std::string csv = render_table(friction_pairs(), request);
  EXPECT_NE(csv.find("pair,point,x,r,z,pressure,shear,mu,mu_pressure,slip,state,px,py_shear,py_bound"), std::string::npos)
      << csv;
  EXPECT_NE(csv.find("pairs (surfaces A / B, mu): 1 = block / base, mu 0.25; 2 = cap / rim, mu 0; 3 = pin / hole, mu 0.5;"),
            std::string::npos) << csv;
  EXPECT_NE(csv.find("x: arc length along side A [mm]"), std::string::npos) << csv;
  EXPECT_NE(csv.find("shear, mu_pressure = mu x pressure in MPa"), std::string::npos) << csv;
  // The zones reach halfway to the neighbouring points; the open point has none.
  EXPECT_NE(csv.find("# zones pair 1: stick 0..1.5 slip 1.5..3.5\n"), std::string::npos) << csv;
  EXPECT_NE(csv.find("# zones pair 3: stick 0..0.5 slip 0.5..1\n"), std::string::npos) << csv;
  EXPECT_EQ(csv.find("zones pair 2"), std::string::npos) << csv;

  // The frictionless pair is not drawn: 5 + 2 points.
  const auto rows = csv_rows(csv);
  ASSERT_EQ(rows.size(), 7U) << csv;
  const auto first = [&rows](std::size_t row) {
    std::string text;
    for (std::size_t c = 0; c < 11; ++c) text += (c ? "," : "") + rows[row][c];
    return text;
  };
  EXPECT_EQ(first(0), "1,1,0,0,1,100,10,0.25,25,0,stick");
  EXPECT_EQ(first(2), "1,3,2,2,1,80,20,0.25,20,0.125,slip");
  EXPECT_EQ(first(3), "1,4,3,3,1,50,-12.5,0.25,12.5,-0.25,slip");
  EXPECT_EQ(first(4), "1,5,4,4,1,0,0,0.25,0,0,open");
  EXPECT_EQ(first(6), "3,2,1,6,1,20,10,0.5,10,0.5,slip");
  // A point slipping in the positive sense lies on the bound: its marker is where the bound's is.
  EXPECT_EQ(rows[2][12], rows[2][13]);
  EXPECT_NE(rows[0][12], rows[0][13]);  // a sticking point lies inside
  // The y axis maps the shear: py_shear is the tick line's px for the shear's value.
  EXPECT_NEAR(std::stod(rows[0][12]), y_px(csv, "shear", 10.0), 1e-6);

  for (const ImageFormat format : {ImageFormat::png, ImageFormat::svg}) {
    request.format = format;
    EXPECT_GT(render_plot(friction_pairs(), request).size(), 1000U);
  }
}

TEST(FrictionPlot, StickAndSlipZonesAreShadedAndPointsMarkedByState) {
  // Pair 1 alone, so that no other pair's zones overlap it.
  json document = friction_pairs();
  document["contact"] = json::array({document["contact"][0]});
  PlotRequest request;
  request.name = "friction";
  request.width = 800;
  request.height = 600;
  const std::string csv = render_table(document, request);
  const std::string png = render_plot(document, request);
  const auto rows = csv_rows(csv);
  ASSERT_EQ(rows.size(), 5U) << csv;
  const auto px = [&rows](std::size_t row) { return std::stod(rows[row][11]); };
  // At shear -8 no curve passes over x = 0.5, 1.75 or 3.75 (the bounds are further out, the
  // shear positive or near 0 there).
  const double y = y_px(csv, "shear", -8.0);
  const std::array<int, 3> stick = pixel(png, 0.5 * (px(0) + px(1)), y);
  EXPECT_GT(stick[2], stick[0] + 20) << "stick zone, tinted blue: " << stick[0] << "," << stick[1] << "," << stick[2];
  const std::array<int, 3> slip = pixel(png, px(1) + 0.75 * (px(2) - px(1)), y);
  EXPECT_GT(slip[0], slip[2] + 40) << "slip zone, tinted orange: " << slip[0] << "," << slip[1] << "," << slip[2];
  const std::array<int, 3> open = pixel(png, px(3) + 0.75 * (px(4) - px(3)), y);
  EXPECT_GT(std::min({open[0], open[1], open[2]}), 245) << "open: no zone " << open[0] << "," << open[1] << "," << open[2];
  // A sticking point is a filled dot in the pair's colour (red); a slipping one an open ring.
  const std::array<int, 3> dot = pixel(png, px(0), std::stod(rows[0][12]));
  EXPECT_GT(dot[0], dot[2] + 80) << dot[0] << "," << dot[1] << "," << dot[2];
  const std::array<int, 3> ring = pixel(png, px(3), std::stod(rows[3][12]));
  EXPECT_GT(std::min({ring[0], ring[1], ring[2]}), 200) << ring[0] << "," << ring[1] << "," << ring[2];
}

TEST(FrictionPlot, FrictionlessResultsAreRefusedClearly) {
  PlotRequest request;
  request.name = "friction";
  request.width = 400;
  request.height = 300;
  // Contact pairs without friction (or friction 0), and no contact at all.
  json frictionless = two_contact_pairs();
  frictionless["contact"][0]["friction"] = 0.0;
  for (const json& document : {frictionless, two_squares()}) {
    try {
      render_plot(document, request);
      FAIL() << "no exception";
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find("no contact pair with friction > 0"), std::string::npos) << e.what();
    }
  }
  // A friction plot does not run along a path; its result selection reads no mesh.
  EXPECT_FALSE(result_selection_for(request).mesh);
  request.path = PathOptions{};
  EXPECT_THROW(render_plot(friction_pairs(), request), std::invalid_argument);
}

// ------------------------------------------------------------------------------ raster band fill
/// The pixels of an ARGB32 surface, row by row.
std::vector<std::uint32_t> pixels_of(cairo_surface_t* image) {
  cairo_surface_flush(image);
  const int w = cairo_image_surface_get_width(image), h = cairo_image_surface_get_height(image);
  const int stride = cairo_image_surface_get_stride(image);
  const unsigned char* data = cairo_image_surface_get_data(image);
  std::vector<std::uint32_t> out;
  for (int j = 0; j < h; ++j) {
    const auto* row = reinterpret_cast<const std::uint32_t*>(data + static_cast<std::ptrdiff_t>(j) * stride);
    out.insert(out.end(), row, row + w);
  }
  return out;
}

/// The decoded pixels of a PNG (opaque RGB24, 0x00RRGGBB) and its width.
std::pair<std::vector<std::uint32_t>, int> decode_png(const std::string& png) {
  cairo_surface_t* image = png_surface(png);
  std::vector<std::uint32_t> pixels = pixels_of(image);
  for (std::uint32_t& p : pixels) p &= 0xFFFFFFU;
  const int width = cairo_image_surface_get_width(image);
  cairo_surface_destroy(image);
  return {pixels, width};
}

TEST(BandRaster, EachPixelCentreInsideTakesTheBandOfItsInterpolatedValue) {
  const std::vector<double> levels{0.0, 1.0, 2.0, 3.0};
  const std::vector<Rgb> colors{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  const std::uint32_t red = 0xFFFF0000U, green = 0xFF00FF00U, blue = 0xFF0000FFU;
  EXPECT_EQ(band_of(levels, -5.0), 0);
  EXPECT_EQ(band_of(levels, 0.99), 0);
  EXPECT_EQ(band_of(levels, 1.0), 1) << "a value at a level is in the band above it, as the path fill paints it";
  EXPECT_EQ(band_of(levels, 2.5), 2);
  EXPECT_EQ(band_of(levels, 7.0), 2);
  const int w = 60, h = 40;
  BandRaster raster(w, h, levels, colors);
  const ValueTriangle t{{{3.2, 2.7, 0.0}, {57.1, 6.3, 3.0}, {12.4, 37.6, 1.5}}};
  raster.fill(t);
  const std::vector<std::uint32_t> px = pixels_of(raster.surface());
  // Barycentric coordinates of a point: all > 0 inside.
  const auto weights = [&t](double x, double y) {
    const double det = (t[1].x - t[0].x) * (t[2].y - t[0].y) - (t[2].x - t[0].x) * (t[1].y - t[0].y);
    const double l1 = ((x - t[0].x) * (t[2].y - t[0].y) - (t[2].x - t[0].x) * (y - t[0].y)) / det;
    const double l2 = ((t[1].x - t[0].x) * (y - t[0].y) - (x - t[0].x) * (t[1].y - t[0].y)) / det;
    return std::array<double, 3>{1.0 - l1 - l2, l1, l2};
  };
  int inside = 0, checked = 0;
  for (int j = 0; j < h; ++j) {
    for (int i = 0; i < w; ++i) {
      const std::array<double, 3> l = weights(i + 0.5, j + 0.5);
      const double smallest = std::min({l[0], l[1], l[2]});
      const std::uint32_t got = px[static_cast<std::size_t>(j * w + i)];
      if (smallest < -1e-9) {
        EXPECT_EQ(got, 0U) << "outside, transparent: pixel " << i << "," << j;
      } else if (smallest > 1e-9) {
        ++inside;
        const double v = l[0] * t[0].v + l[1] * t[1].v + l[2] * t[2].v;
        // Values within round-off of a level may fall either side.
        if (std::abs(v - 1.0) < 1e-9 || std::abs(v - 2.0) < 1e-9) continue;
        ++checked;
        const std::uint32_t want = v < 1.0 ? red : v < 2.0 ? green : blue;
        EXPECT_EQ(got, want) << "pixel " << i << "," << j << " v = " << v;
      }
    }
  }
  EXPECT_GT(checked, 800) << inside;
  EXPECT_GE(checked, inside - 5);
}

TEST(BandRaster, TrianglesSharingAnEdgeCoverEveryPixelOnce) {
  // A square of corners at fractional px split along each diagonal: every centre inside is painted,
  // none outside, whichever way the square is split.
  const std::vector<double> levels{0.0, 1.0};
  for (const bool other_diagonal : {false, true}) {
    BandRaster raster(32, 32, levels, {{0.2, 0.4, 0.6}});
    const ValuePoint a{3.3, 4.7, 0.5}, b{27.6, 4.7, 0.5}, c{27.6, 25.2, 0.5}, d{3.3, 25.2, 0.5};
    if (other_diagonal) {
      raster.fill({a, b, d});
      raster.fill({b, c, d});
    } else {
      raster.fill({a, b, c});
      raster.fill({a, c, d});
    }
    const std::vector<std::uint32_t> px = pixels_of(raster.surface());
    for (int j = 0; j < 32; ++j) {
      for (int i = 0; i < 32; ++i) {
        const bool in = i + 0.5 > 3.3 && i + 0.5 < 27.6 && j + 0.5 > 4.7 && j + 0.5 < 25.2;
        EXPECT_EQ(px[static_cast<std::size_t>(j * 32 + i)] != 0U, in) << i << "," << j << " " << other_diagonal;
      }
    }
  }
}

TEST(BandRaster, IsoSegmentsEndWhereTheClipCutsTheEdges) {
  const ValueTriangle t{{{0.0, 0.0, 0.0}, {4.0, 0.0, 4.0}, {0.0, 4.0, 2.0}}};
  const auto s = iso_segment(t, 1.0);
  ASSERT_TRUE(s.has_value());
  // v = x + y / 2: v = 1 crosses edge 0-1 at (1, 0) and edge 2-0 at (0, 2).
  const auto near = [](Point p, double x, double y) { return std::hypot(p.x - x, p.y - y) < 1e-12; };
  EXPECT_TRUE((near((*s)[0], 1.0, 0.0) && near((*s)[1], 0.0, 2.0)) || (near((*s)[1], 1.0, 0.0) && near((*s)[0], 0.0, 2.0)));
  EXPECT_FALSE(iso_segment(t, 5.0).has_value());
  EXPECT_FALSE(iso_segment(t, -1.0).has_value());
}

TEST(BandRaster, RasterAndPathContoursAgreeAwayFromTheBandEdges) {
  // The two fills of the same contour: the same colour wherever a pixel lies inside one band. They
  // differ only along band edges and the outline (antialiasing), where a pixel's neighbours in the
  // paths picture differ from it: how many those are depends on where the edges fall on the pixel
  // grid, so only pixels inside a band (their four neighbours of their colour) are compared.
  PlotRequest request;
  request.width = 500;
  request.height = 300;
  request.contour.fill = BandFill::paths;
  const auto [paths, width] = decode_png(render_plot(two_squares(), request));
  request.contour.fill = BandFill::raster;
  const auto [raster, raster_width] = decode_png(render_plot(two_squares(), request));
  ASSERT_EQ(width, raster_width);
  ASSERT_EQ(paths.size(), raster.size());
  std::size_t coloured = 0, differ = 0;
  for (std::size_t i = 0; i < paths.size(); ++i) {
    const std::uint32_t p = paths[i];
    const int r = static_cast<int>(p >> 16 & 0xFF), g = static_cast<int>(p >> 8 & 0xFF), b = static_cast<int>(p & 0xFF);
    // Band colours are saturated (viridis): not a grey of the text, axes or background.
    if (std::max({r, g, b}) - std::min({r, g, b}) < 40) continue;
    ++coloured;
    const std::size_t w = static_cast<std::size_t>(width);
    if (i < w || i + w >= paths.size() || paths[i - 1] != p || paths[i + 1] != p || paths[i - w] != p ||
        paths[i + w] != p) {
      continue;  // on a band edge
    }
    const std::uint32_t q = raster[i];
    const int dr = std::abs(r - static_cast<int>(q >> 16 & 0xFF)), dg = std::abs(g - static_cast<int>(q >> 8 & 0xFF)),
              db = std::abs(b - static_cast<int>(q & 0xFF));
    if (std::max({dr, dg, db}) > 2) ++differ;
  }
  EXPECT_GT(coloured, 20000U) << "the mesh covers a good part of the picture";
  EXPECT_LT(static_cast<double>(differ), 0.01 * static_cast<double>(coloured)) << differ << " of " << coloured;
}

/// A plane-stress grid of nx x ny unit squares with effective = x + y at each element, plus
/// `triangles` extra triangular elements along its bottom edge.
json grid_result(int nx, int ny, int triangles) {
  json nodes = json::array();
  const auto node_id = [nx](int i, int j) { return j * (nx + 1) + i + 1; };
  for (int j = 0; j <= ny; ++j) {
    for (int i = 0; i <= nx; ++i) {
      nodes.push_back({{"id", node_id(i, j)}, {"r", i}, {"z", j}, {"u_r", 0.0}, {"u_z", 0.0}});
    }
  }
  json elements = json::array();
  const auto element = [&elements](std::vector<int> n, double v) {
    elements.push_back({{"id", static_cast<int>(elements.size()) + 1}, {"nodes", std::move(n)}, {"material", 1},
                        {"effective", v}});
  };
  for (int j = 0; j < ny; ++j) {
    for (int i = 0; i < nx; ++i) element({node_id(i, j), node_id(i + 1, j), node_id(i + 1, j + 1), node_id(i, j + 1)}, i + j);
  }
  for (int t = 0; t < triangles; ++t) {
    nodes.push_back({{"id", 1000000 + t}, {"r", t + 0.5}, {"z", -1.0}, {"u_r", 0.0}, {"u_z", 0.0}});
    element({1000000 + t, node_id(t + 1, 0), node_id(t, 0)}, 0.0);
  }
  return {{"status", "converged"}, {"iterations", 1},   {"title", "grid"},      {"analysis", "plane_stress"},
          {"history", json::array()}, {"nodes", nodes}, {"elements", elements}, {"gaps", json::array()}};
}

TEST(BandRaster, MeshesAbovePathFillLimitAreRasterized) {
  // docs/plots.md: paths up to 20,000 solid elements, an image above (an SVG shows which).
  ASSERT_EQ(path_fill_limit, 20000U);
  PlotRequest request;
  request.format = ImageFormat::svg;
  request.width = 300;
  request.height = 200;
  const std::string at_limit = render_plot(grid_result(200, 100, 0), request);
  EXPECT_EQ(at_limit.find("<image"), std::string::npos) << "20,000 elements: paths";
  const std::string above = render_plot(grid_result(200, 100, 1), request);
  EXPECT_NE(above.find("<image"), std::string::npos) << "20,001 elements: an image";
  EXPECT_LT(above.size(), at_limit.size()) << "the image is smaller than 12 paths through 40,000 triangles";
}

/// The adaptive loop's convergence: error against unknowns on log-log axes (decade ticks labelled
/// with the values), a point per cycle, the target dashed; a document without cycles is refused.
TEST(AdaptationPlot, ErrorAgainstUnknownsLogLog) {
  const Axis a = log_axis(300.0, 40000.0, "unknowns");
  EXPECT_EQ(a.min, 2.0);
  EXPECT_EQ(a.max, 5.0);
  ASSERT_EQ(a.labels.size(), 4U);  // three decades and more: the decades only
  EXPECT_EQ(a.labels.front(), "100");
  EXPECT_EQ(a.labels.back(), "100000");
  const Axis fine = log_axis(0.01, 0.2, "error");
  EXPECT_NE(std::find(fine.labels.begin(), fine.labels.end(), "0.05"), fine.labels.end());

  json document = {{"title", "LE1"},
                   {"target_error", 0.01},
                   {"adaptation",
                    {{{"cycle", 1}, {"unknowns", 296}, {"relative_error", 0.1237}},
                     {{"cycle", 2}, {"unknowns", 4898}, {"relative_error", 0.02793}},
                     {{"cycle", 3}, {"unknowns", 20742}, {"relative_error", 0.011}}}}};
  PlotRequest request;
  request.name = "adaptation";
  request.format = ImageFormat::svg;
  const std::string svg = render_plot(document, request);
  EXPECT_NE(svg.find("<svg"), std::string::npos);
  EXPECT_GT(svg.size(), 1000U);
  const std::string csv = render_table(document, request);
  EXPECT_NE(csv.find("2,4898,0.02793"), std::string::npos) << csv;
  EXPECT_THROW(render_plot(json{{"title", "none"}}, request), std::invalid_argument);
}

}  // namespace
}  // namespace saasgaps::plot
