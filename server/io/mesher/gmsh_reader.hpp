#pragma once
/// The calls into Gmsh (libgmsh): linked only into saasgaps-mesher, which makes them inside its
/// sandbox. Gmsh keeps its model in global state: one read per process.

#include <cstddef>
#include <filesystem>

#include "io/mesher/gmsh_mesh.hpp"

namespace saasgaps::io {

/// Opens `file` with Gmsh (a `.geo` is meshed in 2D with the options it sets itself, its element
/// order replaced by `order` when that is 1 or 2: read_gmsh_mesh, and with `sizes` as the background
/// mesh size when given, `parameters` set in Gmsh's parser before the file runs) and returns the
/// mesh; messages name the file as `shown`. Throws
/// MeshTooLarge beyond `max_nodes` nodes, std::bad_alloc when memory runs out, MeshError for anything
/// else (never a Gmsh exception).
GmshMesh read_with_gmsh(const std::filesystem::path& file, const std::filesystem::path& shown, std::size_t max_nodes,
                        int order = 0, const SizeField* sizes = nullptr, const MeshParameters& parameters = {});

}  // namespace saasgaps::io
