#include "io/model/scan_model_reader.hpp"

#include <algorithm>
#include <string>
#include <vector>

#include "io/json/json_limits.hpp"
#include "io/model/json_scan.hpp"
#include "io/model/model_stream.hpp"

namespace saasgaps::io {

namespace {

/// The deepest a member of the root may nest (the root is level 1).
constexpr std::size_t member_depth = max_json_depth - 1;

bool node_item(JsonScan& scan, NodeValues& v) {
  static constexpr std::array<std::string_view, 3> keys{"id", "r", "z"};
  unsigned seen = 0;
  return scan_members(scan, keys, seen,
                      [&](std::size_t k) { return scan.number(k == 0 ? v.id : k == 1 ? v.r : v.z); }) &&
         seen == 7;
}

bool element_item(JsonScan& scan, ElementValues& v) {
  static constexpr std::array<std::string_view, 4> keys{"id", "nodes", "material", "angle"};
  unsigned seen = 0;
  const bool shaped = scan_members(scan, keys, seen, [&](std::size_t k) {
    if (k == 0) return scan.number(v.id);
    if (k == 2) return scan.number(v.material);
    if (k == 3) return scan.number(v.angle.emplace());
    v.node_count = 0;
    return scan_items(scan, [&] {
             return v.node_count < max_element_nodes && scan.number(v.nodes[static_cast<std::size_t>(v.node_count++)]);
           }) &&
           v.node_count >= 3;
  });
  return shaped && (seen & 7U) == 7U;
}

bool constraint_item(JsonScan& scan, ConstraintValues& v) {
  static constexpr std::array<std::string_view, 3> keys{"node", "r", "z"};
  unsigned seen = 0;
  return scan_members(scan, keys, seen,
                      [&](std::size_t k) {
                        return scan.number(k == 0 ? v.node : k == 1 ? v.r.emplace() : v.z.emplace());
                      }) &&
         (seen & 1U) != 0;
}

bool temperature_item(JsonScan& scan, TemperatureValues& v) {
  static constexpr std::array<std::string_view, 2> keys{"node", "T"};
  unsigned seen = 0;
  return scan_members(scan, keys, seen, [&](std::size_t k) { return scan.number(k == 0 ? v.node : v.T); }) &&
         seen == 3;
}

/// The span of the value of `key` in the object `object`, when the key is there once; false when
/// it is not, is there twice, or the object is not of the scan's subset.
bool only_member(std::string_view object, std::string_view key, std::string_view& value) {
  JsonScan scan(object);
  if (!scan.consume('{')) return false;
  int found = 0;
  if (scan.consume('}')) return false;
  do {
    std::string_view k;
    std::string_view span;
    if (!scan.key(k) || !scan.skip_value(span, member_depth)) return false;
    if (k == key) {
      value = span;
      ++found;
    }
  } while (scan.consume(','));
  return scan.consume('}') && found == 1;
}

class ModelScan {
 public:
  explicit ModelScan(SectionReader& reader) : reader_(reader) {}

  bool read(std::string_view text) {
    JsonScan scan(text);
    if (!scan.consume('{')) return false;
    if (!scan.consume('}')) {
      do {
        std::string_view key;
        if (!scan.key(key)) return false;
        const auto s = section_of(key);
        // An unknown or repeated key is an issue: the reporting path reports it where it is.
        if (!s || present_[index(*s)]) return false;
        present_[index(*s)] = true;
        if (ready(*s)) {
          if (!read_section(*s, scan)) return false;
          done_[index(*s)] = true;
        } else if (!scan.skip_value(spans_[index(*s)], member_depth)) {
          return false;
        }
      } while (scan.consume(','));
      if (!scan.consume('}')) return false;
    }
    if (!scan.at_end()) return false;
    for (std::size_t k = 0; k < section_count; ++k) {
      const auto s = static_cast<Section>(k);
      if (done_[k]) continue;
      if (!present_[k]) {
        reader_.read_section(s, nullptr);
      } else {
        JsonScan member(spans_[k]);
        if (!read_section(s, member)) return false;
      }
      done_[k] = true;
    }
    reader_.check_required_root_keys(present_);
    return true;
  }

 private:
  static std::size_t index(Section s) { return static_cast<std::size_t>(s); }

  /// Every section `s` depends on has been read.
  [[nodiscard]] bool ready(Section s) const {
    const auto before = dependencies(s);
    return std::all_of(before.begin(), before.end(), [&](Section d) { return done_[index(d)]; });
  }

  bool read_section(Section s, JsonScan& scan) {
    if (streams_items(s)) return read_items(s, scan);
    std::string_view span;
    if (!scan.skip_value(span, member_depth)) return false;
    if (s == Section::loads) return read_loads(span);
    return read_tree(s, span);
  }

  /// A small member: its tree judged by the rule code.
  bool read_tree(Section s, std::string_view span) {
    try {
      const json value = parse_tree(span);
      reader_.read_section(s, &value);
      return true;
    } catch (const ModelError&) {
      return false;  // not JSON, a repeated key, a number beyond a double: the reporting path says
    }
  }

  bool read_items(Section s, JsonScan& scan) {
    reader_.begin_items(s);
    std::size_t count = 0;
    const bool read = scan_items(scan, [&] {
      bool taken = false;
      if (s == Section::nodes) {
        NodeValues v;
        taken = node_item(scan, v) && reader_.read_node_values(v, count);
      } else if (s == Section::elements) {
        ElementValues v;
        taken = element_item(scan, v) && reader_.read_element_values(v, count);
      } else {
        ConstraintValues v;
        taken = constraint_item(scan, v) && reader_.read_constraint_values(v, count);
      }
      ++count;
      return taken;
    });
    if (!read) return false;
    reader_.end_items(s, count);
    return true;
  }

  /// loads, with its /temperatures/nodal table (258,000 items at 10^6 unknowns) read typed when
  /// every item has the usual shape and the reader takes them all; the tree is then parsed with
  /// that table empty, as the reporting path builds it. Any other case: the tree of it all.
  bool read_loads(std::string_view span) {
    std::string_view temperatures;
    std::string_view nodal;
    if (!only_member(span, "temperatures", temperatures) || !only_member(temperatures, "nodal", nodal)) {
      return read_tree(Section::loads, span);
    }
    std::vector<TemperatureValues> values;
    values.reserve(nodal.size() / 16);  // {"node":1,"T":0} is the shortest item
    JsonScan scan(nodal);
    if (!scan_items(scan, [&] { return temperature_item(scan, values.emplace_back()); }) ||
        !reader_.take_nodal_temperatures(values)) {
      return read_tree(Section::loads, span);
    }
    std::string without_items(span.substr(0, static_cast<std::size_t>(nodal.data() - span.data())));
    without_items += "[]";
    without_items += span.substr(static_cast<std::size_t>(nodal.data() + nodal.size() - span.data()));
    return read_tree(Section::loads, without_items);
  }

  SectionReader& reader_;
  std::array<bool, section_count> present_{};
  std::array<bool, section_count> done_{};
  std::array<std::string_view, section_count> spans_{};  ///< of the members left for the end
};

}  // namespace

bool scan_model_text(std::string_view text, SectionReader& reader) { return ModelScan(reader).read(text); }

}  // namespace saasgaps::io
