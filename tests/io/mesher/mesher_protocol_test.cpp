// The mesher's output decoded as hostile input (io/mesher_protocol.hpp): a faithful round trip,
// and every forged or truncated encoding refused with MeshError rather than read out of bounds.
#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <limits>

#include "io/mesher/mesher_protocol.hpp"

namespace saasgaps::io {
namespace {

GmshMesh two_triangles() {
  GmshMesh m;
  m.node_tags = {1, 2, 3, 4};
  m.r = {0, 1, 1, 0};
  m.z = {0, 0, 1, 1};
  m.faces = {{7, 1, 3, {0, 1, 2, -1}}, {8, 1, 3, {0, 2, 3, -1}}};
  m.curves[1] = {{0, 1}};
  m.points[1] = 0;
  m.groups = {{2, 1, "body", {1}}, {1, 2, "", {1}}};
  return m;
}

/// The encoding with the 4 bytes at `offset` replaced by `value`.
std::string with_int(std::string bytes, std::size_t offset, std::int32_t value) {
  std::memcpy(bytes.data() + offset, &value, sizeof value);
  return bytes;
}

TEST(MesherProtocol, RoundTrip) {
  const GmshMesh m = two_triangles();
  const GmshMesh back = mesher::decode(mesher::encode(m), 100, "t.geo");
  EXPECT_EQ(back.node_tags, m.node_tags);
  EXPECT_EQ(back.r, m.r);
  EXPECT_EQ(back.faces.size(), 2u);
  EXPECT_EQ(back.faces[1].nodes, m.faces[1].nodes);
  EXPECT_EQ(back.curves.at(1).front().b, 1);
  EXPECT_EQ(back.points.at(1), 0);
  EXPECT_EQ(back.groups[0].name, "body");
  EXPECT_EQ(back.groups[1].entities, std::vector<int>{1});
}

TEST(MesherProtocol, SecondOrderFacesAndLinesRoundTrip) {
  GmshMesh m;
  m.node_tags = {1, 2, 3, 4, 5, 6, 7, 8, 9};
  m.r = {0, 2, 2, 0, 1, 2, 1, 0, 1};
  m.z = {0, 0, 2, 2, 0, 1, 2, 1, 1};
  m.faces = {{7, 1, 9, {0, 1, 2, 3, 4, 5, 6, 7, 8}}};
  m.curves[1] = {{0, 1, 4}};
  const GmshMesh back = mesher::decode(mesher::encode(m), 100, "t.msh");
  EXPECT_EQ(back.faces[0].count, 9);
  EXPECT_EQ(back.faces[0].corners(), 4);
  EXPECT_EQ(back.faces[0].nodes, m.faces[0].nodes);
  EXPECT_EQ(back.curves.at(1).front().m, 4);
  // A 7-node face is no element of any family.
  m.faces[0].count = 7;
  EXPECT_THROW(mesher::decode(mesher::encode(m), 100, "t.msh"), MeshError);
}

TEST(MesherProtocol, ForgedOrTruncatedOutputIsRefused) {
  const std::string good = mesher::encode(two_triangles());
  for (std::size_t cut = 0; cut < good.size(); cut += 7) {
    EXPECT_THROW(mesher::decode(good.substr(0, cut), 100, "t.geo"), MeshError) << cut;
  }
  EXPECT_THROW(mesher::decode(good + "x", 100, "t.geo"), MeshError);
  // A node count far beyond the bytes: refused before anything is allocated.
  std::string huge = good;
  const std::uint64_t lie = std::uint64_t{1} << 60;
  std::memcpy(huge.data() + 8, &lie, sizeof lie);
  EXPECT_THROW(mesher::decode(huge, std::size_t{1} << 62, "t.geo"), MeshError);
  // The first face's first node (after the header, 4 nodes, the face count, tag, surface, count).
  const std::size_t first_face_node = 8 + 8 + 4 * 24 + 8 + 8 + 4 + 4;
  EXPECT_THROW(mesher::decode(with_int(good, first_face_node, 4), 100, "t.geo"), MeshError);
  EXPECT_THROW(mesher::decode(with_int(good, first_face_node, -1), 100, "t.geo"), MeshError);
  EXPECT_THROW(mesher::decode(with_int(good, first_face_node - 4, 5), 100, "t.geo"), MeshError);  // 5 nodes
}

TEST(MesherProtocol, NodesBeyondTheLimitAreMeshTooLarge) {
  try {
    (void)mesher::decode(mesher::encode(two_triangles()), 3, "t.geo");
    FAIL() << "decoded";
  } catch (const MeshTooLarge& e) {
    EXPECT_NE(std::string(e.what()).find("4 nodes, more than the limit of 3 nodes"), std::string::npos) << e.what();
  }
}

/// The defaults and the output bound docs/import.md quotes.
TEST(MesherProtocol, DocumentedLimits) {
  const MeshLimits limits;
  EXPECT_EQ(limits.max_nodes, 200000u);
  EXPECT_EQ(limits.seconds, 60);
  EXPECT_EQ(limits.memory_bytes, std::size_t{2} << 30);
  EXPECT_EQ(limits.file_bytes, std::size_t{64} << 20);
  EXPECT_EQ(mesher::output_limit(1000) - mesher::output_limit(0), 280000u);
  EXPECT_EQ(mesher::output_limit(0), 16u + (1u << 20));
  EXPECT_GE(concurrent_meshers(), 2);
}

// ---- the size field the parent sends the mesher for a re-mesh (read by the mesher as hostile input)

SizeField square_sizes() {
  SizeField f;
  f.x = {0, 1, 1, 0};
  f.y = {0, 0, 1, 1};
  f.size = {0.1, 0.2, 0.3, 0.4};
  f.triangles = {{0, 1, 2}, {0, 2, 3}};
  return f;
}

TEST(MesherProtocol, SizeFieldRoundTrip) {
  const SizeField f = square_sizes();
  const SizeField g = mesher::decode_sizes(mesher::encode_sizes(f, 1000), 1000);
  EXPECT_EQ(g.x, f.x);
  EXPECT_EQ(g.y, f.y);
  EXPECT_EQ(g.size, f.size);
  EXPECT_EQ(g.triangles, f.triangles);
  EXPECT_LE(mesher::encode_sizes(f, 1000).size(), mesher::size_input_limit(1000));
}

TEST(MesherProtocol, ForgedSizeFieldsAreRefused) {
  const std::string good = mesher::encode_sizes(square_sizes(), 1000);
  const auto refused = [](const std::string& bytes, std::size_t max_nodes, const char* words) {
    try {
      (void)mesher::decode_sizes(bytes, max_nodes);
      ADD_FAILURE() << "accepted: " << words;
    } catch (const MeshError& e) {
      EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find("the size field on the mesher's input is not valid"), std::string::npos);
    }
  };
  refused(good.substr(0, good.size() - 1), 1000, "end marker");
  refused(good.substr(0, 20), 1000, "beyond the data");
  refused("SGMESH1\n" + good.substr(8), 1000, "no header");
  refused(good + "x", 1000, "bytes after the end marker");
  // The first triangle's first index (after the header, the count, 4 nodes of 24 bytes and the
  // triangle count) pointing past the nodes.
  const std::size_t first_index = 8 + 8 + 4 * 24 + 8;
  refused(with_int(good, first_index, 4), 1000, "node index 4 outside the 4 nodes");
  refused(with_int(good, first_index, -1), 1000, "node index -1");
  // A size of 0 (the first node's size, after x and y).
  std::string zero = good;
  const double nothing = 0.0;
  std::memcpy(zero.data() + 8 + 8 + 16, &nothing, sizeof nothing);
  refused(zero, 1000, "sizes are finite and > 0");
  // More nodes than the bound of 4 x the node limit.
  refused(good, 0, "bytes, beyond its bound");
  // A count beyond the data cannot make the reader allocate.
  std::string huge = good;
  const std::uint64_t many = std::uint64_t{1} << 60;
  std::memcpy(huge.data() + 8, &many, sizeof many);
  refused(huge, 1000, "beyond the data");
}

TEST(MesherProtocol, ASizeFieldOutOfBoundsIsNotSent) {
  SizeField f = square_sizes();
  f.size[2] = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW((void)mesher::encode_sizes(f, 1000), MeshError);
  f = square_sizes();
  f.triangles.push_back({0, 1, 9});
  EXPECT_THROW((void)mesher::encode_sizes(f, 1000), MeshError);
  f = square_sizes();
  f.size.pop_back();
  EXPECT_THROW((void)mesher::encode_sizes(f, 1000), MeshError);
}

}  // namespace
}  // namespace saasgaps::io
