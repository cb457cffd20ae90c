// Plots of real results: report problem 3 case 1 (beam on a foundation, 18 gaps) and the shrink-fit
// rings (plane strain, 24 gaps between two bodies). The results come from the saasgaps binary, as a
// user makes them; the plot library draws them without the solver. Also the plot and export-vtu
// commands' files and errors.
#include <gtest/gtest.h>

#include <cairo.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>
#include <string>

#include "io/results/result_arrays.hpp"
#include "plot/pictures/plot_request.hpp"
#include "plot/result/field.hpp"
#include "support/lame_rings.hpp"

namespace saasgaps::plot {
namespace {

namespace fs = std::filesystem;

std::string read(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

struct Outcome {
  int exit_code = -1;
  std::string err;
};

/// Solves the two example models once for the whole suite.
class PlotRender : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = fs::temp_directory_path() / ("saasgaps-plot-" + std::to_string(::getpid()));
    fs::create_directories(dir_);
    for (const auto& [name, model] : {std::pair{"p3", "report-problem3-case1.json"},
                                      std::pair{"ring", "ring-shrink-fit-plane-strain.json"}}) {
      const Outcome r = run("solve " + std::string(SAASGAPS_EXAMPLES_DIR) + "/" + model + " -q -o " +
                            path(std::string(name) + ".json"));
      ASSERT_EQ(r.exit_code, 0) << r.err;
    }
    p3_ = nlohmann::json::parse(read(dir_ / "p3.json"));
    ring_ = nlohmann::json::parse(read(dir_ / "ring.json"));
  }
  static void TearDownTestSuite() { fs::remove_all(dir_); }

  static std::string path(const std::string& name) { return (dir_ / name).string(); }

  static Outcome run(const std::string& arguments) {
    const std::string err = path("stderr.txt");
    const std::string command = std::string(SAASGAPS_BINARY) + " " + arguments + " > " + path("stdout.txt") + " 2> " + err;
    const int status = std::system(command.c_str());
    return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, read(err)};
  }

  /// Decodes a PNG with cairo; expects the size and counts the distinct colours.
  static std::size_t png_colours(const std::string& png, int width, int height) {
    const fs::path file = dir_ / "decode.png";
    std::ofstream(file, std::ios::binary) << png;
    cairo_surface_t* image = cairo_image_surface_create_from_png(file.c_str());
    EXPECT_EQ(cairo_surface_status(image), CAIRO_STATUS_SUCCESS);
    EXPECT_EQ(cairo_image_surface_get_width(image), width);
    EXPECT_EQ(cairo_image_surface_get_height(image), height);
    std::set<std::uint32_t> colours;
    const unsigned char* data = cairo_image_surface_get_data(image);
    const int stride = cairo_image_surface_get_stride(image);
    for (int y = 0; data && y < height; ++y) {
      const auto* row = reinterpret_cast<const std::uint32_t*>(data + static_cast<std::ptrdiff_t>(y) * stride);
      for (int x = 0; x < width; ++x) colours.insert(row[x] & 0xFFFFFFU);
    }
    cairo_surface_destroy(image);
    return colours.size();
  }

  static std::size_t count(const std::string& text, const std::string& what) {
    std::size_t n = 0;
    for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
    return n;
  }

  static inline fs::path dir_;
  static inline nlohmann::json p3_, ring_;
};

PlotRequest request(const std::string& name, ImageFormat format, int width = 900, int height = 600) {
  PlotRequest r;
  r.name = name;
  r.format = format;
  r.width = width;
  r.height = height;
  return r;
}

TEST_F(PlotRender, ContourPngsDecodeAtTheirSizeWithManyColours) {
  PlotRequest effective = request("effective", ImageFormat::png, 1000, 600);
  effective.contour.deformation_scale = 50.0;
  effective.contour.mesh = true;
  EXPECT_GT(png_colours(render_plot(p3_, effective), 1000, 600), 30U);

  PlotRequest hoop = request("sigma_theta", ImageFormat::png, 700, 700);
  EXPECT_GT(png_colours(render_plot(ring_, hoop), 700, 700), 30U);

  PlotRequest temperature = request("temperature", ImageFormat::png);
  EXPECT_GT(png_colours(render_plot(ring_, temperature), 900, 600), 30U);

  PlotRequest displacement = request("displacement", ImageFormat::png, 800, 800);
  displacement.contour.automatic_deformation = true;
  EXPECT_GT(png_colours(render_plot(ring_, displacement), 800, 800), 30U);
}

/// Runs saasgaps with the arguments, expecting exit code 1 and the message in its stderr.
void expect_error(const Outcome& r, const std::string& message) {
  EXPECT_EQ(r.exit_code, 1) << r.err;
  EXPECT_NE(r.err.find(message), std::string::npos) << r.err;
}

/// Pixels of a decoded PNG that are clearly red (tension in the diverging map) and clearly blue.
std::pair<std::size_t, std::size_t> red_and_blue_pixels(const std::string& png, const fs::path& scratch) {
  std::ofstream(scratch, std::ios::binary) << png;
  cairo_surface_t* image = cairo_image_surface_create_from_png(scratch.c_str());
  std::size_t red = 0, blue = 0;
  const unsigned char* data = cairo_image_surface_get_data(image);
  const int stride = cairo_image_surface_get_stride(image);
  for (int y = 0; data && y < cairo_image_surface_get_height(image); ++y) {
    const auto* row = reinterpret_cast<const std::uint32_t*>(data + static_cast<std::ptrdiff_t>(y) * stride);
    for (int x = 0; x < cairo_image_surface_get_width(image); ++x) {
      const int r = (row[x] >> 16) & 0xFF, g = (row[x] >> 8) & 0xFF, b = row[x] & 0xFF;
      if (r > g + 60 && r > b + 60) ++red;
      if (b > r + 60 && b > g + 20) ++blue;
    }
  }
  cairo_surface_destroy(image);
  return {red, blue};
}

TEST_F(PlotRender, RingFitHoopStressAboutTheOriginIsLames) {
  // The shrink fit (plane strain, centred on the origin) against Lame's solution at the pressure
  // of the closure the run reached: sigma = A -/+ B / r^2 (radial, hoop) in each ring, at each
  // element's centroid radius (8 elements through each ring: the largest difference is 0.35 % of p).
  const ResultMesh mesh = ResultMesh::from_result(ring_);
  double closure = 0.0;
  for (const GapElement& g : mesh.gaps) closure += g.closure / 100.0;
  namespace lame = testing::lame_rings;
  const double p = lame::contact_pressure(closure / static_cast<double>(mesh.gaps.size()));
  ASSERT_GT(p, 10000.0);
  const std::vector<double> hoop = element_values(ring_, mesh, find_field("sigma_hoop"));
  const std::vector<double> radial = element_values(ring_, mesh, find_field("sigma_radial"));
  const std::vector<double> shear = element_values(ring_, mesh, find_field("tau_radial_hoop"));
  const std::vector<double> out_of_plane = element_values(ring_, mesh, find_field("sigma_theta"));
  for (std::size_t e = 0; e < mesh.solids.size(); ++e) {
    double x = 0.0, y = 0.0;
    for (const int n : mesh.solids[e].nodes) {
      x += mesh.nodes[n].r / 4.0;
      y += mesh.nodes[n].z / 4.0;
    }
    const double r = std::hypot(x, y);
    const bool inner = r < lame::b1;
    const double A = inner ? -p * lame::b1 * lame::b1 / (lame::b1 * lame::b1 - lame::a1 * lame::a1)
                           : p * lame::a2 * lame::a2 / (lame::b2 * lame::b2 - lame::a2 * lame::a2);
    const double B = A * (inner ? lame::a1 * lame::a1 : lame::b2 * lame::b2);
    SCOPED_TRACE("element " + std::to_string(mesh.solids[e].id) + " at r = " + std::to_string(r));
    EXPECT_NEAR(hoop[e], A + B / (r * r), 0.01 * p);
    EXPECT_NEAR(radial[e], A - B / (r * r), 0.01 * p);
    EXPECT_NEAR(shear[e], 0.0, 0.01 * p);
    // The hoop stress is not the stored sigma_theta, which here is the out-of-plane stress.
    EXPECT_GT(std::abs(hoop[e] - out_of_plane[e]), 0.1 * p);
  }
}

TEST_F(PlotRender, RingFitOutOfPlaneStressGetsNoBandsOfNoise) {
  // The rings' out-of-plane stress is constant in each ring (Lame: sigma_r + sigma_theta is), up
  // to 3 psi of discretisation noise: -91,532 .. -91,529 and 6,552.7 .. 6,555.8. Quantile levels
  // used to spend eight of twelve bands on the outer ring's 3 psi (6555.80, 6555.55, .., 6552.78,
  // -40000, -91529).
  const ResultMesh mesh = ResultMesh::from_result(ring_);
  const std::vector<double> stored = element_values(ring_, mesh, find_field("sigma_theta"));
  for (std::size_t e = 0; e < mesh.solids.size(); ++e) {
    if (mesh.solids[e].id < 200) {
      EXPECT_NEAR(stored[e], -91530.5, 2.0) << "inner ring, element " << mesh.solids[e].id;
    } else {
      EXPECT_NEAR(stored[e], 6554.25, 1.6) << "outer ring, element " << mesh.solids[e].id;
    }
  }
  const std::vector<double> values = nodal_values(ring_, mesh, find_field("sigma_theta"));
  std::vector<double> area(mesh.nodes.size(), 0.0);
  for (const SolidElement& e : mesh.solids) {
    for (const int n : e.nodes) area[n] += mesh.area(e) / static_cast<double>(e.nodes.size());
  }
  for (const LevelRule rule : {ContourOptions{}.levels, LevelRule::quantile}) {
    const BandLevels b = band_levels(values, area, 12, rule);
    const double span = b.levels.back() - b.levels.front();
    for (std::size_t k = 1; k < b.levels.size(); ++k) {
      EXPECT_GE(b.levels[k] - b.levels[k - 1], 0.01 * span)
          << "rule " << static_cast<int>(rule) << ": levels " << b.levels[k - 1] << " and " << b.levels[k];
    }
  }
}

TEST_F(PlotRender, SignedFieldsAreDrawnInADivergingMapByDefault) {
  // The rings' hoop stress: compressive in the heated inner ring, tensile in the outer one.
  const auto [red, blue] = red_and_blue_pixels(render_plot(ring_, request("sigma_hoop", ImageFormat::png)), dir_ / "d.png");
  EXPECT_GT(red, 2000U) << "tension in red";
  EXPECT_GT(blue, 2000U) << "compression in blue";
  // The beam's effective stress is never negative: viridis, no red at all.
  EXPECT_EQ(red_and_blue_pixels(render_plot(p3_, request("effective", ImageFormat::png)), dir_ / "d.png").first, 0U);
  PlotRequest override = request("sigma_hoop", ImageFormat::png);
  override.contour.color_map = "viridis";
  EXPECT_EQ(red_and_blue_pixels(render_plot(ring_, override), dir_ / "d.png").first, 0U) << "--colormap overrides";
}

TEST_F(PlotRender, CentreOptionOverTheCommandLine) {
  // sigma_hoop along the x axis from the bore out, about the origin and about a far centre.
  Outcome r = run("plot " + path("ring.json") + " --field sigma_hoop --centre 0,0 --path '1.05,0.05;2.15,0.05' "
                  "--samples 5 -o " + path("hoop.csv"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string about_origin = read(dir_ / "hoop.csv");
  r = run("plot " + path("ring.json") + " --field sigma_hoop --centre=-100,0.05 --path '1.05,0.05;2.15,0.05' "
          "--samples 5 -o " + path("hoop.csv"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(read(dir_ / "hoop.csv"), about_origin) << "the centre moves the axes";
  EXPECT_NE(about_origin.find("s,r,z,element,sigma_hoop,px,py"), std::string::npos) << about_origin;
  expect_error(run("plot " + path("ring.json") + " --field sigma_hoop --centre 1 -o " + path("x.png")), "--centre");
  EXPECT_FALSE(fs::exists(dir_ / "x.png"));
}

TEST_F(PlotRender, ClosureAndConvergencePngs) {
  for (const nlohmann::json* result : {&p3_, &ring_}) {
    EXPECT_GT(png_colours(render_plot(*result, request("closure", ImageFormat::png)), 900, 600), 30U);
    EXPECT_GT(png_colours(render_plot(*result, request("convergence", ImageFormat::png, 640, 480)), 640, 480), 30U);
  }
  PlotRequest along = request("closure", ImageFormat::png);
  along.row.along = RowAxis::position;
  EXPECT_GT(png_colours(render_plot(ring_, along), 900, 600), 30U);
}

TEST_F(PlotRender, PlotsReadOnlyTheirPartOfAResultAndDrawTheSame) {
  for (const nlohmann::json* result : {&p3_, &ring_}) {
    const std::string text = result->dump();
    // PNG: cairo numbers the surfaces of SVG documents per process, so two SVGs differ in ids.
    const PlotRequest convergence = request("convergence", ImageFormat::png, 320, 240);
    const io::ResultArrays history = io::read_result_arrays(text, result_selection_for(convergence));
    EXPECT_FALSE(history.nodes || history.elements);
    EXPECT_FALSE(history.document.contains("nodes") || history.document.contains("elements"));
    EXPECT_TRUE(history.document.contains("history"));
    EXPECT_TRUE(history.document.contains("gaps"));
    EXPECT_EQ(render_plot(PlotResult(history), convergence), render_plot(*result, convergence));

    for (const char* name : {"sigma_theta", "sigma_hoop", "temperature", "closure", "contact_pressure"}) {
      SCOPED_TRACE(name);
      PlotRequest plot = request(name, ImageFormat::png, 320, 240);
      plot.contour.automatic_deformation = true;
      const io::ResultArrays read = io::read_result_arrays(text, result_selection_for(plot));
      EXPECT_EQ(read.elements->values.size(), std::string(name) == "sigma_theta" ? 1U : std::string(name) == "sigma_hoop" ? 3U : 0U);
      EXPECT_EQ(render_plot(PlotResult(read), plot), render_plot(*result, plot));
    }
    // A path across the first element, corner to opposite corner: inside the mesh.
    std::map<int, std::pair<double, double>> at;
    for (const auto& n : (*result)["nodes"]) at[n["id"].get<int>()] = {n["r"].get<double>(), n["z"].get<double>()};
    const auto& corners = (*result)["elements"][0]["nodes"];
    const auto [r0, z0] = at.at(corners[0].get<int>());
    const auto [r2, z2] = at.at(corners[2].get<int>());
    PlotRequest along = request("sigma_theta", ImageFormat::png);
    along.path = PathOptions{{{r0, z0}, {r2, z2}}, 21};
    EXPECT_EQ(render_table(PlotResult(io::read_result_arrays(text, result_selection_for(along))), along),
              render_table(*result, along));
  }
}

TEST_F(PlotRender, SvgDocumentsHoldTheDrawing) {
  PlotRequest contour = request("effective", ImageFormat::svg);
  contour.contour.mesh = true;
  const std::string svg = render_plot(p3_, contour);
  EXPECT_EQ(svg.rfind("<?xml", 0), 0U);
  EXPECT_NE(svg.find("width=\"900px\""), std::string::npos);
  EXPECT_NE(svg.find("</svg>"), std::string::npos);
  // One path per colour level and per gap element, glyph outlines for every label.
  EXPECT_GT(count(svg, "<path"), p3_["gaps"].size() + 10);
  EXPECT_GT(count(svg, "<use"), 100U) << "the labels' glyphs";
  for (const char* name : {"closure", "convergence"}) {
    const std::string chart = render_plot(ring_, request(name, ImageFormat::svg));
    EXPECT_NE(chart.find("</svg>"), std::string::npos) << name;
    EXPECT_GT(count(chart, "<use"), 100U) << name;
  }
}

TEST_F(PlotRender, PlotCommandWritesTheFileTheExtensionNames) {
  Outcome r = run("plot " + path("p3.json") + " --field effective --deformed 50 --mesh --width 640 --height 400 -o " +
                  path("effective.png"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_GT(png_colours(read(dir_ / "effective.png"), 640, 400), 30U);
  r = run("plot " + path("ring.json") + " --field closure -o " + path("closure.svg"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(read(dir_ / "closure.svg").find("<svg"), std::string::npos);
  r = run("plot " + path("ring.json") + " --field convergence --deformed auto -o " + path("convergence.png"));
  EXPECT_EQ(r.exit_code, 0) << r.err;
}

TEST_F(PlotRender, ContactSurfacesFromTheCommandLineOneCurvePerPair) {
  // The press fit imported as contact surfaces (docs/import.md), solved and plotted as a user does.
  const std::string assembly = std::string(SAASGAPS_EXAMPLES_DIR) + "/assemblies/ring-press-fit.assembly.json";
  Outcome r = run("import " + assembly + " -o " + path("press-fit-model.json"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  r = run("solve " + path("press-fit-model.json") + " -q -o " + path("press-fit.json"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  r = run("plot " + path("press-fit.json") + " --field contact_pressure --along z -o " + path("press-fit.csv"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string csv = read(dir_ / "press-fit.csv");
  EXPECT_NE(csv.find("pairs (surfaces A / B): 1 = hub_bore / shaft_outside;"), std::string::npos) << csv;
  std::size_t rows = 0;
  std::istringstream lines(csv.substr(csv.find("pair,point,x,r,z,pressure,gap,state")));
  for (std::string line; std::getline(lines, line);) rows += line.rfind("1,", 0) == 0 ? 1 : 0;
  EXPECT_EQ(rows, 13U) << "a row per point of the hub's bore";
  // The closure plot of a model with surfaces only draws them rather than failing.
  for (const char* field : {"contact_pressure", "closure"}) {
    r = run("plot " + path("press-fit.json") + " --field " + field + " -o " + path(std::string(field) + "-pf.png"));
    ASSERT_EQ(r.exit_code, 0) << field << ": " << r.err;
    EXPECT_GT(png_colours(read(dir_ / (std::string(field) + "-pf.png")), 1200, 800), 30U) << field;
  }
}

TEST_F(PlotRender, UnknownFieldIsAClearErrorListingTheFields) {
  const Outcome r = run("plot " + path("p3.json") + " --field stress -o " + path("x.png"));
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.err.find("unknown field 'stress'"), std::string::npos) << r.err;
  for (const char* name : {"sigma_r", "sigma_z", "tau_rz", "sigma_theta", "sigma_1", "sigma_2", "effective",
                           "temperature", "displacement", "closure", "convergence"}) {
    EXPECT_NE(r.err.find(name), std::string::npos) << name << " missing from: " << r.err;
  }
  EXPECT_FALSE(fs::exists(dir_ / "x.png"));
}

TEST_F(PlotRender, OtherBadArgumentsFailWithAMessage) {
  Outcome r = run("plot " + path("p3.json") + " --field effective -o " + path("x.jpg"));
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find(".png or .svg"), std::string::npos) << r.err;
  r = run("plot " + path("p3.json") + " --field effective --deformed lots -o " + path("x.png"));
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("--deformed"), std::string::npos) << r.err;
  r = run("plot " + path("missing.json") + " --field effective -o " + path("x.png"));
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("missing.json"), std::string::npos) << r.err;
}

TEST_F(PlotRender, GapRowAndPathOptionsAreCheckedAndNamed) {
  Outcome r = run("plot " + path("p3.json") + " --field contact_pressure --gaps 81-85,90 --along r -o " + path("row.csv"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string table = read(dir_ / "row.csv");
  EXPECT_EQ(count(table, "\n8"), 5U) << "gaps 81..85 in the row's order:\n" << table;
  EXPECT_NE(table.find("\n90,"), std::string::npos);
  const std::string p3 = "plot " + path("p3.json");
  expect_error(run(p3 + " --field contact_pressure --gaps 85-81 -o " + path("x.png")), "runs backwards");
  expect_error(run(p3 + " --field closure --gaps 81,7 -o " + path("x.png")), "gap 7 is not a gap element");
  expect_error(run(p3 + " --field effective --path 1,2 -o " + path("x.png")), "--path");
  expect_error(run(p3 + " --field effective --path '50,50;60,60' -o " + path("x.png")), "does not pass through the mesh");
  expect_error(run(p3 + " --field closure --path '0,0;1,1' -o " + path("x.png")), "gap field");
  expect_error(run(p3 + " --field effective -o " + path("x.csv")), "data table");
  EXPECT_FALSE(fs::exists(dir_ / "x.png"));
  EXPECT_FALSE(fs::exists(dir_ / "x.csv"));
  // A field along a path in every colour map (the map does not apply; the options still parse).
  for (const char* map : {"viridis", "cividis", "rainbow"}) {
    r = run("plot " + path("ring.json") + " --field temperature --path '0,0;2,2' --colormap " + map + " -o " + path("p.png"));
    EXPECT_EQ(r.exit_code, 0) << r.err;
  }
}

TEST_F(PlotRender, VtuFromExportAndFromSolveAgree) {
  Outcome r = run("export-vtu " + path("p3.json") + " -o " + path("p3.vtu"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  r = run("solve " + std::string(SAASGAPS_EXAMPLES_DIR) + "/report-problem3-case1.json -q -o " + path("again.json") +
          " --vtu " + path("again.vtu"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string exported = read(dir_ / "p3.vtu");
  EXPECT_EQ(exported, read(dir_ / "again.vtu"));
  EXPECT_NE(exported.find("NumberOfPoints=\"114\" NumberOfCells=\"90\""), std::string::npos);
  r = run("export-vtu " + path("p3.json") + " --format text -o " + path("p3.vtu"));
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.err.find("--format"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace saasgaps::plot
