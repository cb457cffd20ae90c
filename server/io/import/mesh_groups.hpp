#pragma once
/// A Gmsh mesh seen through its physical groups: groups found by name (with a suggestion when a
/// name is misspelt), the nodes and line elements a group holds, and the solid elements that own
/// each element edge. No JSON: the assembly reader words the problems into its issues.

#include <array>
#include <initializer_list>
#include <string>
#include <string_view>
#include <vector>

#include "io/mesher/gmsh_mesh.hpp"

namespace saasgaps::io {

class MeshGroups {
 public:
  /// Indexes the edges of `mesh`, which must outlive this object.
  explicit MeshGroups(const GmshMesh& mesh);

  /// The group named `name` whose dimension is one of `dims`, or nullptr and a sentence in
  /// `problem`: no such group (the closest name within two edits, then every named group), or a
  /// group of another dimension (`role` "needs" `needs`).
  const PhysicalGroup* find(const std::string& name, std::initializer_list<int> dims, std::string_view role,
                            std::string_view needs, std::string& problem) const;

  /// Node indices of the group's elements (dimension 2), line elements (1) or points (0), sorted and
  /// unique. `off_mesh` is set when some of them belong to no surface element.
  std::vector<int> nodes(const PhysicalGroup& g, bool& off_mesh) const;

  /// The line elements of a curve group, as node index pairs (-1 for a node off the surface mesh).
  std::vector<std::array<int, 2>> edges(const PhysicalGroup& g) const;

  /// The solid elements (positions in GmshMesh::faces) that have the edge a-b: one on the boundary,
  /// two inside, none off the mesh.
  std::vector<int> owners(int a, int b) const;

 private:
  struct EdgeOwner {
    int lo = 0, hi = 0;  ///< the edge's node indices, lo < hi
    int element = 0;
  };
  const GmshMesh& mesh_;
  std::vector<EdgeOwner> owners_;  ///< every element edge, sorted by (lo, hi)
};

}  // namespace saasgaps::io
