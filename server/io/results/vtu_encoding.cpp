#include "io/results/vtu_encoding.hpp"

#include <zlib.h>

#include <bit>
#include <charconv>
#include <cstring>
#include <stdexcept>

namespace saasgaps::io {

static_assert(std::endian::native == std::endian::little, "the binary VTU writer copies little-endian memory");

VtuFormat vtu_format(const std::string& name) {
  if (name == "binary") return VtuFormat::binary;
  if (name == "ascii") return VtuFormat::ascii;
  throw std::invalid_argument("a VTU file is 'binary' or 'ascii', not '" + name + "'");
}

namespace {

constexpr std::size_t block_size = 32768;

const char* type_name(const VtuArray& a) {
  switch (a.values.index()) {
    case 0: return "Float64";
    case 1: return "Int32";
    case 2: return "Int64";
    default: return "UInt8";
  }
}

template <typename T>
void append_number(std::string& out, T value) {
  char text[32];
  const auto [end, error] = std::to_chars(text, text + sizeof text, value);
  out.append(text, error == std::errc() ? end : text);
}

void append_ascii(std::string& out, const VtuArray& a) {
  std::visit(
      [&out, &a](const auto& values) {
        for (std::size_t i = 0; i < values.size(); ++i) {
          if (i > 0) out += (i % (8 * static_cast<std::size_t>(a.components)) == 0) ? "\n          " : " ";
          // UInt8 prints as a number, not a character.
          if constexpr (std::is_same_v<typename std::decay_t<decltype(values)>::value_type, std::uint8_t>) {
            append_number(out, static_cast<int>(values[i]));
          } else {
            append_number(out, values[i]);
          }
        }
      },
      a.values);
}

void append_u64(std::string& out, std::uint64_t v) { out.append(reinterpret_cast<const char*>(&v), sizeof v); }

/// VTK's compressed layout of one array (see the header) appended to `out`.
void append_compressed(std::string& out, const VtuArray& a) {
  const auto [data, size] = std::visit(
      [](const auto& values) {
        return std::pair{reinterpret_cast<const unsigned char*>(values.data()),
                         values.size() * sizeof(typename std::decay_t<decltype(values)>::value_type)};
      },
      a.values);
  const std::size_t blocks = (size + block_size - 1) / block_size;
  const std::size_t header_at = out.size();
  append_u64(out, blocks);
  append_u64(out, block_size);
  append_u64(out, size % block_size);
  for (std::size_t b = 0; b < blocks; ++b) append_u64(out, 0);  // the compressed sizes, filled in below
  std::vector<unsigned char> buffer(compressBound(block_size));
  for (std::size_t b = 0; b < blocks; ++b) {
    const std::size_t length = std::min(block_size, size - b * block_size);
    uLongf packed = static_cast<uLongf>(buffer.size());
    if (compress2(buffer.data(), &packed, data + b * block_size, static_cast<uLong>(length), Z_DEFAULT_COMPRESSION) != Z_OK) {
      throw std::runtime_error("zlib could not compress the VTU array " + a.name);
    }
    const std::uint64_t packed_size = packed;
    std::memcpy(out.data() + header_at + (3 + b) * sizeof(std::uint64_t), &packed_size, sizeof packed_size);
    out.append(reinterpret_cast<const char*>(buffer.data()), packed);
  }
}

std::string escape_attribute(const std::string& s) {
  std::string out;
  for (const char c : s) {
    if (c == '"') out += "&quot;";
    else if (c == '&') out += "&amp;";
    else if (c == '<') out += "&lt;";
    else out += c;
  }
  return out;
}

}  // namespace

std::string encode_vtu(const VtuPiece& piece, VtuFormat format) {
  std::string xml, appended;
  const bool binary = format == VtuFormat::binary;
  const auto array = [&](const VtuArray& a) {
    xml += "        <DataArray type=\"" + std::string(type_name(a)) + "\" Name=\"" + escape_attribute(a.name) + "\"";
    if (a.components != 1) xml += " NumberOfComponents=\"" + std::to_string(a.components) + "\"";
    if (binary) {
      xml += " format=\"appended\" offset=\"" + std::to_string(appended.size()) + "\"/>\n";
      append_compressed(appended, a);
    } else {
      xml += " format=\"ascii\">\n          ";
      append_ascii(xml, a);
      xml += "\n        </DataArray>\n";
    }
  };
  std::string comment = piece.comment;
  for (std::size_t at = comment.find("--"); at != std::string::npos; at = comment.find("--")) comment.erase(at, 1);
  xml += "<?xml version=\"1.0\"?>\n<!-- " + comment + " -->\n";
  xml += "<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"LittleEndian\" header_type=\"UInt64\"";
  xml += binary ? " compressor=\"vtkZLibDataCompressor\">\n" : ">\n";
  xml += "  <UnstructuredGrid>\n";
  xml += "    <Piece NumberOfPoints=\"" + std::to_string(piece.points) + "\" NumberOfCells=\"" +
         std::to_string(piece.cells) + "\">\n";
  xml += "      <PointData Scalars=\"" + escape_attribute(piece.active_scalars) + "\" Vectors=\"" +
         escape_attribute(piece.active_vectors) + "\">\n";
  for (const VtuArray& a : piece.point_data) array(a);
  xml += "      </PointData>\n";
  xml += "      <CellData Scalars=\"" + escape_attribute(piece.active_cell_scalars) + "\">\n";
  for (const VtuArray& a : piece.cell_data) array(a);
  xml += "      </CellData>\n      <Points>\n";
  array(piece.coordinates);
  xml += "      </Points>\n      <Cells>\n";
  array(piece.connectivity);
  array(piece.offsets);
  array(piece.types);
  xml += "      </Cells>\n    </Piece>\n  </UnstructuredGrid>\n";
  if (binary) {
    xml += "  <AppendedData encoding=\"raw\">\n   _";
    xml += appended;
    xml += "\n  </AppendedData>\n";
  }
  xml += "</VTKFile>\n";
  return xml;
}

}  // namespace saasgaps::io
