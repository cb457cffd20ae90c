#pragma once
/// Nodal values (temperatures) written by another program, keyed by node id or by position:
///
/// - CSV: a header row naming the columns, then one row per node. Columns: `node` (or `id`), or the
///   coordinates `x`, `y` (Gmsh's, i.e. r and z; a `z` column beside them must be 0) or `r`, `z`;
///   and the value column (`T` unless told otherwise). Commas separate; blank lines and lines
///   starting with `#` are skipped.
/// - VTU (VTK XML unstructured grid, as thermal codes and ParaView write it): the points of the
///   first piece and one point-data array by name; inline `ascii` or `binary` (base64, UInt32 or
///   UInt64 headers, uncompressed) data. Read with expat, a streaming XML parser: a VTU file of a
///   10^6-node mesh is tens of megabytes and must not be held twice.
///
/// Both throw NodalFileError naming the file and the line (CSV) or element (VTU).

#include <cstddef>
#include <filesystem>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

namespace saasgaps::io {

class NodalFileError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct NodalValues {
  bool by_id = false;              ///< rows name nodes by id (else by position r, z)
  std::vector<long long> ids;      ///< by_id
  std::vector<double> r, z;        ///< !by_id
  std::vector<double> values;
  std::vector<std::size_t> origin;  ///< CSV line number, or VTU point index, of each row
};

NodalValues read_nodal_csv(const std::filesystem::path& path, const std::string& field);

/// Point positions (x -> r, y -> z; the VTU's z must be 0) and the point array `field`.
NodalValues read_vtu_point_field(const std::filesystem::path& path, const std::string& field);

/// The node of each row (an index into node_tags / r / z), -1 where none: by id through
/// `node_tags`, or by position, the nearest node within `tolerance`, looked up in a hash of cells
/// of that size (time linear in nodes + rows).
std::vector<int> match_rows(const NodalValues& values, std::span<const std::size_t> node_tags,
                            std::span<const double> r, std::span<const double> z, double tolerance);

}  // namespace saasgaps::io
