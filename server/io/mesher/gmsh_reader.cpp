// The part of the mesh reader that calls Gmsh. It runs only in saasgaps-mesher, inside its sandbox
// (io/mesher_main.cpp): libgmsh is never loaded into saasgaps itself, which also spares every
// start of saasgaps the quarter CPU second its hundred shared libraries (OpenCASCADE, FLTK, ...)
// take to load.
#include "io/mesher/gmsh_reader.hpp"

#include <gmsh.h>

#include <algorithm>
#include <array>
#include <charconv>
#include <clocale>
#include <cmath>
#include <limits>
#include <map>
#include <sstream>
#include <string>
#include <system_error>
#include <vector>

namespace saasgaps::io {

namespace {

namespace fs = std::filesystem;

// Gmsh element types this reader accepts (gmsh.h: getElementProperties).
constexpr int gmsh_point = 15;
constexpr int gmsh_line = 1;
constexpr int gmsh_line3 = 8;

/// Nodes of a surface element type this reader accepts: 3-node triangle (2), 4-node quadrangle (3),
/// 6-node triangle (9), 8-node quadrangle (16), 9-node quadrangle (10); 0 for any other.
int surface_nodes(int type) {
  switch (type) {
    case 2: return 3;
    case 3: return 4;
    case 9: return 6;
    case 16: return 8;
    case 10: return 9;
    default: return 0;
  }
}

/// Initializes Gmsh quietly and finalizes it on every way out.
class GmshSession {
 public:
  explicit GmshSession(const MeshParameters& parameters) : locale_(std::setlocale(LC_ALL, nullptr)) {
    // No configuration files: the result must not depend on the user's ~/.gmshrc. The parameters
    // as Gmsh's command line takes them (-setnumber NAME VALUE): the parser holds NAME before the
    // file runs, so the file's DefineConstant[NAME = default] keeps it.
    std::vector<std::string> args{"gmsh"};
    for (const auto& [name, value] : parameters) {
      std::array<char, 32> digits{};
      const auto end = std::to_chars(digits.data(), digits.data() + digits.size(), value).ptr;
      args.insert(args.end(), {"-setnumber", name, std::string(digits.data(), end)});
    }
    std::vector<char*> argv;
    for (std::string& a : args) argv.push_back(a.data());
    gmsh::initialize(parameters.empty() ? 0 : static_cast<int>(argv.size()), parameters.empty() ? nullptr : argv.data(),
                     false);
    gmsh::option::setNumber("General.Terminal", 0);
    // Errors are logged, not thrown: an exception thrown from inside Gmsh's .geo parser leaves the
    // parser's input buffer behind, and the next file parsed in this process starts with its rest.
    gmsh::option::setNumber("General.AbortOnError", 0);
    gmsh::logger::start();
  }
  GmshSession(const GmshSession&) = delete;
  GmshSession& operator=(const GmshSession&) = delete;
  ~GmshSession() {
    try {
      gmsh::logger::stop();
      gmsh::finalize();
      // Gmsh sets the process locale from the environment when it starts; give it back.
      std::setlocale(LC_ALL, locale_.c_str());
    } catch (...) {  // NOLINT(bugprone-empty-catch): nothing is left to clean up if finalize fails
    }
  }

 private:
  std::string locale_;  ///< the process locale before Gmsh started
};

std::string element_type_name(int type) {
  std::string name;
  int dim = 0, order = 0, nodes = 0, primary = 0;
  std::vector<double> local;
  gmsh::model::mesh::getElementProperties(type, name, dim, order, nodes, local, primary);
  std::ostringstream text;
  text << '"' << name << "\" (Gmsh type " << type << ", order " << order << ", " << nodes << " nodes)";
  return text.str();
}

/// Node tag -> index into GmshMesh::nodes; Gmsh numbers nodes densely, so a vector serves.
class NodeIndex {
 public:
  explicit NodeIndex(std::size_t max_tag) : index_(max_tag + 1, -1) {}
  int& operator[](std::size_t tag) { return index_[tag]; }
  [[nodiscard]] int find(std::size_t tag) const { return tag < index_.size() ? index_[tag] : -1; }

 private:
  std::vector<int> index_;
};

/// Calls visit(entity, types, element_tags, node_tags) with the elements of every entity of
/// dimension `dim`, grouped by element type as gmsh::model::mesh::getElements gives them.
template <class Visit>
void for_each_entity(int dim, Visit visit) {
  gmsh::vectorpair entities;
  gmsh::model::getEntities(entities, dim);
  std::vector<int> types;
  std::vector<std::vector<std::size_t>> element_tags, node_tags;
  for (const auto& entity : entities) {
    gmsh::model::mesh::getElements(types, element_tags, node_tags, dim, entity.second);
    visit(entity.second, types, element_tags, node_tags);
  }
}

using TagLists = std::vector<std::vector<std::size_t>>;

double twice_signed_area(const GmshMesh& m, const MeshFace& f) {
  double twice = 0.0;  // shoelace formula, over the corners
  const int corners = f.corners();
  for (int k = 0; k < corners; ++k) {
    const auto a = static_cast<std::size_t>(f.nodes[static_cast<std::size_t>(k)]);
    const auto b = static_cast<std::size_t>(f.nodes[static_cast<std::size_t>((k + 1) % corners)]);
    twice += m.r[a] * m.z[b] - m.r[b] * m.z[a];
  }
  return twice;
}

/// The nodes the surfaces of the open model will have once meshed, from the mesh of their boundary
/// curves: a surface of area A (the polygon of its boundary's line elements) meshed with
/// equilateral triangles of side h (the median length of those elements) has 2 A / (sqrt(3) h^2)
/// nodes. The median, not the mean: a boundary graded towards a corner then does not count as fine
/// everywhere. Sizes set only inside a surface (a field) are not seen: the time limit bounds those.
std::size_t estimated_surface_nodes() {
  std::vector<std::size_t> tags;
  std::vector<double> xyz, parametric;
  gmsh::model::mesh::getNodes(tags, xyz, parametric, 1, -1, true, false);
  std::map<std::size_t, std::size_t> at;  // node tag -> position in xyz / 3
  for (std::size_t i = 0; i < tags.size(); ++i) at[tags[i]] = i;
  gmsh::vectorpair surfaces;
  gmsh::model::getEntities(surfaces, 2);
  double nodes = 0.0;
  for (const auto& surface : surfaces) {
    gmsh::vectorpair curves;
    gmsh::model::getBoundary({surface}, curves, false, true, false);
    double twice_area = 0.0;
    std::vector<double> lengths;
    for (const auto& [dim, signed_curve] : curves) {
      std::vector<int> types;
      std::vector<std::vector<std::size_t>> elements, nodes_of;
      gmsh::model::mesh::getElements(types, elements, nodes_of, 1, std::abs(signed_curve));
      for (std::size_t t = 0; t < types.size(); ++t) {
        if (types[t] != gmsh_line) continue;
        for (std::size_t e = 0; e + 1 < nodes_of[t].size(); e += 2) {
          const auto a = at.find(nodes_of[t][e]), b = at.find(nodes_of[t][e + 1]);
          if (a == at.end() || b == at.end()) continue;
          const double xa = xyz[3 * a->second], ya = xyz[3 * a->second + 1];
          const double xb = xyz[3 * b->second], yb = xyz[3 * b->second + 1];
          twice_area += (signed_curve > 0 ? 1.0 : -1.0) * (xa * yb - xb * ya);
          lengths.push_back(std::hypot(xb - xa, yb - ya));
        }
      }
    }
    if (lengths.empty()) continue;
    std::nth_element(lengths.begin(), lengths.begin() + static_cast<std::ptrdiff_t>(lengths.size() / 2), lengths.end());
    const double h = lengths[lengths.size() / 2];
    if (h > 0.0) nodes += std::fabs(twice_area) / (std::sqrt(3.0) * h * h);
  }
  return nodes >= 1e18 ? std::size_t{1000000000000000000} : static_cast<std::size_t>(nodes);
}

/// Throws the first error Gmsh logged (file syntax, meshing), if any.
void throw_logged_error(const fs::path& path) {
  std::vector<std::string> log;
  gmsh::logger::get(log);
  for (const std::string& line : log) {
    if (line.starts_with("Error: ")) throw MeshError("Gmsh cannot read " + path.string() + ": " + line.substr(7));
  }
}

GmshMesh read_open_model(const fs::path& path, std::size_t max_nodes, int order) {
  throw_logged_error(path);
  GmshMesh mesh;
  std::vector<int> types;
  gmsh::model::mesh::getElementTypes(types, 3);
  if (!types.empty()) {
    throw MeshError(path.string() + " holds 3D elements (" + element_type_name(types.front()) +
                    "); an assembly is a 2D mesh in the plane z = 0");
  }
  gmsh::model::mesh::getElementTypes(types, 2);
  if (types.empty() && path.extension() == ".geo") {
    // The curves first: their mesh tells, before the costly surfaces are meshed, whether a small
    // file asks for millions of nodes. (generate(2) would mesh them the same way itself.)
    gmsh::model::mesh::generate(1);
    throw_logged_error(path);
    if (const std::size_t estimate = estimated_surface_nodes(); estimate > 2 * max_nodes) {
      throw MeshTooLarge(path.string() + " would mesh to about " + std::to_string(estimate) +
                         " nodes (estimated from the mesh of its curves), more than the limit of " +
                         std::to_string(max_nodes) + " nodes");
    }
    if (order == 1 || order == 2) {
      // After the file's own options: the assembly's order wins. Second-order nodes on the curves.
      gmsh::option::setNumber("Mesh.ElementOrder", order);
      if (order == 2) gmsh::option::setNumber("Mesh.SecondOrderLinear", 0);
    }
    gmsh::model::mesh::generate(2);
    throw_logged_error(path);
    gmsh::model::mesh::getElementTypes(types, 2);
  }
  if (types.empty()) {
    throw MeshError(path.string() + " holds no surface elements (triangles or quadrilaterals); mesh it in 2D (or "
                    "give the .geo file, which is meshed here)");
  }
  for (const int type : types) {
    if (surface_nodes(type) == 0) {
      throw MeshError(path.string() + " holds surface elements of type " + element_type_name(type) +
                      "; only triangles of 3 or 6 nodes and quadrilaterals of 4, 8 or 9 nodes can be used: mesh "
                      "with Mesh.ElementOrder = 1 or 2");
    }
  }

  // All nodes, then the ones surface elements use, in Gmsh's tag order.
  std::vector<std::size_t> all_tags;
  std::vector<double> xyz, parametric;
  gmsh::model::mesh::getNodes(all_tags, xyz, parametric, -1, -1, false, false);
  const std::size_t max_tag = all_tags.empty() ? 0 : *std::max_element(all_tags.begin(), all_tags.end());
  if (max_tag > static_cast<std::size_t>(std::numeric_limits<int>::max())) {
    throw MeshError(path.string() + " has node tag " + std::to_string(max_tag) +
                    ", beyond the largest node id a model allows (2147483647); renumber the mesh");
  }
  std::vector<std::size_t> position(max_tag + 1, 0);  // tag -> position in all_tags
  for (std::size_t i = 0; i < all_tags.size(); ++i) position[all_tags[i]] = i;

  // Surface elements first (node tags), then their nodes indexed in increasing tag order, so the
  // model lists nodes as Gmsh numbers them.
  struct RawFace {
    MeshFace face;
    std::array<std::size_t, 9> tags{};
  };
  std::vector<RawFace> raw;
  std::vector<char> used(max_tag + 1, 0);
  for_each_entity(2, [&](int surface, const std::vector<int>& element_types, const TagLists& element_tags,
                         const TagLists& node_tags) {
    for (std::size_t t = 0; t < element_types.size(); ++t) {
      const int count = surface_nodes(element_types[t]);
      for (std::size_t e = 0; e < element_tags[t].size(); ++e) {
        RawFace f;
        f.face.tag = element_tags[t][e];
        f.face.surface = surface;
        f.face.count = count;
        for (std::size_t k = 0; k < static_cast<std::size_t>(count); ++k) {
          f.tags[k] = node_tags[t][e * static_cast<std::size_t>(count) + k];
          used[f.tags[k]] = 1;
        }
        raw.push_back(f);
      }
    }
  });
  if (const auto nodes = static_cast<std::size_t>(std::count(used.begin(), used.end(), 1)); nodes > max_nodes) {
    throw MeshTooLarge(path.string() + " meshes to " + std::to_string(nodes) + " nodes, more than the limit of " +
                       std::to_string(max_nodes) + " nodes");
  }
  NodeIndex index(max_tag);
  for (std::size_t tag = 0; tag <= max_tag; ++tag) {
    if (!used[tag]) continue;
    index[tag] = static_cast<int>(mesh.node_tags.size());
    mesh.node_tags.push_back(tag);
    mesh.r.push_back(xyz[3 * position[tag]]);
    mesh.z.push_back(xyz[3 * position[tag] + 1]);
  }
  mesh.faces.reserve(raw.size());
  for (RawFace& f : raw) {
    for (std::size_t k = 0; k < static_cast<std::size_t>(f.face.count); ++k) f.face.nodes[k] = index[f.tags[k]];
    mesh.faces.push_back(f.face);
  }

  // The plane z = 0, to round-off of the mesh's own size.
  double extent = 0.0;
  for (std::size_t i = 0; i < mesh.node_tags.size(); ++i) {
    extent = std::max({extent, std::fabs(mesh.r[i]), std::fabs(mesh.z[i])});
  }
  const double plane_tolerance = 1e-9 * std::max(extent, 1.0);
  std::size_t off_plane = 0;
  std::size_t first_off = 0;
  for (std::size_t i = 0; i < mesh.node_tags.size(); ++i) {
    const double z = xyz[3 * position[mesh.node_tags[i]] + 2];
    if (std::fabs(z) > plane_tolerance && off_plane++ == 0) first_off = i;
  }
  if (off_plane > 0) {
    std::ostringstream text;
    text << path.string() << ": " << off_plane << " node(s) of the surface mesh lie outside the plane z = 0, "
         << "first node " << mesh.node_tags[first_off] << " at (" << xyz[3 * position[mesh.node_tags[first_off]]]
         << ", " << xyz[3 * position[mesh.node_tags[first_off]] + 1] << ", "
         << xyz[3 * position[mesh.node_tags[first_off]] + 2]
         << "); draw the section in the plane z = 0 (Gmsh x is r, y is z)";
    throw MeshError(text.str());
  }

  // Counter-clockwise in (r, z): Gmsh orients elements by the surface normal, which may be -z.
  // Reversed, corners (0, 1, ..., n-1) become (0, n-1, ..., 1), so the edges run in the opposite
  // order and their mid-side nodes reverse too; a quad9's centre stays last.
  for (MeshFace& f : mesh.faces) {
    if (twice_signed_area(mesh, f) < 0.0) {
      const int corners = f.corners();
      std::reverse(f.nodes.begin() + 1, f.nodes.begin() + corners);
      if (f.count > corners) std::reverse(f.nodes.begin() + corners, f.nodes.begin() + 2 * corners);
    }
  }

  for_each_entity(1, [&](int curve, const std::vector<int>& element_types, const TagLists& element_tags,
                         const TagLists& node_tags) {
    std::vector<MeshEdge>& edges = mesh.curves[curve];
    for (std::size_t t = 0; t < element_types.size(); ++t) {
      if (element_types[t] != gmsh_line && element_types[t] != gmsh_line3) {
        throw MeshError(path.string() + ": curve " + std::to_string(curve) + " holds line elements of type " +
                        element_type_name(element_types[t]) + "; only lines of 2 or 3 nodes can be used");
      }
      // A 3-node line lists its ends, then its mid-side node.
      const std::size_t n = element_types[t] == gmsh_line ? 2 : 3;
      for (std::size_t e = 0; e < element_tags[t].size(); ++e) {
        edges.push_back({index.find(node_tags[t][n * e]), index.find(node_tags[t][n * e + 1]),
                         n == 3 ? index.find(node_tags[t][n * e + 2]) : -1});
      }
    }
  });
  for_each_entity(0, [&](int point, const std::vector<int>& element_types, const TagLists&, const TagLists& node_tags) {
    for (std::size_t t = 0; t < element_types.size(); ++t) {
      if (element_types[t] == gmsh_point && !node_tags[t].empty()) mesh.points[point] = index.find(node_tags[t][0]);
    }
  });

  gmsh::vectorpair groups;
  gmsh::model::getPhysicalGroups(groups);
  for (const auto& [dim, tag] : groups) {
    PhysicalGroup g;
    g.dim = dim;
    g.tag = tag;
    gmsh::model::getPhysicalName(dim, tag, g.name);
    gmsh::model::getEntitiesForPhysicalGroup(dim, tag, g.entities);
    mesh.groups.push_back(std::move(g));
  }
  return mesh;
}

/// The size field as the background mesh size: a view of "ST" list data (one scalar triangle per
/// triangle: 3 x, 3 y, 3 z, 3 values) used by a PostView field. Any mesh the geometry made itself is
/// cleared; sizes from points, curvature and the boundary are off, so the field alone decides
/// (a transfinite curve or surface still keeps its own node count).
void use_size_field(const SizeField& f) {
  gmsh::model::mesh::clear();
  std::vector<double> data;
  data.reserve(f.triangles.size() * 12);
  for (const auto& t : f.triangles) {
    for (const int k : t) data.push_back(f.x[static_cast<std::size_t>(k)]);
    for (const int k : t) data.push_back(f.y[static_cast<std::size_t>(k)]);
    for (int i = 0; i < 3; ++i) data.push_back(0.0);
    for (const int k : t) data.push_back(f.size[static_cast<std::size_t>(k)]);
  }
  const int view = gmsh::view::add("sizes");
  gmsh::view::addListData(view, "ST", static_cast<int>(f.triangles.size()), data);
  const int field = gmsh::model::mesh::field::add("PostView");
  gmsh::model::mesh::field::setNumber(field, "ViewTag", view);
  gmsh::model::mesh::field::setAsBackgroundMesh(field);
  gmsh::option::setNumber("Mesh.MeshSizeExtendFromBoundary", 0);
  gmsh::option::setNumber("Mesh.MeshSizeFromPoints", 0);
  gmsh::option::setNumber("Mesh.MeshSizeFromCurvature", 0);
  // A point the view does not cover (on a curved boundary, a little outside the previous mesh's
  // chords, beyond the search tolerance) takes the largest size asked for, not Gmsh's 1e22.
  if (!f.size.empty()) {
    gmsh::option::setNumber("Mesh.MeshSizeMax", *std::max_element(f.size.begin(), f.size.end()));
  }
}

/// Gmsh 4.8 throws std::string (or std::exception) from its API; its last error says more.
std::string gmsh_failure(const std::string& thrown) {
  std::string last;
  try {
    gmsh::logger::getLastError(last);
  } catch (...) {
    last.clear();
  }
  return last.empty() || last == thrown ? thrown : thrown + " (" + last + ")";
}

}  // namespace

GmshMesh read_with_gmsh(const fs::path& file, const fs::path& path, std::size_t max_nodes, int order,
                        const SizeField* sizes, const MeshParameters& parameters) {
  std::error_code ec;
  if (!fs::is_regular_file(file, ec)) {
    throw MeshError("mesh file " + path.string() + " does not exist or is not a regular file");
  }
  try {
    const GmshSession session(parameters);
    gmsh::open(file.string());
    if (sizes != nullptr) use_size_field(*sizes);
    return read_open_model(path, max_nodes, order);
  } catch (const MeshError&) {
    throw;
  } catch (const std::bad_alloc&) {
    throw;
  } catch (const std::string& thrown) {
    throw MeshError("Gmsh cannot read " + path.string() + ": " + gmsh_failure(thrown));
  } catch (const std::exception& e) {
    throw MeshError("Gmsh cannot read " + path.string() + ": " + gmsh_failure(e.what()));
  } catch (...) {
    throw MeshError("Gmsh cannot read " + path.string() + ": " + gmsh_failure("unknown error"));
  }
}

}  // namespace saasgaps::io
