#include "io/import/nodal_values_file.hpp"

#include <expat.h>

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <map>
#include <memory>
#include <numeric>
#include <optional>
#include <unordered_map>
#include <cctype>
#include <exception>

namespace saasgaps::io {

namespace {

namespace fs = std::filesystem;

std::string_view trim(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t' || s.front() == '\r')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\r')) s.remove_suffix(1);
  return s;
}

std::vector<std::string_view> split_commas(std::string_view line) {
  std::vector<std::string_view> cells;
  for (;;) {
    const auto comma = line.find(',');
    cells.push_back(trim(line.substr(0, comma)));
    if (comma == std::string_view::npos) return cells;
    line.remove_prefix(comma + 1);
  }
}

std::optional<double> parse_double(std::string_view text) {
  double v = 0.0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
  if (ec != std::errc() || end != text.data() + text.size() || !std::isfinite(v)) return std::nullopt;
  return v;
}

/// One line of a CSV file in error.
[[noreturn]] void csv_error(const fs::path& path, std::size_t line, const std::string& what) {
  throw NodalFileError(path.string() + ", line " + std::to_string(line) + ": " + what);
}

}  // namespace

NodalValues read_nodal_csv(const fs::path& path, const std::string& field) {
  std::ifstream in(path);
  if (!in) throw NodalFileError("cannot read the nodal values file " + path.string());
  NodalValues out;
  std::map<std::string, std::size_t, std::less<>> column;  // header name -> column
  std::size_t width = 0;
  std::string line;
  std::size_t number = 0;
  while (std::getline(in, line)) {
    ++number;
    const std::string_view text = trim(line);
    if (text.empty() || text.front() == '#') continue;
    const auto cells = split_commas(text);
    if (column.empty()) {
      for (std::size_t c = 0; c < cells.size(); ++c) column.emplace(std::string(cells[c]), c);
      width = cells.size();
      const auto has = [&](const char* name) { return column.contains(name); };
      if (!has(field.c_str())) {
        csv_error(path, number, "the header names no column \"" + field + "\" for the values");
      }
      out.by_id = has("node") || has("id");
      const bool xy = has("x") && has("y");
      const bool rz = has("r") && has("z") && !has("x");
      if (!out.by_id && !xy && !rz) {
        csv_error(path, number, "the header must name the node (a column node or id) or its position (columns x, y "
                                "or r, z)");
      }
      continue;
    }
    if (cells.size() != width) {
      csv_error(path, number, "has " + std::to_string(cells.size()) + " values; the header names " +
                                  std::to_string(width) + " columns");
    }
    const auto value_at = [&](const std::string& name) {
      const std::string_view cell = cells[column.find(name)->second];
      const auto v = parse_double(cell);
      if (!v) csv_error(path, number, name + " = \"" + std::string(cell) + "\" is not a finite number");
      return *v;
    };
    out.values.push_back(value_at(field));
    out.origin.push_back(number);
    if (out.by_id) {
      const std::string key = column.contains("node") ? "node" : "id";
      const double id = value_at(key);
      if (id != std::floor(id) || id < 1 || id > 2147483647.0) {
        csv_error(path, number, key + " = " + std::string(cells[column.find(key)->second]) +
                                    " is not a node id (a positive integer)");
      }
      out.ids.push_back(static_cast<long long>(id));
    } else if (column.contains("x")) {
      out.r.push_back(value_at("x"));
      out.z.push_back(value_at("y"));
      if (column.contains("z") && value_at("z") != 0.0) {
        csv_error(path, number, "z = " + std::string(cells[column.find("z")->second]) +
                                    ": the mesh lies in the plane z = 0 (x is r, y is z)");
      }
    } else {
      out.r.push_back(value_at("r"));
      out.z.push_back(value_at("z"));
    }
  }
  if (column.empty()) throw NodalFileError(path.string() + " has no header row");
  if (out.values.empty()) throw NodalFileError(path.string() + " has a header but no values");
  return out;
}

std::vector<int> match_rows(const NodalValues& values, std::span<const std::size_t> node_tags,
                            std::span<const double> r, std::span<const double> z, double tolerance) {
  std::vector<int> node(values.values.size(), -1);
  if (values.by_id) {
    std::unordered_map<long long, int> by_tag;
    for (std::size_t n = 0; n < node_tags.size(); ++n) by_tag[static_cast<long long>(node_tags[n])] = static_cast<int>(n);
    for (std::size_t row = 0; row < node.size(); ++row) {
      const auto found = by_tag.find(values.ids[row]);
      if (found != by_tag.end()) node[row] = found->second;
    }
    return node;
  }
  // Nodes hashed by the cell of size `tolerance` they fall in; a row looks in the 3 x 3 cells
  // around its own, so every node within the tolerance is seen. Colliding keys only add candidates.
  const auto cell = [&](double v) { return static_cast<long long>(std::floor(v / tolerance)); };
  const auto key = [](long long i, long long j) { return i * 73856093LL ^ j * 19349663LL; };
  std::unordered_map<long long, std::vector<int>> cells;
  for (std::size_t n = 0; n < r.size(); ++n) cells[key(cell(r[n]), cell(z[n]))].push_back(static_cast<int>(n));
  for (std::size_t row = 0; row < node.size(); ++row) {
    double best = tolerance;
    for (long long di = -1; di <= 1; ++di) {
      for (long long dj = -1; dj <= 1; ++dj) {
        const auto c = cells.find(key(cell(values.r[row]) + di, cell(values.z[row]) + dj));
        if (c == cells.end()) continue;
        for (const int n : c->second) {
          const double d = std::hypot(r[static_cast<std::size_t>(n)] - values.r[row], z[static_cast<std::size_t>(n)] - values.z[row]);
          if (d <= best) {
            best = d;
            node[row] = n;
          }
        }
      }
    }
  }
  return node;
}

// ------------------------------------------------------------------------------------------------
// VTU

namespace {

/// Base64 (RFC 4648) that starts afresh after padding: VTK writers encode the block header and the
/// data separately and concatenate the two texts.
std::vector<unsigned char> decode_base64(std::string_view text) {
  static const std::array<int, 256> value = [] {
    std::array<int, 256> v{};
    v.fill(-1);
    const char* alphabet = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    for (int i = 0; i < 64; ++i) v[static_cast<unsigned char>(alphabet[i])] = i;
    return v;
  }();
  std::vector<unsigned char> out;
  out.reserve(text.size() / 4 * 3);
  std::uint32_t bits = 0;
  int count = 0;
  for (const char c : text) {
    if (c == '=') {
      // Padding ends a quantum: flush the whole bytes it holds and start afresh.
      if (count == 2) out.push_back(static_cast<unsigned char>(bits >> 4));
      if (count == 3) {
        out.push_back(static_cast<unsigned char>(bits >> 10));
        out.push_back(static_cast<unsigned char>(bits >> 2));
      }
      bits = 0;
      count = 0;
      continue;
    }
    const int v = value[static_cast<unsigned char>(c)];
    if (v < 0) continue;  // whitespace between chunks
    bits = (bits << 6) | static_cast<std::uint32_t>(v);
    if (++count == 4) {
      out.push_back(static_cast<unsigned char>(bits >> 16));
      out.push_back(static_cast<unsigned char>(bits >> 8));
      out.push_back(static_cast<unsigned char>(bits));
      bits = 0;
      count = 0;
    }
  }
  return out;
}

struct DataArray {
  std::string type;    ///< Float32 | Float64 | Int32 | Int64 ...
  std::string format;  ///< ascii | binary | appended
  int components = 1;
  std::string text;    ///< the character data
};

/// Walks the XML with expat, keeping the text of the points array and of the wanted point array of
/// the first piece.
class VtuScanner {
 public:
  VtuScanner(const fs::path& path, std::string field) : path_(path), field_(std::move(field)) {}

  void start(const char* name, const char** attributes) {
    const std::string element = name;
    std::map<std::string, std::string> attr;
    for (const char** a = attributes; a[0] != nullptr; a += 2) attr[a[0]] = a[1];
    if (element == "VTKFile") {
      if (attr["type"] != "UnstructuredGrid") fail("is a VTK file of type \"" + attr["type"] + "\", not UnstructuredGrid");
      if (attr.contains("compressor")) {
        fail("is compressed (" + attr["compressor"] + "); write it uncompressed (ascii or binary) for import");
      }
      if (attr.contains("byte_order") && attr["byte_order"] != "LittleEndian") fail("is big-endian");
      uint64_header_ = attr["header_type"] == "UInt64";
    } else if (element == "Piece") {
      ++pieces_;
    } else if (pieces_ == 1 && element == "Points") {
      in_points_ = true;
    } else if (pieces_ == 1 && element == "PointData") {
      in_point_data_ = true;
    } else if (element == "DataArray" && (in_points_ || (in_point_data_ && attr["Name"] == field_))) {
      current_ = in_points_ ? &points_ : &field_data_.emplace();
      current_->type = attr["type"];
      current_->format = attr["format"];
      if (attr.contains("NumberOfComponents")) current_->components = std::atoi(attr["NumberOfComponents"].c_str());
      if (current_->format != "ascii" && current_->format != "binary") {
        fail("stores array \"" + (in_points_ ? std::string("Points") : field_) + "\" as \"" + current_->format +
             "\"; write inline ascii or binary data for import");
      }
    }
  }
  void end(const char* name) {
    const std::string element = name;
    if (element == "Points") in_points_ = false;
    if (element == "PointData") in_point_data_ = false;
    if (element == "DataArray") current_ = nullptr;
  }
  void text(const char* s, int length) {
    if (current_ != nullptr) current_->text.append(s, static_cast<std::size_t>(length));
  }

  NodalValues result() {
    if (points_.type.empty()) fail("has no Points array");
    if (!field_data_) fail("has no point data array named \"" + field_ + "\"");
    if (points_.components != 3) fail("has points with " + std::to_string(points_.components) + " components, not 3");
    const std::vector<double> xyz = numbers(points_, "Points");
    const std::vector<double> t = numbers(*field_data_, field_);
    if (field_data_->components != 1 || t.size() * 3 != xyz.size()) {
      fail("point array \"" + field_ + "\" has " + std::to_string(t.size()) + " values for " +
           std::to_string(xyz.size() / 3) + " points; it must have one per point");
    }
    NodalValues out;
    const double extent = std::transform_reduce(xyz.begin(), xyz.end(), 1.0, [](double a, double b) { return std::max(a, b); },
                                                [](double v) { return std::fabs(v); });
    for (std::size_t i = 0; i < t.size(); ++i) {
      if (std::fabs(xyz[3 * i + 2]) > 1e-9 * extent) {
        fail("point " + std::to_string(i) + " lies at z = " + std::to_string(xyz[3 * i + 2]) +
             "; the mesh lies in the plane z = 0 (x is r, y is z)");
      }
      out.r.push_back(xyz[3 * i]);
      out.z.push_back(xyz[3 * i + 1]);
      out.values.push_back(t[i]);
      out.origin.push_back(i);
    }
    return out;
  }

  [[noreturn]] void fail(const std::string& what) const { throw NodalFileError(path_.string() + " " + what); }

 private:
  std::vector<double> numbers(const DataArray& a, const std::string& name) const {
    std::vector<double> out;
    if (a.format == "ascii") {
      const char* p = a.text.data();
      const char* end = p + a.text.size();
      while (p < end) {
        while (p < end && std::isspace(static_cast<unsigned char>(*p))) ++p;
        if (p == end) break;
        double v = 0.0;
        const auto [next, ec] = std::from_chars(p, end, v);
        if (ec != std::errc() || !std::isfinite(v)) fail("array \"" + name + "\" holds text that is not a finite number");
        out.push_back(v);
        p = next;
      }
      return out;
    }
    const std::vector<unsigned char> bytes = decode_base64(a.text);
    const std::size_t header = uint64_header_ ? 8 : 4;
    if (bytes.size() < header) fail("array \"" + name + "\" has no binary block header");
    std::uint64_t length = 0;
    std::memcpy(&length, bytes.data(), header);  // little-endian host, as checked
    const std::size_t size = a.type == "Float64" || a.type == "Int64" ? 8 : a.type == "Float32" || a.type == "Int32" ? 4 : 0;
    if (size == 0) fail("array \"" + name + "\" has type " + a.type + "; Float32, Float64, Int32 or Int64 expected");
    if (length > bytes.size() - header || length % size != 0) {
      fail("array \"" + name + "\" says it holds " + std::to_string(length) + " bytes but holds " +
           std::to_string(bytes.size() - header));
    }
    for (std::size_t at = header; at < header + length; at += size) {
      if (a.type == "Float64") {
        double v;
        std::memcpy(&v, &bytes[at], 8);
        out.push_back(v);
      } else if (a.type == "Float32") {
        float v;
        std::memcpy(&v, &bytes[at], 4);
        out.push_back(v);
      } else if (a.type == "Int64") {
        std::int64_t v;
        std::memcpy(&v, &bytes[at], 8);
        out.push_back(static_cast<double>(v));
      } else {
        std::int32_t v;
        std::memcpy(&v, &bytes[at], 4);
        out.push_back(v);
      }
      if (!std::isfinite(out.back())) fail("array \"" + name + "\" holds a value that is not finite");
    }
    return out;
  }

  fs::path path_;
  std::string field_;
  bool uint64_header_ = false;
  int pieces_ = 0;
  bool in_points_ = false;
  bool in_point_data_ = false;
  DataArray points_;
  std::optional<DataArray> field_data_;
  DataArray* current_ = nullptr;
};

/// An exception must not unwind through expat's C frames: the handlers keep it and stop the parser.
struct ParseContext {
  VtuScanner* scanner;
  XML_Parser parser;
  std::exception_ptr failure;
};

template <class Action>
void guarded(void* user, const Action& action) {
  auto* c = static_cast<ParseContext*>(user);
  try {
    action(*c->scanner);
  } catch (...) {
    c->failure = std::current_exception();
    XML_StopParser(c->parser, XML_FALSE);
  }
}

}  // namespace

NodalValues read_vtu_point_field(const fs::path& path, const std::string& field) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw NodalFileError("cannot read the nodal values file " + path.string());
  VtuScanner scanner(path, field);
  const std::unique_ptr<XML_ParserStruct, decltype(&XML_ParserFree)> parser(XML_ParserCreate(nullptr), &XML_ParserFree);
  ParseContext context{&scanner, parser.get(), nullptr};
  XML_SetUserData(parser.get(), &context);
  XML_SetElementHandler(
      parser.get(),
      [](void* user, const XML_Char* name, const XML_Char** attributes) {
        guarded(user, [&](VtuScanner& s) { s.start(name, attributes); });
      },
      [](void* user, const XML_Char* name) { guarded(user, [&](VtuScanner& s) { s.end(name); }); });
  XML_SetCharacterDataHandler(parser.get(), [](void* user, const XML_Char* text, int length) {
    guarded(user, [&](VtuScanner& s) { s.text(text, length); });
  });
  // Streamed in blocks: the file is never held whole, only the two arrays' text.
  std::vector<char> block(1 << 20);
  for (;;) {
    in.read(block.data(), static_cast<std::streamsize>(block.size()));
    const auto got = static_cast<int>(in.gcount());
    const bool last = got < static_cast<int>(block.size());
    if (XML_Parse(parser.get(), block.data(), got, last ? 1 : 0) == XML_STATUS_ERROR) {
      if (context.failure) std::rethrow_exception(context.failure);
      throw NodalFileError(path.string() + " is not valid XML: " + XML_ErrorString(XML_GetErrorCode(parser.get())) +
                           " at line " + std::to_string(XML_GetCurrentLineNumber(parser.get())));
    }
    if (last) break;
  }
  return scanner.result();
}

}  // namespace saasgaps::io
