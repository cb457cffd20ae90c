#include "io/model/simd_model_reader.hpp"

#include <array>
#include <optional>
#include <utility>
#include <vector>

#include <simdjson.h>

#include "io/json/json_limits.hpp"
#include "io/model/model_stream.hpp"
#include "io/model/tape_dump.hpp"

namespace saasgaps::io {

namespace {

namespace dom = simdjson::dom;

/// The number of a numeric element; false for any other element.
bool number_of(dom::element e, Number& n) {
  switch (e.type()) {
    case dom::element_type::INT64:
      n.kind = Number::Kind::signed_integer;
      n.integer = e.get_int64().value_unsafe();
      return true;
    case dom::element_type::UINT64:
      n.kind = Number::Kind::unsigned_integer;
      n.unsigned_ = e.get_uint64().value_unsafe();
      return true;
    case dom::element_type::DOUBLE:
      n.kind = Number::Kind::floating;
      n.floating = e.get_double().value_unsafe();
      return true;
    default: return false;
  }
}

/// Each key of `o` is one of `keys` (a bit each) and no key is repeated: which keys there are;
/// `each(index, value)` gets every member and returns false to refuse the object.
template <std::size_t N, class Each>
bool members_of(dom::element item, const std::array<std::string_view, N>& keys, unsigned& seen, Each each) {
  dom::object o;
  if (item.get(o) != simdjson::SUCCESS) return false;
  seen = 0;
  for (const dom::key_value_pair member : o) {
    std::size_t k = 0;
    while (k < N && keys[k] != member.key) ++k;
    if (k == N || (seen & (1U << k)) != 0) return false;
    seen |= 1U << k;
    if (!each(k, member.value)) return false;
  }
  return true;
}

bool node_values(dom::element item, NodeValues& v) {
  static constexpr std::array<std::string_view, 3> keys{"id", "r", "z"};
  unsigned seen = 0;
  return members_of(item, keys, seen,
                    [&](std::size_t k, dom::element value) {
                      return number_of(value, k == 0 ? v.id : k == 1 ? v.r : v.z);
                    }) &&
         seen == 7;
}

bool element_values(dom::element item, ElementValues& v) {
  static constexpr std::array<std::string_view, 4> keys{"id", "nodes", "material", "angle"};
  unsigned seen = 0;
  const bool shaped = members_of(item, keys, seen, [&](std::size_t k, dom::element value) {
    if (k == 0) return number_of(value, v.id);
    if (k == 2) return number_of(value, v.material);
    if (k == 3) return number_of(value, v.angle.emplace());
    dom::array ids;
    if (value.get(ids) != simdjson::SUCCESS) return false;
    v.node_count = 0;
    for (const dom::element id : ids) {
      if (v.node_count == max_element_nodes || !number_of(id, v.nodes[static_cast<std::size_t>(v.node_count)])) return false;
      ++v.node_count;
    }
    return v.node_count >= 3;
  });
  return shaped && (seen & 7U) == 7U;
}

bool constraint_values(dom::element item, ConstraintValues& v) {
  static constexpr std::array<std::string_view, 3> keys{"node", "r", "z"};
  unsigned seen = 0;
  return members_of(item, keys, seen,
                    [&](std::size_t k, dom::element value) {
                      return number_of(value, k == 0 ? v.node : k == 1 ? v.r.emplace() : v.z.emplace());
                    }) &&
         (seen & 1U) != 0;
}

bool temperature_values(dom::element item, TemperatureValues& v) {
  static constexpr std::array<std::string_view, 2> keys{"node", "T"};
  unsigned seen = 0;
  return members_of(item, keys, seen,
                    [&](std::size_t k, dom::element value) { return number_of(value, k == 0 ? v.node : v.T); }) &&
         seen == 3;
}

/// The only member `key` of object `o`: false when o is not an object, has no such member or has
/// it twice (then the tree's rules, which keep the later value, must judge it).
bool only_member(dom::element o, std::string_view key, dom::element& value) {
  dom::object members;
  if (o.get(members) != simdjson::SUCCESS) return false;
  int found = 0;
  for (const dom::key_value_pair member : members) {
    if (member.key == key) {
      value = member.value;
      ++found;
    }
  }
  return found == 1;
}

/// model_digest of a document whose sections are `present`, with these values on the tape.
std::string tape_digest(const std::array<bool, section_count>& present,
                        const std::array<dom::element, section_count>& values) {
  return model_fingerprint(present, [&](Section s, Fingerprint& f) {
    TapeDump dump([&](std::string_view piece) { f.add(piece); });
    dump.value(values[static_cast<std::size_t>(s)]);
  });
}

/// The walk over the tape.
class TapeWalk {
 public:
  explicit TapeWalk(SectionReader& reader) : reader_(reader) {}

  void read(dom::object root) {
    // The root's members in the text's order: unknown and repeated keys are reported where they are.
    auto& values = values_;
    auto& present = present_;
    for (const dom::key_value_pair member : root) {
      const auto s = section_of(member.key);
      if (s && !present[static_cast<std::size_t>(*s)]) {
        present[static_cast<std::size_t>(*s)] = true;
        values[static_cast<std::size_t>(*s)] = member.value;
        continue;
      }
      path_.start_at_member(std::string(member.key));
      if (s) {
        repeated(path_.pointer(), member.key);
      } else {
        reader_.unknown_root_key(member.key);
      }
      (void)tree(member.value);  // built and dropped, for the repeated keys inside
    }
    for (std::size_t k = 0; k < section_count; ++k) {
      const auto s = static_cast<Section>(k);
      if (!present[k]) {
        reader_.read_section(s, nullptr);
      } else if (streams_items(s) && values[k].is_array()) {
        read_items(s, values[k]);
      } else if (s == Section::loads && typed_nodal_temperatures(values[k])) {
        path_.start_at_member(std::string(section_key(s)));
        const json value = tree(values[k]);  // its nodal array left empty: the reader holds the values
        skip_ = std::nullopt;
        reader_.read_section(s, &value);
      } else {
        path_.start_at_member(std::string(section_key(s)));
        const json value = tree(values[k]);
        reader_.read_section(s, &value);
      }
    }
    reader_.check_required_root_keys(present);
    for (InputIssue& issue : repeated_) reader_.repeated_key(std::move(issue.pointer), std::move(issue.detail));
  }

  /// model_digest of the document, from the dumps of the sections' values on the tape.
  [[nodiscard]] std::string digest() const { return tape_digest(present_, values_); }

 private:
  void repeated(std::string pointer, std::string_view key) {
    repeated_.push_back(InputIssue{std::move(pointer), repeated_key_detail(key)});
  }

  /// The element as a nlohmann tree, path_ at its place; a repeated key is reported and its later
  /// value kept. Recursion is bounded by max_json_depth (the parser's max_depth).
  json tree(dom::element e) {
    json value;
    switch (e.type()) {
      case dom::element_type::ARRAY: {
        path_.open(false);
        value = json::array();
        if (skip_ && dom::array(e).begin() == *skip_) {
          path_.close();
          return value;
        }
        auto& items = value.get_ref<json::array_t&>();
        for (const dom::element item : dom::array(e)) items.push_back(tree(item));
        path_.close();
        return value;
      }
      case dom::element_type::OBJECT: {
        path_.open(true);
        value = json::object();
        auto& members = value.get_ref<json::object_t&>();
        for (const dom::key_value_pair member : dom::object(e)) {
          path_.key(member.key);
          const auto [slot, fresh] = members.try_emplace(std::string(member.key));
          if (!fresh) repeated(path_.pointer(), member.key);
          slot->second = tree(member.value);
        }
        path_.close();
        return value;
      }
      case dom::element_type::INT64: {
        // nlohmann's parser makes every integer without a sign unsigned; so does this tree.
        const std::int64_t v = e.get_int64().value_unsafe();
        if (v >= 0) {
          value = static_cast<std::uint64_t>(v);
        } else {
          value = v;
        }
        break;
      }
      case dom::element_type::UINT64: value = e.get_uint64().value_unsafe(); break;
      case dom::element_type::DOUBLE: value = e.get_double().value_unsafe(); break;
      case dom::element_type::STRING: value = std::string(e.get_string().value_unsafe()); break;
      case dom::element_type::BOOL: value = e.get_bool().value_unsafe(); break;
      case dom::element_type::NULL_VALUE: break;
    }
    path_.next();
    return value;
  }

  /// A streamed array: each item of the usual shape read typed, any other as a tree.
  void read_items(Section s, dom::element list) {
    reader_.begin_items(s, dom::array(list).size());
    path_.start_at_member(std::string(section_key(s)));
    path_.open(false);
    std::size_t index = 0;
    for (const dom::element item : dom::array(list)) {
      if (!read_typed(s, item, index)) {
        const json value = tree(item);
        reader_.read_item(s, value, index);
      } else {
        path_.next();
      }
      ++index;
    }
    reader_.end_items(s, index);
  }

  /// The fast path of /loads/temperatures/nodal (258,000 items at 10^6 unknowns, which a tree
  /// costs a fifth of the read): when loads.temperatures.nodal is there once, every item has the
  /// usual shape and the reader takes them all, the loads tree is built without the items
  /// (skip_). Any other case: false, and the tree of loads holds the items.
  bool typed_nodal_temperatures(dom::element loads) {
    dom::element temperatures, nodal;
    dom::array items;
    if (!only_member(loads, "temperatures", temperatures) || !only_member(temperatures, "nodal", nodal) ||
        nodal.get(items) != simdjson::SUCCESS) {
      return false;
    }
    std::vector<TemperatureValues> values;
    values.reserve(items.size());
    for (const dom::element item : items) {
      if (!temperature_values(item, values.emplace_back())) return false;
    }
    if (!reader_.take_nodal_temperatures(values)) return false;
    skip_ = items.begin();
    return true;
  }

  bool read_typed(Section s, dom::element item, std::size_t index) {
    if (s == Section::nodes) {
      NodeValues v;
      return node_values(item, v) && reader_.read_node_values(v, index);
    }
    if (s == Section::elements) {
      ElementValues v;
      return element_values(item, v) && reader_.read_element_values(v, index);
    }
    ConstraintValues v;
    return constraint_values(item, v) && reader_.read_constraint_values(v, index);
  }

  SectionReader& reader_;
  JsonPath path_;
  std::vector<InputIssue> repeated_;
  std::array<bool, section_count> present_{};  ///< the first value of each section the root has
  std::array<dom::element, section_count> values_{};
  std::optional<dom::array::iterator> skip_;  ///< tree() leaves the array that begins here empty
};

/// The document's root object, parsed by `parser` (which holds the tape); false when simdjson
/// refuses the text or the root is not an object.
bool parse_root(dom::parser& parser, std::string_view text, dom::object& members) {
  if (parser.allocate(text.size(), max_json_depth) != simdjson::SUCCESS) return false;
  // The parser copies the text into a buffer with the padding its SIMD loads read past the end.
  dom::element root;
  if (parser.parse(text.data(), text.size(), true).get(root) != simdjson::SUCCESS) return false;
  return root.get(members) == simdjson::SUCCESS;
}

}  // namespace

bool digest_model_text(std::string_view text, std::string& digest) {
  dom::parser parser;
  dom::object members;
  if (!parse_root(parser, text, members)) return false;
  // The first value of each section, as the walk above takes it.
  std::array<bool, section_count> present{};
  std::array<dom::element, section_count> values{};
  for (const dom::key_value_pair member : members) {
    const auto s = section_of(member.key);
    if (s && !present[static_cast<std::size_t>(*s)]) {
      present[static_cast<std::size_t>(*s)] = true;
      values[static_cast<std::size_t>(*s)] = member.value;
    }
  }
  digest = tape_digest(present, values);
  return true;
}

bool read_model_text(std::string_view text, SectionReader& reader, std::string* digest) {
  dom::parser parser;
  dom::object members;
  if (!parse_root(parser, text, members)) return false;
  TapeWalk walk(reader);
  walk.read(members);
  if (digest != nullptr) *digest = walk.digest();
  return true;
}

}  // namespace saasgaps::io
