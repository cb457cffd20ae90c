#pragma once
/// The assembly importer's state and steps (internal to io; import_assembly in
/// io/import/assembly_reader.hpp is the interface). One Importer reads one assembly document; its
/// methods are defined a concept a file: the entry point, which runs the steps in order
/// (assembly_reader.cpp), the shape checks every section makes (assembly_checks.cpp), the mesh and
/// its physical groups (assembly_mesh.cpp), materials and the regions that give them to the
/// surfaces (assembly_regions.cpp), constraints (assembly_constraints.cpp), loads
/// (assembly_loads.cpp), gap face pairs as gap elements (assembly_gaps.cpp) or as contact surfaces
/// (assembly_contact.cpp), and the thermal section by group (assembly_thermal.cpp). The files an
/// assembly names are AssemblyFiles' (assembly_files.hpp), and the model reader's findings on the
/// generated model find their way back to the assembly through GeneratedOrigins
/// (generated_origins.hpp).

#include <filesystem>
#include <initializer_list>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "io/import/adapt_settings.hpp"
#include "io/import/assembly_files.hpp"
#include "io/import/assembly_reader.hpp"
#include "io/import/gap_generator.hpp"
#include "io/import/generated_origins.hpp"
#include "io/import/mesh_groups.hpp"
#include "io/json/value_rules.hpp"
#include "io/mesher/gmsh_mesh.hpp"
#include "solver/base/errors.hpp"

namespace saasgaps::io::assembly {

using nlohmann::json;
namespace fs = std::filesystem;

/// Which dimensions a use of a group accepts, and how to say it.
struct GroupUse {
  std::initializer_list<int> dims;
  const char* role;   ///< "a region", "a pressure"...
  const char* needs;  ///< "a surface (dimension 2)"
};

class Importer {
 public:
  Importer(const json& assembly, fs::path base, FileAccess access, const SizeField* sizes = nullptr)
      : doc_(assembly), files_(std::move(base), access), sizes_(sizes) {}

  json run();
  /// Seconds the mesher took (read_gmsh_mesh), once run.
  [[nodiscard]] double mesh_seconds() const { return mesh_seconds_; }

 private:
  void report(std::string pointer, std::string detail) {
    issues_.push_back({std::move(pointer), files_.as_named(std::move(detail))});
  }
  /// report() as a callable, for the shared checks of value_rules.hpp.
  auto reporter() {
    return [this](const std::string& pointer, std::string detail) { report(pointer, std::move(detail)); };
  }

  // ---- shape checks, and the files values name (assembly_checks.cpp)
  bool object(const json& v, const std::string& p, std::initializer_list<std::string_view> required,
              std::initializer_list<std::string_view> optional);
  /// parent[key] when it is an array (non-empty if asked); nullptr when absent (object() reports a
  /// missing required key) or reported.
  const json* array(const json& parent, const std::string& p, std::string_view key, bool non_empty);
  std::optional<double> number(const json& o, const std::string& p, std::string_view key,
                               const Range& range = any_number);
  std::optional<std::string> string(const json& o, const std::string& p, std::string_view key);
  /// The file `name` (the value at `pointer`) names, or nullopt (reported) when it may not be read.
  std::optional<fs::path> resolve_file(const std::string& name, const std::string& pointer);

  // ---- the mesh and its groups (assembly_mesh.cpp)
  void load_mesh();
  /// /mesh_parameters: values of DefineConstant names the `.geo` at `path` declares, set before it
  /// is meshed; nullopt when one is not (reported at /mesh_parameters/NAME).
  std::optional<MeshParameters> mesh_parameters(const fs::path& path);
  /// What `adapt` needs of the mesh: a `.geo` file to re-mesh, and a first mesh within max_nodes.
  void adapt_mesh(const AdaptSettings& adapt);
  /// The mesh's nodes as the model's, by their Gmsh tags.
  void nodes(json& model) const;
  /// The largest |r| or |z| of the mesh's nodes: the scale of round-off and of position tolerances.
  double extent() const;
  /// The group o["group"] names (reported at <p>/group when missing, misspelt or of the wrong dimension).
  const PhysicalGroup* group(const json& o, const std::string& p, const GroupUse& use);
  const PhysicalGroup* named_group(const json& name, const std::string& at, const GroupUse& use);
  /// Node indices of a group (sorted, unique); reports nodes that no surface element uses.
  std::vector<int> group_nodes(const PhysicalGroup& g, const std::string& p);
  int tag_of(int node) const { return static_cast<int>(mesh_.node_tags[static_cast<std::size_t>(node)]); }
  /// A boundary edge of a curve group: its node indices in the counter-clockwise order of the one
  /// solid element (its position in GmshMesh::faces) that has it.
  struct BoundaryEdge {
    int a = -1, b = -1;
    int owner = -1;
  };
  /// The line elements of curve group g as boundary edges, or nullopt (reported at <p>/group, for
  /// `use` "a pressure", "a thermal boundary condition") when one lies inside the mesh or off it, or
  /// there are none.
  std::optional<std::vector<BoundaryEdge>> boundary_edges(const PhysicalGroup& g, const std::string& p,
                                                          std::string_view use);

  // ---- materials and regions (assembly_regions.cpp)
  /// The ids of /materials, which regions and thermal sources name.
  void read_material_ids();
  void regions(json& model);

  // ---- constraints (assembly_constraints.cpp)
  void constraints(json& model);

  // ---- loads (assembly_loads.cpp)
  void loads(json& model);
  /// A loads object (at p) as the model's, or nullopt when it is no object (reported).
  std::optional<json> converted_loads(const json& loads, const std::string& p);

  // ---- load steps (assembly_steps.cpp) and the named sets of the groups used (assembly_sets.cpp)
  void steps(json& model);
  void sets(json& model) const;
  void pressures(const json& loads, const std::string& p, json& out);
  void nodal_forces(const json& loads, const std::string& p, json& out);
  void temperatures(const json& loads, const std::string& p, json& out);
  void temperature_file(const json& file, const std::string& p, std::vector<std::optional<double>>& T,
                        std::vector<std::string>& source);

  // ---- gap face pairs (assembly_gaps.cpp) and contact surfaces (assembly_contact.cpp)
  void gaps(json& model);
  /// Whether face pair o (at p) is an object; a key of `foreign`, which belongs to the other method,
  /// is reported with `why` after its name.
  bool pair_keys(const json& o, const std::string& p, std::initializer_list<const char*> foreign, std::string_view why);
  /// o["faces"] when it is an array of two; nullptr when absent (object() reports it) or reported.
  const json* pair_faces(const json& o, const std::string& p);
  /// The face pairs as gap elements, appended to `elements`.
  void gap_elements(const json& pairs, json& elements);
  std::optional<FaceChain> face(const json& name, const std::string& p);
  /// The face pairs of gaps.method "exact" as the model's contact pairs and their surfaces.
  void contact_pairs(const json& pairs, json& model);
  /// An exact face pair {faces: [A, B], friction?, conductance?} (its faces at p) as a contact pair of
  /// two surfaces in `contact`.
  void contact_pair(const json& pair, const std::string& p, json& contact);
  /// Index in contact["surfaces"] of the surface made of curve group `name` (at p), defined on first use.
  std::optional<std::size_t> contact_surface(const json& name, const std::string& p, json& contact);

  // ---- thermal (assembly_thermal.cpp): the model's section with boundary conditions on curve
  // groups and sources on surface groups
  void thermal(json& model);
  void thermal_boundary(const json& list, const std::string& p, json& out);
  void thermal_sources(const json& list, const std::string& p, json& out);

  const json& doc_;
  AssemblyFiles files_;
  const SizeField* sizes_ = nullptr;  ///< the background mesh size of a re-mesh, or none
  double mesh_seconds_ = 0.0;
  std::vector<InputIssue> issues_;
  GmshMesh mesh_;
  bool mesh_loaded_ = false;
  std::vector<Vec2> positions_;
  std::vector<int> ids_;
  std::optional<MeshGroups> groups_;  ///< once the mesh is loaded
  std::set<int> material_ids_;
  std::map<int, int> surface_material_;  ///< Gmsh surface tag -> material id, from regions
  std::map<std::string, const PhysicalGroup*> used_groups_;  ///< every named group a value names, by name
  GeneratedOrigins origins_;
};

}  // namespace saasgaps::io::assembly
