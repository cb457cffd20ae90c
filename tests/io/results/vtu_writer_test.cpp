// The VTU export on a hand-made result document: structure, cell types, and the values ParaView
// shows (check_vtu.py reads a real one back with meshio).
#include <gtest/gtest.h>

#include <zlib.h>

#include <cstring>
#include <map>
#include <nlohmann/json.hpp>

#include "io/results/vtu_writer.hpp"

namespace saasgaps::io {
namespace {

using nlohmann::json;

json triangle_and_gap() {
  const auto node = [](int id, double r, double z) {
    return json{{"id", id}, {"r", r}, {"z", z}, {"T", 70.0}, {"u_r", 0.1}, {"u_z", -0.25}};
  };
  return {{"status", "converged"},
          {"title", "a -- b"},
          {"analysis", "axisymmetric"},
          {"nodes", {node(10, 0.0, 0.0), node(20, 1.0, 0.0), node(30, 0.0, 1.0), node(40, 1.0, -0.01),
                     node(50, 0.0, -0.01)}},
          {"elements", {{{"id", 1}, {"nodes", {10, 20, 30}}, {"material", 7}, {"sigma_r", 0.1}, {"sigma_z", 2.0},
                         {"tau_rz", 3.0}, {"sigma_theta", 4.0}, {"sigma_1", 5.0}, {"sigma_2", 6.0}, {"angle", 7.0},
                         {"effective", 8.0}, {"eps_r", 1e-3}, {"eps_z", 2e-3}, {"gamma_rz", 3e-3},
                         {"eps_theta", 4e-3}, {"yield", true}, {"plastic_converged", false}}}},
          {"gaps", {{{"id", 2}, {"nodes", {50, 40, 20, 10}}, {"angle", 90.0}, {"eps_m", -1.02}, {"closure", 102.0},
                     {"modulus", 55.0}, {"sigma_m", -300.0}, {"state", "closed"}, {"converged", true}}}}};
}

std::string array_text(const std::string& vtu, const std::string& name) {
  const std::size_t start = vtu.find("Name=\"" + name + "\"");
  EXPECT_NE(start, std::string::npos) << name;
  const std::size_t open = vtu.find('>', start) + 1;
  const std::size_t close = vtu.find("</DataArray>", open);
  std::string text = vtu.substr(open, close - open);
  std::string squeezed;
  for (const char c : text) {
    if (c == '\n' || c == ' ') {
      if (!squeezed.empty() && squeezed.back() != ' ') squeezed += ' ';
    } else {
      squeezed += c;
    }
  }
  while (!squeezed.empty() && squeezed.back() == ' ') squeezed.pop_back();
  return squeezed;
}

TEST(VtuWriter, PlaneModelsNameTheirAxesAndAModelWithoutGapsHasNoGapArrays) {
  // Issue 33: a plane model's stresses are sigma_x, sigma_y, tau_xy and sigma_z (out of the plane),
  // not cylindrical components; a model without gap elements carries no all-zero gap_* arrays.
  json plane = triangle_and_gap();
  plane["analysis"] = "plane_strain";
  plane["gaps"] = json::array();
  const std::string vtu = result_to_vtu(plane, VtuFormat::ascii);
  EXPECT_EQ(array_text(vtu, "sigma_x"), "0.1");
  EXPECT_EQ(array_text(vtu, "sigma_y"), "2");
  EXPECT_EQ(array_text(vtu, "tau_xy"), "3");
  EXPECT_EQ(array_text(vtu, "sigma_z"), "4");
  EXPECT_EQ(array_text(vtu, "eps_x"), "0.001");
  EXPECT_EQ(array_text(vtu, "gamma_xy"), "0.003");
  EXPECT_EQ(array_text(vtu, "eps_z"), "0.004");
  for (const char* gone : {"Name=\"sigma_r\"", "Name=\"sigma_theta\"", "Name=\"eps_theta\"", "Name=\"gap_"}) {
    EXPECT_EQ(vtu.find(gone), std::string::npos) << gone;
  }
  // Axisymmetric models keep the cylindrical names (the test above), with their gaps.
  json ring = triangle_and_gap();
  ring["gaps"] = json::array();
  const std::string axisymmetric = result_to_vtu(ring, VtuFormat::ascii);
  EXPECT_EQ(array_text(axisymmetric, "sigma_theta"), "4");
  EXPECT_EQ(axisymmetric.find("Name=\"gap_"), std::string::npos);
}

TEST(VtuWriter, SolidsThenGapsWithTheirTypesAndData) {
  const std::string vtu = result_to_vtu(triangle_and_gap(), VtuFormat::ascii);
  EXPECT_NE(vtu.find("NumberOfPoints=\"5\" NumberOfCells=\"2\""), std::string::npos);
  EXPECT_NE(vtu.find("a - b"), std::string::npos) << "no '--' inside the XML comment";
  EXPECT_EQ(array_text(vtu, "Points"), "0 0 0 1 0 0 0 1 0 1 -0.01 0 0 -0.01 0");
  EXPECT_EQ(array_text(vtu, "connectivity"), "0 1 2 4 3 1 0");
  EXPECT_EQ(array_text(vtu, "offsets"), "3 7");
  EXPECT_EQ(array_text(vtu, "types"), "5 9");
  EXPECT_EQ(array_text(vtu, "displacement"), "0.1 -0.25 0 0.1 -0.25 0 0.1 -0.25 0 0.1 -0.25 0 0.1 -0.25 0");
  EXPECT_EQ(array_text(vtu, "node_id"), "10 20 30 40 50");
  EXPECT_EQ(array_text(vtu, "element_id"), "1 2");
  EXPECT_EQ(array_text(vtu, "is_gap"), "0 1");
  EXPECT_EQ(array_text(vtu, "material"), "7 0");
  EXPECT_EQ(array_text(vtu, "sigma_r"), "0.1 0");
  EXPECT_EQ(array_text(vtu, "principal_angle"), "7 0");
  EXPECT_EQ(array_text(vtu, "yield"), "1 0");
  EXPECT_EQ(array_text(vtu, "plastic_converged"), "0 1");
  EXPECT_EQ(array_text(vtu, "gap_closure"), "0 102");
  EXPECT_EQ(array_text(vtu, "gap_sigma_m"), "0 -300");
  EXPECT_EQ(array_text(vtu, "gap_contact_pressure"), "0 300") << "max(0, -sigma_m) when the document lacks it";
  EXPECT_EQ(array_text(vtu, "gap_state"), "-1 2");
  EXPECT_EQ(array_text(vtu, "gap_converged"), "-1 1");
}

/// The bytes of a binary VTU's appended array `name`, decompressed (VTK's UInt64 block header).
std::string appended_bytes(const std::string& vtu, const std::string& name) {
  const std::size_t at = vtu.find("Name=\"" + name + "\"");
  if (at == std::string::npos) return "(no array " + name + ")";
  const std::size_t offset_at = vtu.find("offset=\"", at) + 8;
  const std::size_t offset = std::stoul(vtu.substr(offset_at, vtu.find('"', offset_at) - offset_at));
  const char* data = vtu.data() + vtu.find("<AppendedData encoding=\"raw\">") + 1;
  data = std::strchr(data, '_') + 1 + offset;
  std::uint64_t header[3];
  std::memcpy(header, data, sizeof header);
  std::vector<std::uint64_t> sizes(header[0]);
  std::memcpy(sizes.data(), data + sizeof header, sizes.size() * sizeof(std::uint64_t));
  const char* block = data + sizeof header + sizes.size() * sizeof(std::uint64_t);
  std::string out;
  for (std::size_t b = 0; b < sizes.size(); ++b) {
    std::string plain(header[1], '\0');
    uLongf length = static_cast<uLongf>(plain.size());
    EXPECT_EQ(uncompress(reinterpret_cast<Bytef*>(plain.data()), &length, reinterpret_cast<const Bytef*>(block),
                         static_cast<uLong>(sizes[b])),
              Z_OK);
    out.append(plain.data(), length);
    block += sizes[b];
  }
  EXPECT_EQ(out.size(), (sizes.size() - 1) * header[1] + (header[2] ? header[2] : header[1]));
  return out;
}

template <typename T>
std::vector<T> values_of(const std::string& bytes) {
  std::vector<T> v(bytes.size() / sizeof(T));
  std::memcpy(v.data(), bytes.data(), v.size() * sizeof(T));
  return v;
}

TEST(VtuWriter, ReactionsArePointForcesZeroAtFreeNodes) {
  json result = triangle_and_gap();
  EXPECT_EQ(result_to_vtu(result, VtuFormat::ascii).find("Name=\"reaction"), std::string::npos)
      << "a result written before reactions has none";
  result["reactions"] = {{{"node", 40}, {"fr", 0.0}, {"fz", 12.5}}, {{"node", 50}, {"fr", -3.0}, {"fz", 0.0}}};
  result["units"] = {{"force", "lbf"}};
  const std::string vtu = result_to_vtu(result, VtuFormat::ascii);
  EXPECT_EQ(array_text(vtu, "reaction [lbf]"), "0 0 0 0 0 0 0 0 0 0 12.5 0 -3 0 0");
}

TEST(VtuWriter, BinaryIsZlibCompressedAppendedDataWithTheSameValues) {
  const std::string vtu = result_to_vtu(triangle_and_gap());
  EXPECT_NE(vtu.find("compressor=\"vtkZLibDataCompressor\""), std::string::npos);
  EXPECT_NE(vtu.find("header_type=\"UInt64\""), std::string::npos);
  EXPECT_EQ(vtu.find("format=\"ascii\""), std::string::npos);
  EXPECT_EQ(values_of<std::int32_t>(appended_bytes(vtu, "node_id")), (std::vector<std::int32_t>{10, 20, 30, 40, 50}));
  EXPECT_EQ(values_of<std::int64_t>(appended_bytes(vtu, "connectivity")),
            (std::vector<std::int64_t>{0, 1, 2, 4, 3, 1, 0}));
  EXPECT_EQ(values_of<std::uint8_t>(appended_bytes(vtu, "types")), (std::vector<std::uint8_t>{5, 9}));
  EXPECT_EQ(values_of<double>(appended_bytes(vtu, "gap_sigma_m")), (std::vector<double>{0.0, -300.0}));
  EXPECT_EQ(values_of<double>(appended_bytes(vtu, "eps_r")), (std::vector<double>{1e-3, 0.0}));

  // An array larger than one 32 KiB block: 5000 nodes of displacement (120000 bytes, 4 blocks).
  json big = triangle_and_gap();
  for (int i = 0; i < 4995; ++i) {
    big["nodes"].push_back({{"id", 100 + i}, {"r", 2.0 + i}, {"z", 0.0}, {"T", 1.0 * i}, {"u_r", 0.5 * i}, {"u_z", -1.0}});
  }
  const std::vector<double> t = values_of<double>(appended_bytes(result_to_vtu(big), "temperature"));
  ASSERT_EQ(t.size(), 5000U);
  EXPECT_EQ(t[4999], 4994.0);
}

TEST(VtuWriter, UnitsNameTheArrays) {
  json result = triangle_and_gap();
  result["units"] = {{"length", "in"}, {"stress", "psi"}, {"temperature", "degF"}};
  const std::string vtu = result_to_vtu(result, VtuFormat::ascii);
  for (const char* name : {"sigma_r [psi]", "effective [psi]", "gap_sigma_m [psi]", "gap_contact_pressure [psi]",
                           "gap_modulus [psi]", "displacement [in]", "temperature [degF]"}) {
    EXPECT_NE(vtu.find("Name=\"" + std::string(name) + "\""), std::string::npos) << name;
  }
  EXPECT_NE(vtu.find("Name=\"eps_r\""), std::string::npos) << "strains are dimensionless";
  EXPECT_NE(vtu.find("Vectors=\"displacement [in]\""), std::string::npos);
}

TEST(VtuWriter, SeriesHasOneFilePerIterationAndACollection) {
  json result = triangle_and_gap();
  result["iterations"] = 2;
  result["history"] = {{{"iteration", 1}, {"gap_closures", {250.0}}}, {{"iteration", 2}, {"gap_closures", {102.0}}}};
  std::map<std::string, std::string> files;
  std::vector<std::string> order;
  write_vtu_series(result, "out/run", VtuFormat::ascii, [&](const std::string& file, const std::string& bytes) {
    files[file] = bytes;
    order.push_back(file);
  });
  ASSERT_EQ(order, (std::vector<std::string>{"out/run_iter0001.vtu", "out/run_iter0002.vtu", "out/run.pvd"}));
  EXPECT_EQ(array_text(files["out/run_iter0001.vtu"], "gap_closure"), "0 250");
  EXPECT_EQ(files["out/run_iter0002.vtu"], result_to_vtu(result, VtuFormat::ascii)) << "the last is the whole result";
  EXPECT_NE(files["out/run.pvd"].find("timestep=\"1\" part=\"0\" file=\"run_iter0001.vtu\""), std::string::npos);
}

TEST(VtuWriter, GapStateCodes) {
  EXPECT_EQ(vtu_gap_state_code("open"), 0);
  EXPECT_EQ(vtu_gap_state_code("partial"), 1);
  EXPECT_EQ(vtu_gap_state_code("closed"), 2);
  EXPECT_EQ(vtu_gap_state_code("overclosed"), 3);
  EXPECT_THROW(vtu_gap_state_code("ajar"), std::invalid_argument);
}

TEST(VtuWriter, RefusesResultsWithoutAMesh) {
  EXPECT_THROW(result_to_vtu({{"status", "failed"}, {"message", "singular"}, {"nodes", json::array()}}),
               std::invalid_argument);
  json old = triangle_and_gap();
  for (json& n : old["nodes"]) n.erase("r");
  EXPECT_THROW(result_to_vtu(old), std::invalid_argument);
  json dangling = triangle_and_gap();
  dangling["gaps"][0]["nodes"][0] = 99;
  EXPECT_THROW(result_to_vtu(dangling), std::invalid_argument);
}

TEST(VtuWriter, ContactPointsArePointDataOnSideANodes) {
  json result = triangle_and_gap();
  // Without contact no contact arrays (a result without contact exports as before).
  EXPECT_EQ(result_to_vtu(result, VtuFormat::ascii).find("Name=\"contact_"), std::string::npos);
  result["units"] = {{"stress", "psi"}, {"length", "in"}};
  const auto point = [](double r, double z, double gap, double pressure, const char* state) {
    return json{{"r", r}, {"z", z}, {"gap", gap}, {"pressure", pressure}, {"shear", 0.0}, {"state", state}, {"slip", 0.0}};
  };
  result["contact"] = {{{"surfaces", {"a", "b"}}, {"points", {point(0.0, 0.0, 0.0, 12.5, "stick"), point(1.0, 0.0, 0.003, 0.0, "open")}}},
                       {{"surfaces", {"c", "d"}}, {"points", {point(0.0, -0.01, 0.0, 7.0, "stick")}}}};
  const std::string vtu = result_to_vtu(result, VtuFormat::ascii);
  // Nodes 10, 20, 30, 40, 50: 10 and 20 are side A of pair 1, 50 of pair 2.
  EXPECT_EQ(array_text(vtu, "contact_pressure [psi]"), "12.5 0 0 0 7");
  EXPECT_EQ(array_text(vtu, "contact_gap [in]"), "0 0.003 0 0 0");
  EXPECT_EQ(array_text(vtu, "contact_state"), "1 0 -1 -1 1");
  EXPECT_EQ(array_text(vtu, "contact_pair"), "1 1 0 0 2");
  EXPECT_EQ(array_text(vtu, "contact_slip [in]"), "0 0 0 0 0");
  EXPECT_NE(vtu.find("NumberOfPoints=\"5\" NumberOfCells=\"2\""), std::string::npos) << "one piece, the same mesh";

  json astray = result;
  astray["contact"][1]["points"][0]["r"] = 0.5;
  EXPECT_THROW(result_to_vtu(astray), std::invalid_argument);
  json bad_state = result;
  bad_state["contact"][0]["points"][0]["state"] = "glued";
  EXPECT_THROW(result_to_vtu(bad_state), std::invalid_argument);
}

}  // namespace
}  // namespace saasgaps::io
