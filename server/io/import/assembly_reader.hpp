#pragma once
/// The assembly document (schemas/assembly.schema.json, docs/import.md): a Gmsh mesh and, by the
/// names of its physical groups, the materials of its surfaces, the constraints, pressures, forces
/// and temperatures on its curves and points, the pairs of curves that face each other across a
/// gap, and the thermal conditions on its curves and heat sources in its surfaces. import_assembly
/// turns it into a model document (model.schema.json) with generated gap elements or contact
/// surfaces and a thermal section of edges and materials; the analysis, materials, gap settings,
/// solver, output, units and body force blocks pass through unchanged.
///
/// Every problem is an InputIssue located by the JSON Pointer of the assembly value it concerns
/// (the group name, the pair, "/mesh" for the mesh file), thrown together as one ModelError. The
/// model built is checked by the model reader before it is returned: a problem it finds in a block
/// that passed through keeps its pointer (the same in both documents); one in a generated block is
/// reported at "/mesh" with the generated pointer in its text.

#include <filesystem>

#include <nlohmann/json.hpp>

#include "io/mesher/gmsh_mesh.hpp"

namespace saasgaps::io {

/// Which files an assembly may name.
enum class FileAccess {
  anywhere,    ///< any path: relative ones against the base directory (the command line)
  base_only,   ///< only plain file names inside the base directory (uploads to the service)
};

/// Builds the model document. Relative file names (the mesh, a temperature file) are resolved
/// against `base_directory`, the assembly file's own directory. `sizes`, when given, is the
/// background mesh size the `.geo` is re-meshed with (the adaptive loop). Throws ModelError, or
/// MeshTooLarge when the mesh passes the limits of io/mesher/gmsh_mesh.hpp. `mesh_seconds`, when
/// given, receives the time the mesher took.
nlohmann::json import_assembly(const nlohmann::json& assembly, const std::filesystem::path& base_directory,
                               FileAccess access = FileAccess::anywhere, const SizeField* sizes = nullptr,
                               double* mesh_seconds = nullptr);

}  // namespace saasgaps::io
