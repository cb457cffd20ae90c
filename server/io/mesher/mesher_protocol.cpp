#include "io/mesher/mesher_protocol.hpp"

#include <cstdint>
#include <cmath>
#include <cstring>
#include <utility>
#include <type_traits>

namespace saasgaps::io::mesher {

namespace {

constexpr std::string_view magic = "SGMESH2\n";  // 2: faces of up to 9 nodes, edges with a mid-side node
constexpr std::string_view trailer = "END\n";
constexpr std::string_view size_magic = "SGSIZE1\n";

// Bytes per record of the encoding, for the bounds below.
constexpr std::size_t node_bytes = 8 + 8 + 8;
constexpr std::size_t face_bytes = 8 + 4 + 4 + 9 * 4;
constexpr std::size_t edge_bytes = 3 * 4;
constexpr std::size_t size_node_bytes = 3 * 8;
constexpr std::size_t triangle_bytes = 3 * 4;

class Writer {
 public:
  template <class T>
  void put(T value) {
    static_assert(std::is_trivially_copyable_v<T>);
    text_.append(reinterpret_cast<const char*>(&value), sizeof value);
  }
  void count(std::size_t n) { put(static_cast<std::uint64_t>(n)); }
  void bytes(std::string_view s) { text_.append(s); }
  std::string take() { return std::move(text_); }

 private:
  std::string text_;
};

/// Reads the encoding front to back; every read is checked against what remains.
class Reader {
 public:
  /// `prefix` begins every message: what the bytes were meant to be.
  Reader(std::string_view bytes, std::string prefix) : rest_(bytes), prefix_(std::move(prefix)) {}

  template <class T>
  T get() {
    static_assert(std::is_trivially_copyable_v<T>);
    need(sizeof(T), "a value");
    T value;
    std::memcpy(&value, rest_.data(), sizeof value);
    rest_.remove_prefix(sizeof value);
    return value;
  }
  /// A count of records of at least `record` bytes each: no more than the bytes left can hold,
  /// so a forged count cannot make the reader allocate beyond the (bounded) input.
  std::size_t count(std::size_t record, const char* what) {
    const auto n = get<std::uint64_t>();
    if (n > rest_.size() / record) fail(std::string("a count of ") + what + " (" + std::to_string(n) + ") beyond the data");
    return static_cast<std::size_t>(n);
  }
  void expect(std::string_view text, const char* what) {
    need(text.size(), what);
    if (rest_.substr(0, text.size()) != text) fail(std::string("no ") + what);
    rest_.remove_prefix(text.size());
  }
  std::string text(std::size_t n) {
    need(n, "a name");
    std::string s(rest_.substr(0, n));
    rest_.remove_prefix(n);
    return s;
  }
  /// A node index: -1 (none) when `may_be_none`, else in [0, nodes).
  int node(std::size_t nodes, bool may_be_none) {
    const auto i = get<std::int32_t>();
    if ((i == -1 && may_be_none) || (i >= 0 && static_cast<std::size_t>(i) < nodes)) return i;
    fail("node index " + std::to_string(i) + " outside the " + std::to_string(nodes) + " nodes");
  }
  [[nodiscard]] bool done() const { return rest_.empty(); }
  [[noreturn]] void fail(const std::string& what) const {
    throw MeshError(prefix_ + what);
  }

 private:
  void need(std::size_t n, const char* what) const {
    if (rest_.size() < n) fail(std::string("it ends before ") + what);
  }
  std::string_view rest_;
  std::string prefix_;
};

}  // namespace

std::size_t output_limit(std::size_t max_nodes) {
  // A first-order 2D mesh has about 2 triangles per node (a second-order one fewer) and fewer
  // boundary edges than nodes;
  // 4 faces and 4 edges per node plus 1 MiB for groups and names leaves room for any real mesh.
  return magic.size() + 8 + max_nodes * (node_bytes + 4 * face_bytes + 4 * edge_bytes) + (std::size_t{1} << 20);
}

std::string encode(const GmshMesh& mesh) {
  Writer w;
  w.bytes(magic);
  w.count(mesh.node_tags.size());
  for (std::size_t i = 0; i < mesh.node_tags.size(); ++i) {
    w.put(static_cast<std::uint64_t>(mesh.node_tags[i]));
    w.put(mesh.r[i]);
    w.put(mesh.z[i]);
  }
  w.count(mesh.faces.size());
  for (const MeshFace& f : mesh.faces) {
    w.put(static_cast<std::uint64_t>(f.tag));
    w.put(static_cast<std::int32_t>(f.surface));
    w.put(static_cast<std::int32_t>(f.count));
    for (const int n : f.nodes) w.put(static_cast<std::int32_t>(n));
  }
  w.count(mesh.curves.size());
  for (const auto& [curve, edges] : mesh.curves) {
    w.put(static_cast<std::int32_t>(curve));
    w.count(edges.size());
    for (const MeshEdge& e : edges) {
      w.put(static_cast<std::int32_t>(e.a));
      w.put(static_cast<std::int32_t>(e.b));
      w.put(static_cast<std::int32_t>(e.m));
    }
  }
  w.count(mesh.points.size());
  for (const auto& [point, node] : mesh.points) {
    w.put(static_cast<std::int32_t>(point));
    w.put(static_cast<std::int32_t>(node));
  }
  w.count(mesh.groups.size());
  for (const PhysicalGroup& g : mesh.groups) {
    w.put(static_cast<std::int32_t>(g.dim));
    w.put(static_cast<std::int32_t>(g.tag));
    w.count(g.name.size());
    w.bytes(g.name);
    w.count(g.entities.size());
    for (const int e : g.entities) w.put(static_cast<std::int32_t>(e));
  }
  w.bytes(trailer);
  return w.take();
}

GmshMesh decode(std::string_view bytes, std::size_t max_nodes, const std::string& source) {
  Reader in(bytes, "the mesher's output for " + source + " is not a valid mesh: ");
  in.expect(magic, "header");
  GmshMesh mesh;
  const std::size_t nodes = in.count(node_bytes, "nodes");
  if (nodes > max_nodes) {
    throw MeshTooLarge(source + " meshes to " + std::to_string(nodes) + " nodes, more than the limit of " +
                       std::to_string(max_nodes) + " nodes");
  }
  mesh.node_tags.resize(nodes);
  mesh.r.resize(nodes);
  mesh.z.resize(nodes);
  for (std::size_t i = 0; i < nodes; ++i) {
    mesh.node_tags[i] = in.get<std::uint64_t>();
    mesh.r[i] = in.get<double>();
    mesh.z[i] = in.get<double>();
  }
  mesh.faces.resize(in.count(face_bytes, "faces"));
  for (MeshFace& f : mesh.faces) {
    f.tag = in.get<std::uint64_t>();
    f.surface = in.get<std::int32_t>();
    f.count = in.get<std::int32_t>();
    if (f.count != 3 && f.count != 4 && f.count != 6 && f.count != 8 && f.count != 9) {
      in.fail("a face of " + std::to_string(f.count) + " nodes");
    }
    for (int k = 0; k < 9; ++k) f.nodes[static_cast<std::size_t>(k)] = in.node(nodes, k >= f.count);
  }
  const std::size_t curves = in.count(4 + 8, "curves");
  for (std::size_t c = 0; c < curves; ++c) {
    const auto curve = in.get<std::int32_t>();
    std::vector<MeshEdge>& edges = mesh.curves[curve];
    edges.resize(in.count(edge_bytes, "edges"));
    // An edge's node is -1 when no surface element uses it (the importer reports such a curve).
    for (MeshEdge& e : edges) {
      e.a = in.node(nodes, true);
      e.b = in.node(nodes, true);
      e.m = in.node(nodes, true);
    }
  }
  const std::size_t points = in.count(8, "points");
  for (std::size_t p = 0; p < points; ++p) {
    const auto point = in.get<std::int32_t>();
    mesh.points[point] = in.node(nodes, true);
  }
  mesh.groups.resize(in.count(4 + 4 + 8 + 8, "groups"));
  for (PhysicalGroup& g : mesh.groups) {
    g.dim = in.get<std::int32_t>();
    if (g.dim < 0 || g.dim > 3) in.fail("a physical group of dimension " + std::to_string(g.dim));
    g.tag = in.get<std::int32_t>();
    g.name = in.text(in.count(1, "name bytes"));
    g.entities.resize(in.count(4, "entities"));
    for (int& e : g.entities) e = in.get<std::int32_t>();
  }
  in.expect(trailer, "end marker");
  if (!in.done()) in.fail("bytes after the end marker");
  return mesh;
}

std::size_t size_input_limit(std::size_t max_nodes) {
  const std::size_t nodes = size_field_node_factor * max_nodes;
  return size_magic.size() + 16 + nodes * (size_node_bytes + 2 * triangle_bytes) + trailer.size();
}

namespace {

/// The bounds decode_sizes() sets, said the same way whichever side finds them broken.
void check_sizes(const SizeField& f, std::size_t max_nodes, Reader& in) {
  const std::size_t n = f.size.size();
  if (n > size_field_node_factor * max_nodes) {
    in.fail(std::to_string(n) + " nodes, more than " + std::to_string(size_field_node_factor) + " x the limit of " +
            std::to_string(max_nodes) + " nodes");
  }
  if (f.triangles.size() > 2 * size_field_node_factor * max_nodes) {
    in.fail(std::to_string(f.triangles.size()) + " triangles, more than twice its node bound");
  }
  for (std::size_t i = 0; i < n; ++i) {
    if (!std::isfinite(f.x[i]) || !std::isfinite(f.y[i]) || !std::isfinite(f.size[i]) || !(f.size[i] > 0.0)) {
      in.fail("node " + std::to_string(i) + " has the size " + std::to_string(f.size[i]) + " at (" +
              std::to_string(f.x[i]) + ", " + std::to_string(f.y[i]) + "); sizes are finite and > 0");
    }
  }
}

}  // namespace

std::string encode_sizes(const SizeField& field, std::size_t max_nodes) {
  Reader check({}, "the size field is not valid: ");
  if (field.x.size() != field.size.size() || field.y.size() != field.size.size()) {
    check.fail("its coordinates and sizes differ in number");
  }
  check_sizes(field, max_nodes, check);
  Writer w;
  w.bytes(size_magic);
  w.count(field.size.size());
  for (std::size_t i = 0; i < field.size.size(); ++i) {
    w.put(field.x[i]);
    w.put(field.y[i]);
    w.put(field.size[i]);
  }
  w.count(field.triangles.size());
  for (const auto& t : field.triangles) {
    for (const int k : t) {
      if (k < 0 || static_cast<std::size_t>(k) >= field.size.size()) check.fail("a triangle's node index " + std::to_string(k));
      w.put(static_cast<std::int32_t>(k));
    }
  }
  w.bytes(trailer);
  return w.take();
}

SizeField decode_sizes(std::string_view bytes, std::size_t max_nodes) {
  Reader in(bytes, "the size field on the mesher's input is not valid: ");
  if (bytes.size() > size_input_limit(max_nodes)) in.fail(std::to_string(bytes.size()) + " bytes, beyond its bound");
  in.expect(size_magic, "header");
  SizeField f;
  const std::size_t n = in.count(size_node_bytes, "nodes");
  if (n > size_field_node_factor * max_nodes) {
    in.fail(std::to_string(n) + " nodes, more than " + std::to_string(size_field_node_factor) + " x the limit of " +
            std::to_string(max_nodes) + " nodes");
  }
  f.x.resize(n);
  f.y.resize(n);
  f.size.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    f.x[i] = in.get<double>();
    f.y[i] = in.get<double>();
    f.size[i] = in.get<double>();
  }
  f.triangles.resize(in.count(triangle_bytes, "triangles"));
  for (auto& t : f.triangles) {
    for (int& k : t) k = in.node(n, false);
  }
  check_sizes(f, max_nodes, in);
  in.expect(trailer, "end marker");
  if (!in.done()) in.fail("bytes after the end marker");
  return f;
}

}  // namespace saasgaps::io::mesher
