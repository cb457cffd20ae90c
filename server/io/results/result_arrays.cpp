#include "io/results/result_arrays.hpp"

// The project keeps assert() in release builds (no NDEBUG), and RapidJSON then also drops the
// forced inlining of the per-character pushes onto its stack (every number and key goes through
// them): a call per byte was 15 % of a read. Forced as an NDEBUG build forces it. (This is the only
// file that includes RapidJSON.)
#define RAPIDJSON_FORCEINLINE __attribute__((always_inline))
#include <rapidjson/error/en.h>
#include <rapidjson/memorystream.h>
#include <rapidjson/reader.h>

#include <array>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <memory>
#include <utility>
#include <vector>

#include "io/json/json_limits.hpp"
#include "io/json/tree_builder.hpp"

namespace saasgaps::io {

namespace {

using json = nlohmann::json;

constexpr double nan = std::numeric_limits<double>::quiet_NaN();

[[noreturn]] void malformed(const std::string& pointer, const std::string& what) {
  throw std::invalid_argument("malformed result document: " + shown_pointer(pointer) + " " + what);
}

/// A JSON number's text as a double, rounded as strtod rounds (nlohmann's parser uses it); a number
/// beyond the range of a double is refused, as nlohmann refuses it.
double to_double(std::string_view text, const JsonPath& path) {
  double value = 0.0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error == std::errc::result_out_of_range) {
    // libstdc++ reports underflow as out of range too; strtod gives the (signed) zero or subnormal.
    const std::string copy(text);
    value = std::strtod(copy.c_str(), nullptr);
    if (!std::isfinite(value)) malformed(path.pointer(), "is a number beyond the range of a double: " + copy);
    return value;
  }
  if (error != std::errc() || end != text.data() + text.size()) {
    malformed(path.pointer(), "is not a number: " + std::string(text));  // unreachable for JSON numbers
  }
  return value;
}

/// A JSON number's text as an int; ids are written as integers.
int to_int(std::string_view text, const JsonPath& path) {
  int value = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || end != text.data() + text.size()) {
    malformed(path.pointer(), "is not an integer within the range of an int: " + std::string(text));
  }
  return value;
}

/// A number of the tree part as nlohmann's parser types it: an integer text is a signed (negative)
/// or unsigned integer when it fits, else a double.
json tree_number(std::string_view text, const JsonPath& path) try {
  if (text.find_first_of(".eE") == std::string_view::npos) {
    if (text.front() == '-') {
      std::int64_t v = 0;
      const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), v);
      if (error == std::errc() && end == text.data() + text.size()) return json(v);
    } else {
      std::uint64_t v = 0;
      const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), v);
      if (error == std::errc() && end == text.data() + text.size()) return json(v);
    }
  }
  return json(to_double(text, path));
} catch (const std::invalid_argument& e) {
  throw ResultTextError(e.what());  // nlohmann's parser refuses the text too: it is not a document we read
}

/// The node members read, by slot.
enum NodeSlot : int {
  node_id, node_r, node_z, node_t, node_u_r, node_u_z,
  node_sigma_r, node_sigma_z, node_tau_rz, node_sigma_theta, node_effective,  // recovered (optional)
  node_slots
};
constexpr std::array<std::string_view, node_slots> node_keys{
    "id", "r", "z", "T", "u_r", "u_z", "sigma_r", "sigma_z", "tau_rz", "sigma_theta", "effective"};

/// The SAX handler: where the parse is decides what an event does.
class ResultHandler : public rapidjson::BaseReaderHandler<rapidjson::UTF8<>, ResultHandler> {
 public:
  ResultHandler(const ResultSelection& selection, ResultArrays& out) : selection_(selection), out_(out) {
    out_.element_keys = selection.element_keys;
  }

  bool Null() { return scalar([] { return json(nullptr); }, "null"); }
  bool Bool(bool b) {
    // A boolean where a value is read counts 1 or 0, as nlohmann's get<double>() counts it (the
    // elements' "yield" and "plastic_converged" are booleans).
    if (skipping_ == 0 && place_ == Place::node_member && slot_ > node_id) {
      node_[static_cast<std::size_t>(slot_)] = b ? 1.0 : 0.0;
      node_seen_ |= 1U << slot_;
      return step();
    }
    if (skipping_ == 0 && place_ == Place::element_member && slot_ >= 0) {
      element_values_[static_cast<std::size_t>(slot_)] = b ? 1.0 : 0.0;
      element_seen_[static_cast<std::size_t>(slot_)] = true;
      return step();
    }
    return scalar([b] { return json(b); }, "a boolean");
  }
  bool RawNumber(const char* text, rapidjson::SizeType length, bool) {
    const std::string_view number(text, length);
    check_range(number);
    if (skipping_ > 0) return step();
    if (place_ == Place::start || place_ == Place::root || place_ == Place::tree) {
      return scalar([&] { return tree_number(number, path_); }, "a number");
    }
    try {
      typed_number(number);
    } catch (const std::invalid_argument& e) {
      mesh_error(e.what());
    }
    return step();
  }

  /// A number beyond the range of a double, anywhere (skipped parts too): nlohmann's parser refuses
  /// the text, and so does this reader. Only a number with an exponent or of 300 digits can be.
  void check_range(std::string_view number) const {
    if (number.size() <= 300 && number.find_first_of("eE") == std::string_view::npos) return;
    try {
      (void)to_double(number, path_);
    } catch (const std::invalid_argument& e) {
      throw ResultTextError(e.what());
    }
  }

  /// A number inside a node or an element.
  void typed_number(std::string_view number) {
    switch (place_) {
      case Place::node_member: {
        if (slot_ < 0) return;
        const double v = slot_ == node_id ? static_cast<double>(to_int(number, path_)) : to_double(number, path_);
        node_[static_cast<std::size_t>(slot_)] = v;
        node_seen_ |= 1U << slot_;
        return;
      }
      case Place::element_member: {
        if (slot_ == slot_skip) return;
        if (slot_ == slot_element_id) {
          element_id_ = to_int(number, path_);
          element_id_seen_ = true;
        } else if (slot_ == slot_material) {
          material_ = to_int(number, path_);
        } else if (slot_ == slot_nodes) {
          malformed(path_.pointer(), "is a number, not an array of node ids");
        } else {
          element_values_[static_cast<std::size_t>(slot_)] = to_double(number, path_);
          element_seen_[static_cast<std::size_t>(slot_)] = true;
        }
        return;
      }
      case Place::element_nodes: out_.elements->node_ids.push_back(to_int(number, path_)); return;
      case Place::nodes:
      case Place::elements: malformed(path_.pointer(), "is a number, not an object");
      default: return;
    }
  }
  bool String(const char* text, rapidjson::SizeType length, bool) {
    return scalar([&] { return json(std::string(text, length)); }, "a string");
  }

  bool StartObject() { return open(true); }
  bool StartArray() { return open(false); }
  bool EndObject(rapidjson::SizeType) { return close(); }
  bool EndArray(rapidjson::SizeType) { return close(); }

  bool Key(const char* text, rapidjson::SizeType length, bool) {
    const std::string_view name(text, length);
    path_.key(name);
    if (skipping_ > 0) return true;
    switch (place_) {
      case Place::root: root_key_.assign(name); break;
      case Place::node_member: {
        slot_ = -1;
        for (int s = 0; s < node_slots; ++s) {
          if (name == node_keys[static_cast<std::size_t>(s)]) slot_ = s;
        }
        break;
      }
      case Place::element_member: slot_ = element_slot(name); break;
      case Place::tree: (void)tree_.key(std::string(name)); break;  // repeated: the later value, as nlohmann
      default: break;
    }
    return true;
  }

 private:
  enum class Place { start, root, tree, nodes, node_member, elements, element_member, element_nodes };
  static constexpr int slot_skip = -1, slot_element_id = -2, slot_material = -3, slot_nodes = -4;

  int element_slot(std::string_view name) const {
    if (name == "id") return slot_element_id;
    if (name == "material") return slot_material;
    if (name == "nodes") return slot_nodes;
    for (std::size_t k = 0; k < selection_.element_keys.size(); ++k) {
      if (name == selection_.element_keys[k]) return static_cast<int>(k);
    }
    return slot_skip;
  }

  /// A value is complete at the current place: arrays move to their next item.
  bool step() {
    path_.next();
    return true;
  }

  template <class Make>
  bool scalar(Make make, const char* what) {
    if (skipping_ > 0) return step();
    try {
      return typed_scalar(make, what);
    } catch (const std::invalid_argument& e) {
      mesh_error(e.what());
      return step();
    }
  }

  template <class Make>
  bool typed_scalar(Make make, const char* what) {
    switch (place_) {
      case Place::start: mesh_error("the result document is not a JSON object"); return true;
      case Place::root:
        if (!selected_root_member()) return step();
        if (root_key_ == "nodes") out_.nodes.reset();  // a later member replaces an earlier one
        if (root_key_ == "elements") out_.elements.reset();
        out_.document[root_key_] = make();
        return step();
      case Place::tree:
        tree_.value(make());
        return step();
      case Place::nodes:
      case Place::elements: malformed(path_.pointer(), std::string("is ") + what + ", not an object");
      case Place::node_member:
        if (slot_ >= 0) malformed(path_.pointer(), std::string("is ") + what + ", not a number");
        return step();
      case Place::element_member:
        if (slot_ != slot_skip) malformed(path_.pointer(), std::string("is ") + what + ", not a number");
        return step();
      case Place::element_nodes: malformed(path_.pointer(), std::string("is ") + what + ", not a node id");
    }
    return step();
  }

  /// The first thing wrong with the nodes or elements; the parse goes on (the text may still not be
  /// JSON, or be a model rather than a result: the caller says so first).
  void mesh_error(const std::string& what) {
    if (!out_.mesh_error) out_.mesh_error = what;
  }

  /// Whether the root member being read is kept (`nodes` and `elements` are not when the mesh is not
  /// selected).
  bool selected_root_member() const { return selection_.mesh || (root_key_ != "nodes" && root_key_ != "elements"); }

  bool open(bool is_object) {
    path_.open(is_object);  // the limit is the document's, skipped parts included
    if (skipping_ > 0) {
      ++skipping_;
      return true;
    }
    try {
      return typed_open(is_object);
    } catch (const std::invalid_argument& e) {
      mesh_error(e.what());
      skipping_ = 1;  // what is wrong is skipped: the parse goes on, to find text that is not JSON
      return true;
    }
  }

  bool typed_open(bool is_object) {
    switch (place_) {
      case Place::start:
        if (!is_object) throw std::invalid_argument("the result document is not a JSON object");
        place_ = Place::root;
        return true;
      case Place::root:
        if (!selected_root_member()) {
          skipping_ = 1;
        } else if (!is_object && root_key_ == "nodes") {
          out_.document.erase("nodes");
          out_.nodes.emplace();
          place_ = Place::nodes;
        } else if (!is_object && root_key_ == "elements") {
          out_.document.erase("elements");
          out_.elements.emplace();
          out_.elements->values.assign(selection_.element_keys.size(), {});
          out_.elements->first_missing.assign(selection_.element_keys.size(), std::nullopt);
          place_ = Place::elements;
        } else {
          if (root_key_ == "nodes") out_.nodes.reset();  // a later member replaces an earlier one
          if (root_key_ == "elements") out_.elements.reset();
          tree_.begin();
          tree_.start(is_object ? json::object() : json::array());
          place_ = Place::tree;
        }
        return true;
      case Place::tree:
        tree_.start(is_object ? json::object() : json::array());
        return true;
      case Place::nodes:
        if (!is_object) malformed(parent_pointer(), "is an array, not an object");
        node_seen_ = 0;
        node_ = {0.0, 0.0, 0.0, 0.0, 0.0, 0.0, nan, nan, nan, nan, nan};
        place_ = Place::node_member;
        return true;
      case Place::elements:
        if (!is_object) malformed(parent_pointer(), "is an array, not an object");
        element_id_seen_ = false;
        element_id_ = 0;
        material_ = 0;
        nodes_seen_ = false;
        out_.elements->node_ids.resize(out_.elements->first_node.back());  // a repeated "nodes" starts over
        element_values_.assign(selection_.element_keys.size(), nan);
        element_seen_.assign(selection_.element_keys.size(), false);
        place_ = Place::element_member;
        return true;
      case Place::node_member:
        if (slot_ >= 0) malformed(parent_pointer(), std::string("is ") + (is_object ? "an object" : "an array") + ", not a number");
        skipping_ = 1;
        return true;
      case Place::element_member:
        if (slot_ == slot_nodes && !is_object) {
          out_.elements->node_ids.resize(out_.elements->first_node.back());
          nodes_seen_ = true;
          place_ = Place::element_nodes;
          return true;
        }
        if (slot_ != slot_skip) {
          malformed(parent_pointer(), std::string("is ") + (is_object ? "an object" : "an array") + ", not " +
                                          (slot_ == slot_nodes ? "an array of node ids" : "a number"));
        }
        skipping_ = 1;
        return true;
      case Place::element_nodes: malformed(parent_pointer(), "is not a node id");
    }
    return true;
  }

  /// The pointer of the container just opened: path_ holds it as a frame now, so its parent's
  /// pointer is where it is.
  std::string parent_pointer() const {
    const std::string p = path_.pointer();
    return p.substr(0, p.rfind('/'));
  }

  bool close() {
    path_.close();
    if (skipping_ > 0) {
      --skipping_;
      return true;
    }
    switch (place_) {
      case Place::start: break;
      case Place::root: place_ = Place::start; break;  // the document is complete
      case Place::tree:
        tree_.end();
        if (tree_.complete()) {
          out_.document[root_key_] = tree_.take();
          place_ = Place::root;
        }
        break;
      case Place::nodes:
      case Place::elements: place_ = Place::root; break;
      case Place::node_member: end_node(); break;
      case Place::element_member: end_element(); break;
      case Place::element_nodes: place_ = Place::element_member; break;
    }
    return true;
  }

  void end_node() {
    place_ = Place::nodes;
    ResultNodes& nodes = *out_.nodes;
    const std::size_t index = nodes.id.size();
    const std::string where = "/nodes/" + std::to_string(index);
    if (index == 0 && !(node_seen_ & (1U << node_r))) {
      mesh_error("the result document has no node coordinates (nodes[].r, .z): it predates self-contained "
                 "results; solve the model again");
    }
    for (const int s : {node_id, node_r, node_z, node_u_r, node_u_z}) {
      if (!(node_seen_ & (1U << s))) {
        mesh_error("malformed result document: " + where + " has no '" + std::string(node_keys[static_cast<std::size_t>(s)]) + "'");
      }
    }
    nodes.id.push_back(static_cast<int>(node_[node_id]));
    nodes.r.push_back(node_[node_r]);
    nodes.z.push_back(node_[node_z]);
    nodes.T.push_back(node_[node_t]);
    nodes.u_r.push_back(node_[node_u_r]);
    nodes.u_z.push_back(node_[node_u_z]);
    for (int k = 0; k < 5; ++k) {
      nodes.stress[static_cast<std::size_t>(k)].push_back(node_[static_cast<std::size_t>(node_sigma_r + k)]);
    }
  }

  void end_element() {
    place_ = Place::elements;
    ResultElements& elements = *out_.elements;
    const std::size_t index = elements.id.size();
    if (!element_id_seen_ || !nodes_seen_) {
      mesh_error("malformed result document: /elements/" + std::to_string(index) + " has no '" +
                 (element_id_seen_ ? "nodes" : "id") + "'");
    }
    elements.id.push_back(element_id_);
    elements.material.push_back(material_);
    elements.first_node.push_back(elements.node_ids.size());
    for (std::size_t k = 0; k < element_values_.size(); ++k) {
      elements.values[k].push_back(element_values_[k]);
      if (!element_seen_[k] && !elements.first_missing[k]) elements.first_missing[k] = index;
    }
  }

  const ResultSelection& selection_;
  ResultArrays& out_;
  JsonPath path_;
  TreeBuilder tree_;
  Place place_ = Place::start;
  std::string root_key_;
  int skipping_ = 0;  ///< open containers inside a skipped value
  int slot_ = slot_skip;
  // The node being read.
  std::array<double, node_slots> node_{};
  unsigned node_seen_ = 0;
  // The element being read.
  int element_id_ = 0, material_ = 0;
  bool element_id_seen_ = false, nodes_seen_ = false;
  std::vector<double> element_values_;
  std::vector<bool> element_seen_;
};

/// A RapidJSON input stream over TextPieces, one buffer of pieces at a time (RapidJSON's
/// FileReadStream, with the source a function: a file or a database blob).
class PieceReadStream {
 public:
  using Ch = char;
  PieceReadStream(const TextPieces& next, std::size_t capacity) : next_(next), buffer_(capacity + 1) { fill(); }
  [[nodiscard]] Ch Peek() const { return *current_; }
  Ch Take() {
    const Ch c = *current_;
    advance();
    return c;
  }
  [[nodiscard]] std::size_t Tell() const { return count_ + static_cast<std::size_t>(current_ - buffer_.data()); }
  // An input stream only (RapidJSON's Reader never writes to it).
  void Put(Ch) { std::abort(); }
  void Flush() { std::abort(); }
  Ch* PutBegin() { std::abort(); }
  std::size_t PutEnd(Ch*) { std::abort(); }

 private:
  void advance() {
    if (current_ < last_) {
      ++current_;
    } else if (!end_) {
      count_ += filled_;
      fill();
    }
  }
  /// The buffer full, or what is left; at the end a '\0' after the text, which RapidJSON reads as
  /// the end (as FileReadStream does).
  void fill() {
    const std::size_t capacity = buffer_.size() - 1;
    filled_ = 0;
    while (filled_ < capacity) {
      const std::size_t got = next_(buffer_.data() + filled_, capacity - filled_);
      if (got == 0) break;
      filled_ += got;
    }
    current_ = buffer_.data();
    last_ = buffer_.data() + filled_ - 1;
    if (filled_ < capacity) {
      buffer_[filled_] = '\0';
      ++last_;
      end_ = true;
    }
  }

  const TextPieces& next_;
  std::vector<char> buffer_;
  std::size_t filled_ = 0;
  std::size_t count_ = 0;  ///< bytes before the buffer
  char* current_ = nullptr;
  char* last_ = nullptr;
  bool end_ = false;
};

template <class Stream>
ResultArrays parse(Stream& stream, const ResultSelection& selection) {
  ResultArrays out;
  ResultHandler handler(selection, out);
  rapidjson::Reader reader;
  constexpr unsigned flags =
      rapidjson::kParseIterativeFlag | rapidjson::kParseValidateEncodingFlag | rapidjson::kParseNumbersAsStringsFlag;
  if (const rapidjson::ParseResult ok = reader.Parse<flags>(stream, handler); !ok) {
    throw ResultTextError(std::string(rapidjson::GetParseError_En(ok.Code())) + " (at byte " +
                          std::to_string(ok.Offset()) + ")");
  }
  return out;
}

}  // namespace

ResultArrays read_result_arrays(std::string_view text, const ResultSelection& selection) {
  rapidjson::MemoryStream stream(text.data(), text.size());
  return parse(stream, selection);
}

ResultArrays read_result_arrays_pieces(const TextPieces& next, const ResultSelection& selection) {
  PieceReadStream stream(next, 64 * 1024);
  return parse(stream, selection);
}

ResultArrays read_result_arrays_file(const std::string& path, const ResultSelection& selection) {
  const std::unique_ptr<std::FILE, int (*)(std::FILE*)> file(std::fopen(path.c_str(), "rb"), &std::fclose);
  if (!file) throw std::runtime_error("cannot read " + path + ": " + std::strerror(errno));
  return read_result_arrays_pieces(
      [&file](char* out, std::size_t capacity) { return std::fread(out, 1, capacity, file.get()); }, selection);
}

}  // namespace saasgaps::io
