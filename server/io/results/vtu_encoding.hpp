#pragma once
/// The VTK XML unstructured-grid file format (.vtu), one piece, with its data arrays encoded either
///   binary (the default): every array in one <AppendedData encoding="raw"> block after the XML,
///     each zlib-compressed in blocks of 32 KiB with VTK's header in front of it: UInt64 values
///     [number of blocks, block size, size of the last block (0 when it is full), compressed size
///     of each block], then the compressed blocks; the <DataArray> names its offset into the block.
///     Little-endian, as the file says (byte_order). About a fifth of the ASCII size for results,
///     and read without parsing text.
///   ascii: numbers as text inside each <DataArray>, shortest form that reads back to the same
///     double, for reading with a text editor.
/// Both carry the same values bit for bit.

#include <cstdint>
#include <string>
#include <variant>
#include <vector>

namespace saasgaps::io {

enum class VtuFormat { binary, ascii };

/// "binary" or "ascii"; anything else: std::invalid_argument.
VtuFormat vtu_format(const std::string& name);

struct VtuArray {
  std::string name;
  int components = 1;
  /// Float64, Int32, Int64 or UInt8 values, components interleaved.
  std::variant<std::vector<double>, std::vector<std::int32_t>, std::vector<std::int64_t>, std::vector<std::uint8_t>>
      values;
};

struct VtuPiece {
  std::size_t points = 0;
  std::size_t cells = 0;
  std::string comment;  ///< an XML comment after the declaration ("--" is removed)
  std::string active_scalars, active_vectors, active_cell_scalars;
  std::vector<VtuArray> point_data;
  std::vector<VtuArray> cell_data;
  VtuArray coordinates;                 ///< 3 components per point
  VtuArray connectivity, offsets, types;
};

/// The file's bytes.
std::string encode_vtu(const VtuPiece& piece, VtuFormat format);

}  // namespace saasgaps::io
