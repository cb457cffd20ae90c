#pragma once
/// A 2D mesh read through Gmsh's own C++ API (libgmsh): a `.msh` file opened, or a `.geo` file
/// opened and meshed in-process. Only what an assembly needs: the nodes of the surface elements,
/// first-order triangles and quadrilaterals (counter-clockwise), the line elements of every curve,
/// the node of every meshed point, and the physical groups by name.
///
/// Coordinates: Gmsh x -> r, y -> z; the mesh must lie in the plane z = 0 (Gmsh's z).
///
/// Gmsh keeps its model in global state, so one mesh is read at a time (a process-wide mutex), and
/// every call initializes Gmsh, reads, and finalizes it again. General.Terminal is 0: Gmsh prints
/// nothing; its errors come back as MeshError.
///
/// The calls into Gmsh live in a module, libsaasgaps_gmsh.so (io/gmsh_reader.cpp), opened on the
/// first read: beside the program, in ../lib/saasgaps beside it, where the build put it, or at
/// $SAASGAPS_GMSH_MODULE.

#include <array>
#include <cstddef>
#include <filesystem>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

namespace saasgaps::io {

/// The file is missing, is not a mesh Gmsh can read, or holds a mesh this program cannot use
/// (higher-order or 3D elements, no surface elements, not in the plane z = 0). The message says
/// which and where (node or element tag, element type name).
class MeshError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// A first-order surface element: 3 or 4 node indices (into GmshMesh::node_tags, r, z),
/// counter-clockwise.
struct MeshFace {
  std::size_t tag = 0;  ///< Gmsh element tag
  int surface = 0;      ///< tag of the Gmsh surface entity it is classified on
  int count = 0;        ///< 3 or 4
  std::array<int, 4> nodes{-1, -1, -1, -1};
};

/// A first-order line element of a curve: node indices in the curve's direction.
struct MeshEdge {
  int a = -1;
  int b = -1;
};

/// A physical group: its dimension (0 point, 1 curve, 2 surface) and the entity tags it holds.
struct PhysicalGroup {
  int dim = 0;
  int tag = 0;
  std::string name;  ///< empty when the group has no name
  std::vector<int> entities;
};

struct GmshMesh {
  std::vector<std::size_t> node_tags;  ///< Gmsh node tag of each node (only nodes of surface elements)
  std::vector<double> r;               ///< Gmsh x
  std::vector<double> z;               ///< Gmsh y
  std::vector<MeshFace> faces;
  std::map<int, std::vector<MeshEdge>> curves;  ///< curve entity tag -> its line elements
  std::map<int, int> points;                    ///< point entity tag -> node index (meshed points only)
  std::vector<PhysicalGroup> groups;
};

/// Opens `path` with Gmsh (a `.geo` is meshed in 2D with the options it sets itself) and returns
/// the mesh. Throws MeshError; never lets a Gmsh exception through.
GmshMesh read_gmsh_mesh(const std::filesystem::path& path);

/// "dimension 1 (curve)": the name of a dimension for messages.
std::string dimension_name(int dim);

}  // namespace saasgaps::io
