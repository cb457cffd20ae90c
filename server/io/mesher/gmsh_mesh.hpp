#pragma once
/// A 2D mesh read through Gmsh's own C++ API (libgmsh): a `.msh` file opened, or a `.geo` file
/// opened and meshed. Only what an assembly needs: the nodes of the surface elements, triangles and
/// quadrilaterals of the first or second order (3, 4, 6, 8 or 9 nodes, counter-clockwise), the line
/// elements of every curve (2 or 3 nodes), the node of every meshed point, and the physical groups by
/// name.
///
/// Coordinates: Gmsh x -> r, y -> z; the mesh must lie in the plane z = 0 (Gmsh's z).
///
/// A geometry is a program (Gmsh's .geo language runs shell commands, reads and writes files, ends
/// the process), so Gmsh never runs in this process: every read starts saasgaps-mesher
/// (io/mesher_main.cpp), a short-lived process confined to the file's own directory by chroot, a
/// seccomp system-call filter and resource limits (io/mesher_sandbox.hpp), and decodes the mesh it
/// writes as hostile input (io/mesher_protocol.hpp). docs/import.md says why this is safe.
///
/// The mesher is looked for at $SAASGAPS_MESHER, beside the running program, in ../lib/saasgaps
/// beside it (an installation), and where the build put it.

#include <array>
#include <cstddef>
#include <filesystem>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

namespace saasgaps::io {

/// The file is missing, is not a mesh Gmsh can read, or holds a mesh this program cannot use
/// (third-order or 3D elements, no surface elements, not in the plane z = 0). The message says
/// which and where (node or element tag, element type name).
class MeshError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// The mesh is larger than MeshLimits allow (nodes, or the memory meshing needed): the service
/// answers 413. The message names the limit.
class MeshTooLarge : public MeshError {
 public:
  using MeshError::MeshError;
};

/// What one mesh read may cost. The defaults are those docs/import.md gives.
struct MeshLimits {
  std::size_t max_nodes = 200000;          ///< nodes of the mesh (saasgaps serve/import --max-mesh-nodes)
  int seconds = 60;                        ///< wall and CPU time of the mesher (--mesh-time-limit)
  std::size_t memory_bytes = std::size_t{2} << 30;  ///< the mesher's address space
  std::size_t file_bytes = std::size_t{64} << 20;   ///< largest file the geometry may write (Printf)
};

/// Sets the limits of every later read (once, at start-up: `saasgaps serve` and `saasgaps import`).
void set_mesh_limits(const MeshLimits& limits);
MeshLimits mesh_limits();

/// At most this many meshers run at once in a process; further reads wait for one to end.
int concurrent_meshers();

/// A surface element: 3, 4, 6, 8 or 9 node indices (into GmshMesh::node_tags, r, z), the corners
/// counter-clockwise, then the mid-side nodes in the order of the edges, then a quad9's centre
/// (Gmsh's order, which is the model's: docs/elements.md).
struct MeshFace {
  std::size_t tag = 0;  ///< Gmsh element tag
  int surface = 0;      ///< tag of the Gmsh surface entity it is classified on
  int count = 0;        ///< 3, 4, 6, 8 or 9
  std::array<int, 9> nodes{-1, -1, -1, -1, -1, -1, -1, -1, -1};
  /// 3 for triangles, 4 for quadrilaterals.
  [[nodiscard]] int corners() const { return count == 3 || count == 6 ? 3 : 4; }
};

/// A line element of a curve: its end node indices in the curve's direction, and the mid-side node
/// of a second-order (3-node) line (-1 for a 2-node one).
struct MeshEdge {
  int a = -1;
  int b = -1;
  int m = -1;
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

/// A background mesh size for re-meshing a geometry (the adaptive loop, io/import/adapt_sizes.hpp):
/// element sizes (lengths, the model's unit) at the nodes of a triangulation of the previous mesh,
/// interpolated linearly inside each triangle. Gmsh takes it as a post-processing view ("ST" list
/// data) used by a PostView field set as the background mesh; sizes from points, curvature and the
/// boundary are then off, so the field alone decides.
struct SizeField {
  std::vector<double> x, y;   ///< node coordinates (Gmsh x = r, y = z)
  std::vector<double> size;   ///< the element size wanted at each node (> 0, finite)
  std::vector<std::array<int, 3>> triangles;  ///< node indices, any orientation
};

/// Values of a `.geo`'s DefineConstant names (io/mesher/geo_constants.hpp), set in Gmsh's parser
/// before the file runs (as `gmsh -setnumber NAME VALUE` does): {name, value}, names that
/// geo_identifier() takes, finite values.
using MeshParameters = std::map<std::string, double>;

/// Opens `path` with Gmsh in the sandboxed mesher (a `.geo` is meshed in 2D with the options it
/// sets itself, and with `sizes` as its background mesh size when given: only a `.geo`) and returns
/// the mesh. order 1 or 2 meshes a `.geo` with elements of that order whatever it sets
/// (Mesh.ElementOrder; order 2 also Mesh.SecondOrderLinear = 0, so that mid-side nodes lie on the
/// true curves; Mesh.SecondOrderIncomplete stays the file's: 1 for quad8, 0 for quad9); 0 leaves the
/// file's own. Throws MeshTooLarge beyond the limits, MeshError for everything else that goes wrong
/// (the message names the file and, for a limit, the limit). `parameters` (only a `.geo`) are set
/// before the file is parsed.
GmshMesh read_gmsh_mesh(const std::filesystem::path& path, int order = 0, const SizeField* sizes = nullptr,
                        const MeshParameters& parameters = {});

/// "dimension 1 (curve)": the name of a dimension for messages.
std::string dimension_name(int dim);

}  // namespace saasgaps::io
