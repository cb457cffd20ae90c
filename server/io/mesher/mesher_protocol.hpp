#pragma once
/// What the sandboxed mesher (saasgaps-mesher, io/mesher_main.cpp) and the program that starts it
/// (io/gmsh_mesh.cpp) exchange: the command line, the exit codes, and the mesh on the mesher's
/// standard output in a binary form that the parent decodes as hostile input (the mesher runs Gmsh
/// on an untrusted geometry, so whatever it writes may be forged): every count is bounded by the
/// bytes that remain and by the node limit, every node index is checked.
///
/// Encoding (native byte order: the two programs are always built together, on one machine):
///   "SGMESH1\n"
///   u64 n, then n x {u64 tag, f64 r, f64 z}                                   nodes
///   u64 f, then f x {u64 tag, i32 surface, i32 count, 4 x i32 node}          faces
///   u64 c, then c x {i32 curve, u64 e, e x {i32 a, i32 b}}                   curves
///   u64 p, then p x {i32 point, i32 node}                                    points
///   u64 g, then g x {i32 dim, i32 tag, u64 len, len bytes name, u64 k, k x i32 entity}  groups
///   "END\n"
///
/// The size field for re-meshing (SizeField), from the parent on the mesher's standard input
/// (empty input: no size field), decoded by the mesher as bounded input too:
///   "SGSIZE1\n"
///   u64 n, then n x {f64 x, f64 y, f64 size}                                   nodes
///   u64 t, then t x {3 x i32 node}                                             triangles
///   "END\n"

#include <cstddef>
#include <string>
#include <string_view>

#include "io/mesher/gmsh_mesh.hpp"

namespace saasgaps::io::mesher {

/// Exit codes of saasgaps-mesher; any message is on its standard error.
enum Exit : int {
  ok = 0,               ///< the mesh is on standard output
  mesh_error = 2,       ///< not a mesh this program can use (Gmsh's error, 3D, second order, ...)
  too_many_nodes = 3,   ///< the mesh has more nodes than --max-nodes
  no_sandbox = 4,       ///< the sandbox could not be set up: nothing was read
  out_of_memory = 5,    ///< the address-space limit was reached
  usage = 64,           ///< a bad command line
};

/// Bytes the encoding of a mesh within `max_nodes` may take: what the parent reads at most.
std::size_t output_limit(std::size_t max_nodes);

std::string encode(const GmshMesh& mesh);

/// The mesh, or MeshError saying what is wrong with the bytes (truncated, a count beyond what
/// remains or beyond `max_nodes`, a node index out of range); `source` names the file in messages.
GmshMesh decode(std::string_view bytes, std::size_t max_nodes, const std::string& source);

/// The size field's nodes may be at most this many times the node limit (a previous mesh within
/// the limit, its quadratic nodes included), its triangles twice that.
constexpr std::size_t size_field_node_factor = 4;

/// Bytes a size field within `max_nodes` may take: what the mesher reads at most.
std::size_t size_input_limit(std::size_t max_nodes);

/// The size field's encoding; throws MeshError when it passes the bounds decode_sizes() sets (more
/// nodes than size_field_node_factor * max_nodes, a size not finite and > 0, an index out of range).
std::string encode_sizes(const SizeField& field, std::size_t max_nodes);

/// The size field, or MeshError saying what is wrong with the bytes.
SizeField decode_sizes(std::string_view bytes, std::size_t max_nodes);

}  // namespace saasgaps::io::mesher
