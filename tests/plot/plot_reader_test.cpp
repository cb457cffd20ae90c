// Every plot of every example result, drawn from the tree of the whole document (the reference)
// and from the typed arrays of the stored-result reader (io/results/result_arrays.hpp), which `saasgaps
// plot` and the service's plot routes use: the same PNG bytes and the same CSV tables, or the same
// error. The VTU export likewise against the tree writer it replaced (vtu_tree_reference). Also
// `saasgaps plot`'s file against the reference.
#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "io/results/result_arrays.hpp"
#include "io/results/vtu_writer.hpp"
#include "plot/pictures/plot_request.hpp"
#include "plot/vtu_tree_reference.hpp"
#include "support/captured_command.hpp"

namespace saasgaps::plot {
namespace {

namespace fs = std::filesystem;

/// The image, or the error's message.
template <class Render>
std::string drawn(Render render) {
  try {
    return render();
  } catch (const std::invalid_argument& e) {
    return std::string("error: ") + e.what();
  }
}

class PlotReader : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = fs::temp_directory_path() / ("saasgaps-plot-reader-" + std::to_string(::getpid()));
    fs::create_directories(dir_);
    for (const auto& entry : fs::directory_iterator(SAASGAPS_EXAMPLES_DIR)) {
      if (entry.path().extension() != ".json") continue;
      const fs::path result = dir_ / entry.path().filename();
      const testing::Outcome r = testing::run_captured(std::string(SAASGAPS_BINARY) + " solve " + entry.path().string() +
                                                           " -q -o " + result.string(),
                                                       dir_ / "out.txt", dir_ / "err.txt");
      ASSERT_EQ(r.exit_code, 0) << entry.path() << r.err;
      results_.push_back(result);
    }
  }
  static void TearDownTestSuite() { fs::remove_all(dir_); }

  static inline fs::path dir_;
  static inline std::vector<fs::path> results_;
};

TEST_F(PlotReader, EveryPlotOfEveryExampleIsTheTreesPlot) {
  ASSERT_GE(results_.size(), 10U);
  int images = 0;  // drawn, not refused: the comparison is of pictures, not only of errors
  for (const fs::path& file : results_) {
    SCOPED_TRACE(file.filename().string());
    const std::string text = testing::read_text(file);
    const nlohmann::json tree = nlohmann::json::parse(text);
    for (const std::string& name : plot_names()) {
      SCOPED_TRACE(name);
      PlotRequest request;
      request.name = name;
      request.width = 200;
      request.height = 150;
      request.contour.automatic_deformation = name == "effective";
      request.contour.mesh = name == "sigma_r";
      const PlotResult arrays(io::read_result_arrays(text, result_selection_for(request)));
      const std::string reference = drawn([&] { return render_plot(tree, request); });
      EXPECT_EQ(drawn([&] { return render_plot(arrays, request); }), reference);
      if (reference.rfind("error: ", 0) != 0) ++images;
      if (name == "closure" || name == "contact_pressure") {
        EXPECT_EQ(drawn([&] { return render_table(arrays, request); }), drawn([&] { return render_table(tree, request); }));
      }
    }
  }
  EXPECT_GT(images, 200);
}

TEST_F(PlotReader, EveryExampleExportsTheTreesVtu) {
  for (const fs::path& file : results_) {
    SCOPED_TRACE(file.filename().string());
    const std::string text = testing::read_text(file);
    const nlohmann::json tree = nlohmann::json::parse(text);
    const io::ResultArrays arrays = io::read_result_arrays(text, io::vtu_result_selection());
    for (const io::VtuFormat format : {io::VtuFormat::binary, io::VtuFormat::ascii}) {
      EXPECT_EQ(io::result_to_vtu(arrays, format), io::reference::result_to_vtu(tree, format));
    }
    std::map<std::string, std::string> typed, reference;
    io::write_vtu_series(arrays, "run", io::VtuFormat::binary,
                         [&](const std::string& name, const std::string& bytes) { typed[name] = bytes; });
    io::reference::write_vtu_series(tree, "run", io::VtuFormat::binary,
                                    [&](const std::string& name, const std::string& bytes) { reference[name] = bytes; });
    EXPECT_EQ(typed, reference);
  }
}

TEST_F(PlotReader, ThePlotCommandDrawsTheTreesPlot) {
  for (const fs::path& file : results_) {
    if (file.filename() != "ring-shrink-fit-plane-strain.json" && file.filename() != "report-problem1.json") continue;
    const nlohmann::json tree = nlohmann::json::parse(testing::read_text(file));
    for (const char* name : {"sigma_hoop", "convergence", "closure"}) {
      const fs::path png = dir_ / "plot.png";
      const testing::Outcome r = testing::run_captured(std::string(SAASGAPS_BINARY) + " plot " + file.string() +
                                                           " --field " + name + " -o " + png.string(),
                                                       dir_ / "out.txt", dir_ / "err.txt");
      PlotRequest request;
      request.name = name;
      const std::string reference = drawn([&] { return render_plot(tree, request); });
      if (reference.rfind("error: ", 0) == 0) {
        EXPECT_NE(r.exit_code, 0);
        continue;
      }
      ASSERT_EQ(r.exit_code, 0) << r.err;
      EXPECT_EQ(testing::read_text(png), reference) << file.filename() << " " << name;
    }
  }
}

}  // namespace
}  // namespace saasgaps::plot
