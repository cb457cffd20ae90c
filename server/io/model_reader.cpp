#include "io/model_reader.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <optional>
#include <span>
#include <string>
#include <unordered_map>
#include <unordered_set>
#include <utility>
#include <vector>

#include "element_kernel.hpp"
#include "errors.hpp"
#include "io/json_pointer.hpp"
#include "material.hpp"

namespace saasgaps::io {

namespace {

using nlohmann::json;

// ------------------------------------------------------------------------------------------------
// Quoting values in messages. Every quote is bounded in length and depth: a message must stay a
// sentence whatever the document holds (a string of a megabyte, arrays nested a million deep).

constexpr std::size_t quote_limit = 80;
constexpr int quote_depth = 2;

/// A number as JSON writes it (shortest round trip, 1.0 stays 1.0), and inf or nan, which JSON
/// cannot write.
std::string format_number(double v) {
  if (std::isnan(v)) return "nan";
  if (std::isinf(v)) return v > 0.0 ? "inf" : "-inf";
  return json(v).dump();
}

/// A string as a JSON string literal; long ones are cut, invalid UTF-8 is replaced.
std::string quote_string(std::string_view text) {
  const bool cut = text.size() > quote_limit;
  const json literal = std::string(cut ? text.substr(0, quote_limit) : text);
  return literal.dump(-1, ' ', false, json::error_handler_t::replace) + (cut ? "..." : "");
}

void append_quote(const json& value, int depth, std::string& out) {
  if (value.is_number_float()) {
    out += format_number(value.get<double>());
  } else if (value.is_string()) {
    out += quote_string(value.get_ref<const std::string&>());
  } else if (value.is_structured()) {
    const bool is_object = value.is_object();
    out += is_object ? '{' : '[';
    if (!value.empty() && depth == 0) out += "...";
    if (depth > 0) {
      bool first = true;
      for (auto it = value.begin(); it != value.end(); ++it) {
        if (!first) out += ", ";
        first = false;
        if (out.size() > quote_limit) {
          out += "...";
          break;
        }
        if (is_object) out += quote_string(it.key()) + ": ";
        append_quote(*it, depth - 1, out);
      }
    }
    out += is_object ? '}' : ']';
  } else {
    // null, booleans and integers: their JSON text is short and exact.
    out += value.dump();
  }
}

/// The value as (bounded) JSON text, for quoting in a message.
std::string quote(const json& value) {
  std::string out;
  append_quote(value, quote_depth, out);
  return out;
}

/// "the string \"1\"", "the array [1, 2]", "null": what a value of the wrong type was.
std::string describe(const json& value) {
  switch (value.type()) {
    case json::value_t::null: return "null";
    case json::value_t::boolean: return "the boolean " + quote(value);
    case json::value_t::string: return "the string " + quote(value);
    case json::value_t::array: return "the array " + quote(value);
    case json::value_t::object: return "the object " + quote(value);
    case json::value_t::number_integer:
    case json::value_t::number_unsigned:
    case json::value_t::number_float: return "the number " + quote(value);
    default: return "a value that is not plain JSON";
  }
}

/// "a, b, c": a list of names for a message.
std::string join(std::span<const std::string_view> names) {
  std::string text;
  for (const std::string_view name : names) {
    if (!text.empty()) text += ", ";
    text += name;
  }
  return text;
}

// ------------------------------------------------------------------------------------------------
// Ranges of numbers, with the wording of the rule they state.

struct Bound {
  double value = 0.0;
  bool inclusive = false;
};

struct Range {
  std::optional<Bound> lower;
  std::optional<Bound> upper;
  const char* reason = nullptr;  ///< why the range holds, when it is not obvious
};

constexpr Range any_number{};
constexpr Range positive{Bound{0.0, false}, std::nullopt};
constexpr Range non_negative{Bound{0.0, true}, std::nullopt};
constexpr Range poisson_ratio{Bound{-1.0, false}, Bound{0.5, false},
                              "an isotropic material is stable only for -1 < nu < 0.5"};
constexpr Range hardening{Bound{0.0, true}, Bound{1.0, false}, "the secondary slope is a fraction of E"};
constexpr Range extrapolation{Bound{0.0, true}, Bound{1.0, false}};
constexpr Range tolerance_fraction{Bound{0.0, false}, Bound{1.0, false}};
constexpr Range axisymmetric_radius{Bound{0.0, true}, std::nullopt,
                                    "an axisymmetric model lies in the half plane r >= 0"};

bool contains(const Range& range, double v) {
  if (range.lower && (range.lower->inclusive ? v < range.lower->value : v <= range.lower->value)) return false;
  if (range.upper && (range.upper->inclusive ? v > range.upper->value : v >= range.upper->value)) return false;
  return true;
}

/// Bounds are round numbers; write 0 rather than 0.0 so the rule reads like the documentation.
std::string format_bound(double v) {
  if (v == std::floor(v) && std::fabs(v) < 1e15) return std::to_string(static_cast<long long>(v));
  return format_number(v);
}

/// "E > 0", "0 <= hardening_ratio < 1": the rule a value broke.
std::string requirement(const Range& range, std::string_view name) {
  const auto op = [](const Bound& b) { return b.inclusive ? " <= " : " < "; };
  std::string text;
  if (range.lower && range.upper) {
    text = format_bound(range.lower->value) + op(*range.lower) + std::string(name) + op(*range.upper) +
           format_bound(range.upper->value);
  } else if (range.lower) {
    text = std::string(name) + (range.lower->inclusive ? " >= " : " > ") + format_bound(range.lower->value);
  } else if (range.upper) {
    text = std::string(name) + op(*range.upper) + format_bound(range.upper->value);
  }
  if (range.reason != nullptr) text += std::string(" (") + range.reason + ")";
  return text;
}

// ------------------------------------------------------------------------------------------------
// Rows of temperature tables, read field by field into a row struct.

template <class Row>
struct Field {
  std::string_view key;
  double Row::*member;
  const Range* range;
};

constexpr std::array<Field<PropertyRow>, 4> isotropic_fields{{
    {"T", &PropertyRow::T, &any_number},
    {"E", &PropertyRow::E1, &positive},
    {"nu", &PropertyRow::nu12, &poisson_ratio},
    {"alpha", &PropertyRow::alpha1, &any_number},
}};

constexpr std::array<Field<PropertyRow>, 11> orthotropic_fields{{
    {"T", &PropertyRow::T, &any_number},
    {"E1", &PropertyRow::E1, &positive},
    {"E2", &PropertyRow::E2, &positive},
    {"E3", &PropertyRow::E3, &positive},
    {"nu12", &PropertyRow::nu12, &any_number},
    {"nu13", &PropertyRow::nu13, &any_number},
    {"nu23", &PropertyRow::nu23, &any_number},
    {"G12", &PropertyRow::G12, &positive},
    {"alpha1", &PropertyRow::alpha1, &any_number},
    {"alpha2", &PropertyRow::alpha2, &any_number},
    {"alpha3", &PropertyRow::alpha3, &any_number},
}};

/// The object form of plasticity: one curve for every temperature (T stays 0).
constexpr std::array<Field<PlasticityRow>, 2> plasticity_curve_fields{{
    {"yield_stress", &PlasticityRow::yield_stress, &positive},
    {"hardening_ratio", &PlasticityRow::hardening_ratio, &hardening},
}};

constexpr std::array<Field<PlasticityRow>, 3> plasticity_row_fields{{
    {"T", &PlasticityRow::T, &any_number},
    {"yield_stress", &PlasticityRow::yield_stress, &positive},
    {"hardening_ratio", &PlasticityRow::hardening_ratio, &hardening},
}};

ElasticConstants constants_of(const PropertyRow& row) {
  return {row.E1, row.E2, row.E3, row.nu12, row.nu13, row.nu23, row.G12, row.alpha1, row.alpha2, row.alpha3};
}

// ------------------------------------------------------------------------------------------------
// The reader.

constexpr std::array<std::string_view, 3> analysis_names{"plane_stress", "plane_strain", "axisymmetric"};
constexpr std::array<std::string_view, 2> elastic_names{"isotropic", "orthotropic"};
constexpr std::array<std::string_view, 2> convergence_test_names{"report", "strict"};
constexpr std::array<std::string_view, 2> gap_method_names{"classic", "exact"};
constexpr std::array<std::string_view, 4> unit_names{"length", "force", "stress", "temperature"};

/// An object of the document (already checked by Reader::object) and its pointer.
struct Obj {
  const json& value;
  std::string pointer;

  [[nodiscard]] const json* find(std::string_view key) const {
    const auto it = value.find(key);
    return it == value.end() ? nullptr : &*it;
  }
  [[nodiscard]] std::string at(std::string_view key) const { return pointer_append(pointer, key); }
};

/// Where an id was defined, so a repeated id can name the first definition.
struct Entry {
  int index = 0;     ///< into Model::nodes, Model::materials, Model::elements or GapSettings::elements
  bool gap = false;  ///< element ids: a gap element
  std::string pointer;
};

/// Ids of one kind (solid and gap elements share one kind).
using Registry = std::unordered_map<int, Entry>;

/// Up to four node indices of an element, a gap element or a pressure edge; -1 where an id did not
/// resolve (the rest still serve, e.g. as edges that a pressure may name).
struct NodeList {
  std::array<int, 4> nodes{-1, -1, -1, -1};
  int count = 0;
  [[nodiscard]] bool complete() const {
    return std::none_of(nodes.begin(), nodes.begin() + count, [](int n) { return n < 0; });
  }
};

int as_index(std::size_t i) { return static_cast<int>(i); }

/// Reads one document, accumulating issues; one function per section of the document. Every
/// check reports its own issue and returns nullopt / nullptr / false, and the caller carries on, so
/// one pass finds every independent problem.
class Reader {
 public:
  Model read(const json& document);

 private:
  // Generic checks.
  void report(std::string pointer, std::string detail) {
    issues_.push_back(InputIssue{std::move(pointer), std::move(detail)});
  }
  /// True when value is an object; reports each unknown key at its own pointer and each missing
  /// required key at the object's pointer (the object is still read).
  bool check_object(const json& value, const std::string& pointer, std::span<const std::string_view> required,
                    std::span<const std::string_view> optional);
  bool object(const json& value, const std::string& pointer, std::initializer_list<std::string_view> required,
              std::initializer_list<std::string_view> optional = {}) {
    return check_object(value, pointer, {required.begin(), required.size()}, {optional.begin(), optional.size()});
  }
  /// The array, or nullptr (reported) when value is not an array or has fewer than min_items.
  const json* array(const json& value, const std::string& pointer, std::string_view name, std::size_t min_items);
  /// A finite number inside range (booleans are not numbers).
  std::optional<double> number(const json& value, const std::string& pointer, std::string_view name,
                               const Range& range);
  /// A JSON integer (1.0 is not one) from minimum to INT_MAX.
  std::optional<int> integer(const json& value, const std::string& pointer, std::string_view name, int minimum);

  // Optional fields of a checked object: absent gives nullopt silently (object() has already
  // reported a missing required key).
  std::optional<double> number_field(const Obj& o, std::string_view key, const Range& range = any_number);
  std::optional<int> integer_field(const Obj& o, std::string_view key, int minimum);
  std::optional<std::string> string_field(const Obj& o, std::string_view key);
  std::optional<std::size_t> choice_field(const Obj& o, std::string_view key,
                                          std::span<const std::string_view> choices);
  const json* array_field(const Obj& o, std::string_view key, std::size_t min_items);

  // Ids and references.
  /// False (reported) when id is already in the registry.
  bool is_new(const Registry& registry, int id, const std::string& pointer, std::string_view what);
  /// The entry a reference names; nullptr when the value is no id or names nothing (reported
  /// unless the registry is incomplete).
  const Entry* resolve(const Registry& registry, bool complete, const json& value, const std::string& pointer,
                       std::string_view what, std::string_view where);
  const Entry* resolve_node(const json& value, const std::string& pointer) {
    return resolve(nodes_, nodes_complete_, value, pointer, "node", "/nodes");
  }
  std::optional<int> new_element_id(const Obj& o);
  /// o["nodes"]: min_count..max_count distinct node ids that resolve.
  std::optional<NodeList> read_node_list(const Obj& o, std::size_t min_count, std::size_t max_count,
                                         std::string_view expectation);
  /// An element's 3 or 4 corners, with their shape checked when all are placed.
  std::optional<NodeList> read_corners(const Obj& o);
  /// Counter-clockwise with positive area; for a quadrilateral, each triangle around the centre.
  void check_shape(const NodeList& corners, const json& ids, const std::string& pointer);

  // Tables.
  /// An object with exactly the keys of fields, each a number in its range.
  template <class Row>
  std::optional<Row> read_row(const json& value, const std::string& pointer, std::span<const Field<Row>> fields);
  template <class Row, class Finish>
  std::vector<Row> read_table(const json& rows, const std::string& pointer, std::span<const Field<Row>> fields,
                              Finish finish);
  std::vector<PropertyRow> read_property_table(const Obj& o, std::string_view key, bool isotropic,
                                               std::size_t min_rows);
  std::vector<PlasticityRow> read_plasticity(const Obj& o);

  // Sections, in document order.
  void read_header(const Obj& root);
  void read_units(const Obj& root);
  void read_analysis(const Obj& root);
  void read_nodes(const Obj& root);
  void read_materials(const Obj& root);
  void read_elements(const Obj& root);
  void read_gaps(const Obj& root);
  void read_constraints(const Obj& root);
  void read_loads(const Obj& root);
  void read_nodal_forces(const Obj& loads);
  void read_pressures(const Obj& loads);
  void read_temperatures(const Obj& loads);
  void read_body_force(const Obj& loads);
  void read_solver(const Obj& root);
  void read_output(const Obj& root);
  std::vector<int> read_watch_list(const Obj& output, std::string_view key, bool gaps);

  std::vector<InputIssue> issues_;
  Model model_;
  std::optional<AnalysisType> analysis_;  ///< empty when analysis.type is missing or invalid
  Registry nodes_;
  Registry materials_;
  Registry elements_;              ///< solid and gap elements share one id space
  std::vector<bool> node_placed_;  ///< per node index: both coordinates valid (else skip shape checks)
  // False when a list that defines ids is missing or not an array: a reference into it cannot be
  // judged, and reporting every one as undefined would bury the real issue.
  bool nodes_complete_ = true;
  bool materials_complete_ = true;
  bool solids_complete_ = true;
  bool gaps_complete_ = true;
  [[nodiscard]] bool elements_complete() const { return solids_complete_ && gaps_complete_; }
};

// ---- generic checks

bool Reader::check_object(const json& value, const std::string& pointer, std::span<const std::string_view> required,
                          std::span<const std::string_view> optional) {
  if (!value.is_object()) {
    report(pointer, "expected an object, got " + describe(value));
    return false;
  }
  const auto allowed = [&](const std::string& key) {
    return std::ranges::find(required, key) != required.end() || std::ranges::find(optional, key) != optional.end();
  };
  for (auto it = value.begin(); it != value.end(); ++it) {
    if (allowed(it.key())) continue;
    std::vector<std::string_view> names(required.begin(), required.end());
    names.insert(names.end(), optional.begin(), optional.end());
    report(pointer_append(pointer, it.key()), "unknown key " + quote_string(it.key()) + " (allowed here: " +
                                                  (names.empty() ? std::string("none") : join(names)) + ")");
  }
  for (const std::string_view key : required) {
    if (!value.contains(key)) report(pointer, "missing required key " + quote_string(key));
  }
  return true;
}

const json* Reader::array(const json& value, const std::string& pointer, std::string_view name,
                          std::size_t min_items) {
  if (!value.is_array()) {
    report(pointer, std::string(name) + " must be an array, got " + describe(value));
    return nullptr;
  }
  if (value.size() < min_items) {
    report(pointer, std::string(name) + " must not be empty");
    return nullptr;
  }
  return &value;
}

std::optional<double> Reader::number(const json& value, const std::string& pointer, std::string_view name,
                                     const Range& range) {
  // is_number() is false for booleans, so true is not silently 1.
  if (!value.is_number()) {
    report(pointer, std::string(name) + " must be a number, got " + describe(value));
    return std::nullopt;
  }
  const double v = value.get<double>();
  if (!std::isfinite(v)) {
    report(pointer, std::string(name) + " = " + format_number(v) + " is not a finite number");
    return std::nullopt;
  }
  if (!contains(range, v)) {
    report(pointer, std::string(name) + " = " + quote(value) + " is out of range: need " + requirement(range, name));
    return std::nullopt;
  }
  return v;
}

std::optional<int> Reader::integer(const json& value, const std::string& pointer, std::string_view name,
                                   int minimum) {
  constexpr auto maximum = std::numeric_limits<int>::max();
  if (!value.is_number_integer()) {
    std::string detail = std::string(name) + " must be an integer, got " + describe(value);
    // JSON Schema calls 1.0 an integer; this reader does not, so say what to write instead.
    if (value.is_number_float() && std::isfinite(value.get<double>()) &&
        value.get<double>() == std::floor(value.get<double>()) && std::fabs(value.get<double>()) < 1e15) {
      detail += " (write " + std::to_string(static_cast<long long>(value.get<double>())) + " without a fraction)";
    }
    report(pointer, std::move(detail));
    return std::nullopt;
  }
  // Unsigned values above INT64_MAX would wrap in get<int64_t>(); compare in the value's own type.
  const bool in_range = value.is_number_unsigned()
                            ? value.get<std::uint64_t>() <= static_cast<std::uint64_t>(maximum) &&
                                  (minimum <= 0 || value.get<std::uint64_t>() >= static_cast<std::uint64_t>(minimum))
                            : value.get<std::int64_t>() >= minimum && value.get<std::int64_t>() <= maximum;
  if (!in_range) {
    report(pointer, std::string(name) + " = " + quote(value) + " is out of range: need " + std::to_string(minimum) +
                        " <= " + std::string(name) + " <= " + std::to_string(maximum));
    return std::nullopt;
  }
  return static_cast<int>(value.get<std::int64_t>());
}

std::optional<double> Reader::number_field(const Obj& o, std::string_view key, const Range& range) {
  const json* v = o.find(key);
  if (v == nullptr) return std::nullopt;
  return number(*v, o.at(key), key, range);
}

std::optional<int> Reader::integer_field(const Obj& o, std::string_view key, int minimum) {
  const json* v = o.find(key);
  if (v == nullptr) return std::nullopt;
  return integer(*v, o.at(key), key, minimum);
}

std::optional<std::string> Reader::string_field(const Obj& o, std::string_view key) {
  const json* v = o.find(key);
  if (v == nullptr) return std::nullopt;
  if (!v->is_string()) {
    report(o.at(key), std::string(key) + " must be a string, got " + describe(*v));
    return std::nullopt;
  }
  return v->get<std::string>();
}

std::optional<std::size_t> Reader::choice_field(const Obj& o, std::string_view key,
                                                std::span<const std::string_view> choices) {
  const json* v = o.find(key);
  if (v == nullptr) return std::nullopt;
  if (v->is_string()) {
    const auto it = std::ranges::find(choices, v->get_ref<const std::string&>());
    if (it != choices.end()) return static_cast<std::size_t>(it - choices.begin());
  }
  report(o.at(key), std::string(key) + " must be one of " + join(choices) + ", got " + describe(*v));
  return std::nullopt;
}

const json* Reader::array_field(const Obj& o, std::string_view key, std::size_t min_items) {
  const json* v = o.find(key);
  if (v == nullptr) return nullptr;
  return array(*v, o.at(key), key, min_items);
}

// ---- ids and references

bool Reader::is_new(const Registry& registry, int id, const std::string& pointer, std::string_view what) {
  const auto found = registry.find(id);
  if (found == registry.end()) return true;
  report(pointer, std::string(what) + " id " + std::to_string(id) + " is already used by " + found->second.pointer +
                      "; ids must be unique");
  return false;
}

const Entry* Reader::resolve(const Registry& registry, bool complete, const json& value,
                             const std::string& pointer, std::string_view what, std::string_view where) {
  const auto id = integer(value, pointer, what, 1);
  if (!id) return nullptr;
  const auto found = registry.find(*id);
  if (found != registry.end()) return &found->second;
  if (complete) {
    report(pointer, std::string(what) + " " + std::to_string(*id) + " is not defined: no entry of " +
                        std::string(where) + " has id " + std::to_string(*id));
  }
  return nullptr;
}

std::optional<int> Reader::new_element_id(const Obj& o) {
  const auto id = integer_field(o, "id", 1);
  if (!id || !is_new(elements_, *id, o.at("id"), "element")) return std::nullopt;
  return id;
}

std::optional<NodeList> Reader::read_node_list(const Obj& o, std::size_t min_count, std::size_t max_count,
                                               std::string_view expectation) {
  const json* ids = o.find("nodes");
  if (ids == nullptr) return std::nullopt;
  const std::string pointer = o.at("nodes");
  if (!ids->is_array()) {
    report(pointer, "nodes must be an array of node ids, got " + describe(*ids));
    return std::nullopt;
  }
  if (ids->size() < min_count || ids->size() > max_count) {
    report(pointer, "nodes " + quote(*ids) + " lists " + std::to_string(ids->size()) + " ids, but " +
                        std::string(expectation));
    return std::nullopt;
  }
  NodeList list;
  list.count = as_index(ids->size());
  for (std::size_t k = 0; k < ids->size(); ++k) {
    const std::string item = pointer_append(pointer, k);
    const Entry* node = resolve_node((*ids)[k], item);
    if (node == nullptr) continue;
    const auto end = list.nodes.begin() + static_cast<std::ptrdiff_t>(k);
    if (std::find(list.nodes.begin(), end, node->index) != end) {
      report(item, "node " + quote((*ids)[k]) + " appears twice in " + quote(*ids) + "; the nodes must be distinct");
      continue;
    }
    list.nodes[k] = node->index;
  }
  return list;
}

std::optional<NodeList> Reader::read_corners(const Obj& o) {
  auto corners = read_node_list(o, 3, 4, "an element has 3 (triangle) or 4 (quadrilateral) nodes");
  if (!corners || !corners->complete()) return corners;
  const bool placed = std::all_of(corners->nodes.begin(), corners->nodes.begin() + corners->count,
                                  [&](int n) { return node_placed_[static_cast<std::size_t>(n)]; });
  if (placed) check_shape(*corners, *o.find("nodes"), o.at("nodes"));
  return corners;
}

void Reader::check_shape(const NodeList& corners, const json& ids, const std::string& pointer) {
  const auto n = static_cast<std::size_t>(corners.count);
  // Eigen leaves default-constructed vectors uninitialised; the unused corner of a triangle too.
  std::array<Vec2, 4> x;
  x.fill(Vec2::Zero());
  std::array<Vec2, 4> reversed = x;
  for (std::size_t k = 0; k < n; ++k) {
    const Node& node = model_.nodes[static_cast<std::size_t>(corners.nodes[k])];
    x[k] = Vec2(node.r, node.z);
    reversed[n - 1 - k] = x[k];
  }
  const double smallest = min_twice_area(corners.count, x);
  if (smallest > 0.0) return;
  double twice_area = 0.0;  // shoelace formula
  for (std::size_t k = 0; k < n; ++k) {
    const Vec2& a = x[k];
    const Vec2& b = x[(k + 1) % n];
    twice_area += a.x() * b.y() - b.x() * a.y();
  }
  const std::string area = "signed area " + format_number(0.5 * twice_area);
  // A shape that is fine the other way round is only listed clockwise: say how to list it.
  if (min_twice_area(corners.count, reversed) > 0.0) {
    json fixed = json::array();
    for (std::size_t k = n; k-- > 0;) fixed.push_back(ids[k]);
    report(pointer, "nodes " + quote(ids) + " are clockwise (" + area + "); list them counter-clockwise, e.g. " +
                        quote(fixed));
  } else if (corners.count == 3) {
    report(pointer, "nodes " + quote(ids) + " are collinear (" + area + "); a triangle needs a positive area");
  } else {
    report(pointer, "nodes " + quote(ids) + " do not form a convex, non-degenerate quadrilateral in this order (" +
                        area + ", smallest triangle around the centre node has twice area " +
                        format_number(smallest) +
                        "); the SAAS element needs all 4 triangles between its edges and the centre of its "
                        "corners to have positive area, counter-clockwise");
  }
}

// ---- tables

template <class Row>
std::optional<Row> Reader::read_row(const json& value, const std::string& pointer,
                                    std::span<const Field<Row>> fields) {
  std::vector<std::string_view> keys;
  for (const Field<Row>& f : fields) keys.push_back(f.key);
  if (!check_object(value, pointer, keys, {})) return std::nullopt;
  const Obj o{value, pointer};
  Row row{};
  bool complete = true;
  for (const Field<Row>& f : fields) {
    const auto v = number_field(o, f.key, *f.range);
    if (v) {
      row.*f.member = *v;
    } else {
      complete = false;
    }
  }
  if (!complete) return std::nullopt;
  return row;
}

/// Rows must be in strictly increasing T: interpolation needs a function of T. The order is judged
/// on every row whose T is a valid number, even when another value of the row is bad. `finish`
/// completes and checks a valid row at its pointer.
template <class Row, class Finish>
std::vector<Row> Reader::read_table(const json& rows, const std::string& pointer,
                                    std::span<const Field<Row>> fields, Finish finish) {
  std::vector<Row> table;
  const json* previous_T = nullptr;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const std::string row_pointer = pointer_append(pointer, i);
    auto row = read_row(rows[i], row_pointer, fields);
    // read_row has reported a missing or bad T; here only the order matters.
    const auto found = rows[i].is_object() ? rows[i].find("T") : rows[i].end();
    const json* T = found != rows[i].end() ? &*found : nullptr;
    if (T != nullptr && T->is_number() && std::isfinite(T->get<double>())) {
      if (previous_T != nullptr && !(T->get<double>() > previous_T->get<double>())) {
        report(pointer_append(row_pointer, "T"), "T = " + quote(*T) + " does not follow T = " + quote(*previous_T) +
                                                     " of an earlier row; rows must be in strictly increasing T");
      }
      previous_T = T;
    }
    if (!row) continue;
    finish(*row, row_pointer);
    table.push_back(*row);
  }
  return table;
}

std::vector<PropertyRow> Reader::read_property_table(const Obj& o, std::string_view key, bool isotropic,
                                                     std::size_t min_rows) {
  const json* rows = array_field(o, key, min_rows);
  if (rows == nullptr) return {};
  const auto finish = [&](PropertyRow& row, const std::string& row_pointer) {
    if (isotropic) {
      row.E2 = row.E3 = row.E1;
      row.nu13 = row.nu23 = row.nu12;
      row.alpha2 = row.alpha3 = row.alpha1;
      row.G12 = row.E1 / (2.0 * (1.0 + row.nu12));
      return;  // -1 < nu < 0.5 and E > 0 already make it positive definite
    }
    if (!positive_definite(constants_of(row))) {
      report(row_pointer,
             "these orthotropic constants are not admissible: their compliance matrix is not positive definite "
             "(E1 = " + format_number(row.E1) + ", E2 = " + format_number(row.E2) + ", E3 = " +
                 format_number(row.E3) + ", nu12 = " + format_number(row.nu12) + ", nu13 = " +
                 format_number(row.nu13) + ", nu23 = " + format_number(row.nu23) + ", G12 = " +
                 format_number(row.G12) + "); the Poisson ratios are too large for the moduli (each nu_ij^2 must be "
                 "below E_i/E_j, and the compliance determinant must be positive)");
    }
  };
  if (isotropic) return read_table<PropertyRow>(*rows, o.at(key), isotropic_fields, finish);
  return read_table<PropertyRow>(*rows, o.at(key), orthotropic_fields, finish);
}

std::vector<PlasticityRow> Reader::read_plasticity(const Obj& o) {
  const json* v = o.find("plasticity");
  if (v == nullptr) return {};
  const std::string pointer = o.at("plasticity");
  if (v->is_object()) {
    const auto curve = read_row<PlasticityRow>(*v, pointer, plasticity_curve_fields);
    if (!curve) return {};
    return {*curve};
  }
  if (!v->is_array()) {
    report(pointer, "plasticity must be an object {yield_stress, hardening_ratio} or an array of rows {T, "
                    "yield_stress, hardening_ratio}, got " + describe(*v));
    return {};
  }
  if (array(*v, pointer, "plasticity", 1) == nullptr) return {};
  return read_table<PlasticityRow>(*v, pointer, plasticity_row_fields, [](PlasticityRow&, const std::string&) {});
}

// ---- sections

Model Reader::read(const json& document) {
  if (object(document, "", {"schema_version", "title", "analysis", "nodes", "materials", "elements", "constraints"},
             {"description", "units", "gaps", "loads", "solver", "output"})) {
    const Obj root{document, ""};
    // Order matters: analysis before nodes (r >= 0), nodes and materials before the elements that
    // use them, every element before pressures and watch lists.
    read_header(root);
    read_analysis(root);
    read_nodes(root);
    read_materials(root);
    read_elements(root);
    read_gaps(root);
    read_constraints(root);
    read_loads(root);
    read_solver(root);
    read_output(root);
  }
  if (!issues_.empty()) throw ModelError(std::move(issues_));
  return std::move(model_);
}

/// schema_version is the integer 1; title a string; description an optional string.
void Reader::read_header(const Obj& root) {
  if (const json* version = root.find("schema_version")) {
    if (!(version->is_number_integer() && *version == 1)) {
      report(root.at("schema_version"),
             "schema_version must be the integer 1 (the only version this reader knows), got " + describe(*version));
    }
  }
  model_.title = string_field(root, "title").value_or("");
  model_.description = string_field(root, "description").value_or("");
  read_units(root);
}

/// Optional names of the units (length, force, stress, temperature), each an optional non-empty
/// string; the solver never converts, so these are labels for results, plots and VTU fields.
void Reader::read_units(const Obj& root) {
  const json* v = root.find("units");
  if (v == nullptr) return;
  const std::string pointer = root.at("units");
  if (!check_object(*v, pointer, {}, unit_names)) return;
  const Obj o{*v, pointer};
  std::array<std::string*, 4> targets{&model_.units.length, &model_.units.force, &model_.units.stress,
                                      &model_.units.temperature};
  for (std::size_t i = 0; i < unit_names.size(); ++i) {
    const auto name = string_field(o, unit_names[i]);
    if (!name) continue;
    if (name->empty()) {
      report(o.at(unit_names[i]), std::string(unit_names[i]) + " must be a non-empty unit name, got \"\"");
      continue;
    }
    *targets[i] = *name;
  }
}

/// type is one of three; thickness > 0 and only in plane analyses; reference_temperature a number.
void Reader::read_analysis(const Obj& root) {
  const json* v = root.find("analysis");
  if (v == nullptr || !object(*v, root.at("analysis"), {"type"}, {"thickness", "reference_temperature"})) return;
  const Obj analysis{*v, root.at("analysis")};
  if (const auto type = choice_field(analysis, "type", analysis_names)) {
    analysis_ = static_cast<AnalysisType>(*type);
    model_.analysis = *analysis_;
  }
  if (const json* thickness = analysis.find("thickness")) {
    if (analysis_ == AnalysisType::axisymmetric) {
      report(analysis.at("thickness"), "thickness " + quote(*thickness) +
                                           " applies only to plane analyses; an axisymmetric model spans the full "
                                           "ring, so remove it");
    } else {
      model_.thickness = number(*thickness, analysis.at("thickness"), "thickness", positive).value_or(1.0);
    }
  }
  model_.reference_temperature = number_field(analysis, "reference_temperature").value_or(0.0);
}

/// A non-empty array of {id, r, z}; ids unique; axisymmetric nodes at r >= 0.
void Reader::read_nodes(const Obj& root) {
  const json* list = array_field(root, "nodes", 1);
  nodes_complete_ = list != nullptr;
  if (list == nullptr) return;
  const Range& radius = analysis_ == AnalysisType::axisymmetric ? axisymmetric_radius : any_number;
  for (std::size_t i = 0; i < list->size(); ++i) {
    const std::string pointer = pointer_append(root.at("nodes"), i);
    if (!object((*list)[i], pointer, {"id", "r", "z"})) continue;
    const Obj o{(*list)[i], pointer};
    const auto id = integer_field(o, "id", 1);
    const auto r = number_field(o, "r", radius);
    const auto z = number_field(o, "z");
    if (!id || !is_new(nodes_, *id, o.at("id"), "node")) continue;
    nodes_.emplace(*id, Entry{as_index(model_.nodes.size()), false, pointer});
    model_.nodes.push_back(Node{*id, r.value_or(0.0), z.value_or(0.0)});
    node_placed_.push_back(r && z);
  }
}

/// A non-empty array; ids unique; table rows shaped by elastic; density >= 0; optional plasticity.
void Reader::read_materials(const Obj& root) {
  const json* list = array_field(root, "materials", 1);
  materials_complete_ = list != nullptr;
  if (list == nullptr) return;
  for (std::size_t i = 0; i < list->size(); ++i) {
    const std::string pointer = pointer_append(root.at("materials"), i);
    if (!object((*list)[i], pointer, {"id", "elastic", "table"},
                {"name", "density", "compression_table", "plasticity"})) {
      continue;
    }
    const Obj o{(*list)[i], pointer};
    Material m;
    const auto id = integer_field(o, "id", 1);
    m.name = string_field(o, "name").value_or("");
    m.density = number_field(o, "density", non_negative).value_or(0.0);
    // The row shape depends on the kind: without a valid kind the rows cannot be judged.
    if (const auto kind = choice_field(o, "elastic", elastic_names)) {
      m.isotropic = *kind == 0;
      m.table = read_property_table(o, "table", m.isotropic, 1);
      m.compression_table = read_property_table(o, "compression_table", m.isotropic, 0);
    }
    m.plasticity = read_plasticity(o);
    if (!id || !is_new(materials_, *id, o.at("id"), "material")) continue;
    m.id = *id;
    materials_.emplace(*id, Entry{as_index(model_.materials.size()), false, pointer});
    model_.materials.push_back(std::move(m));
  }
}

/// A non-empty array of {id, nodes, material, angle?}; ids unique among all elements.
void Reader::read_elements(const Obj& root) {
  const json* list = array_field(root, "elements", 1);
  solids_complete_ = list != nullptr;
  if (list == nullptr) return;
  for (std::size_t i = 0; i < list->size(); ++i) {
    const std::string pointer = pointer_append(root.at("elements"), i);
    if (!object((*list)[i], pointer, {"id", "nodes", "material"}, {"angle"})) continue;
    const Obj o{(*list)[i], pointer};
    Element e;
    const auto id = new_element_id(o);
    const auto corners = read_corners(o);
    const json* material = o.find("material");
    const Entry* m = material == nullptr ? nullptr
                                         : resolve(materials_, materials_complete_, *material, o.at("material"),
                                                   "material", "/materials");
    e.angle_deg = number_field(o, "angle").value_or(0.0);
    if (!id) continue;
    e.id = *id;
    if (corners) {
      e.nodes = corners->nodes;
      e.node_count = corners->count;
    }
    if (m != nullptr) e.material = m->index;
    elements_.emplace(*id, Entry{as_index(model_.elements.size()), false, pointer});
    model_.elements.push_back(e);
  }
}

/// Optional. E0 > 0, a non-empty schedule of positive moduli, 0 <= XFACT < 1, 0 < tolerance < 1,
/// shear ratio > 0, and a non-empty array of gap elements {id, nodes, angle} (angle required).
void Reader::read_gaps(const Obj& root) {
  const json* v = root.find("gaps");
  if (v == nullptr) return;
  const std::string pointer = root.at("gaps");
  if (!object(*v, pointer, {"initial_modulus", "tensile_schedule", "elements"},
              {"method", "extrapolation_factor", "closure_tolerance", "shear_ratio", "convergence_test"})) {
    gaps_complete_ = false;
    return;
  }
  const Obj g{*v, pointer};
  GapSettings& s = model_.gaps.emplace();
  if (const auto method = choice_field(g, "method", gap_method_names)) s.method = static_cast<GapMethod>(*method);
  s.initial_modulus = number_field(g, "initial_modulus", positive).value_or(s.initial_modulus);
  if (const json* schedule = array_field(g, "tensile_schedule", 1)) {
    for (std::size_t i = 0; i < schedule->size(); ++i) {
      const std::string name = "tensile_schedule[" + std::to_string(i) + "]";
      if (const auto modulus = number((*schedule)[i], pointer_append(g.at("tensile_schedule"), i), name, positive)) {
        s.tensile_schedule.push_back(*modulus);
      }
    }
  }
  s.extrapolation_factor = number_field(g, "extrapolation_factor", extrapolation).value_or(s.extrapolation_factor);
  s.closure_tolerance = number_field(g, "closure_tolerance", tolerance_fraction).value_or(s.closure_tolerance);
  s.shear_ratio = number_field(g, "shear_ratio", positive).value_or(s.shear_ratio);
  if (const auto test = choice_field(g, "convergence_test", convergence_test_names)) {
    s.convergence_test = static_cast<GapConvergenceTest>(*test);
  }
  const json* list = array_field(g, "elements", 1);
  gaps_complete_ = list != nullptr;
  if (list == nullptr) return;
  for (std::size_t i = 0; i < list->size(); ++i) {
    const std::string item = pointer_append(g.at("elements"), i);
    if (!object((*list)[i], item, {"id", "nodes", "angle"})) continue;
    const Obj o{(*list)[i], item};
    GapElement e;
    const auto id = new_element_id(o);
    const auto corners = read_corners(o);
    e.angle_deg = number_field(o, "angle").value_or(0.0);
    if (!id) continue;
    e.id = *id;
    if (corners) {
      e.nodes = corners->nodes;
      e.node_count = corners->count;
    }
    elements_.emplace(*id, Entry{as_index(s.elements.size()), true, item});
    s.elements.push_back(e);
  }
}

/// A non-empty array of {node, r?, z?} with r and/or z; no component of a node twice.
void Reader::read_constraints(const Obj& root) {
  const json* list = array_field(root, "constraints", 0);
  if (list == nullptr) return;
  if (list->empty()) {
    report(root.at("constraints"), "the model has no constraints: it can move as a rigid body; prescribe r and/or z "
                                   "at enough nodes to hold it");
    return;
  }
  std::map<std::pair<int, char>, std::string> prescribed;  // (node index, component) -> first pointer
  for (std::size_t i = 0; i < list->size(); ++i) {
    const std::string pointer = pointer_append(root.at("constraints"), i);
    if (!object((*list)[i], pointer, {"node"}, {"r", "z"})) continue;
    const Obj o{(*list)[i], pointer};
    const json* node_id = o.find("node");
    const Entry* node = node_id == nullptr ? nullptr : resolve_node(*node_id, o.at("node"));
    Constraint c;
    c.u_r = number_field(o, "r");
    c.u_z = number_field(o, "z");
    if (o.find("r") == nullptr && o.find("z") == nullptr) {
      report(pointer, "the constraint of node " + (node_id ? quote(*node_id) : std::string("?")) +
                          " prescribes neither r nor z; give r and/or z (the prescribed displacement)");
    }
    if (node == nullptr) continue;
    c.node = node->index;
    for (const char component : {'r', 'z'}) {
      const std::string_view key = component == 'r' ? "r" : "z";
      if (o.find(key) == nullptr) continue;
      const auto [first, fresh] = prescribed.emplace(std::pair{node->index, component}, o.at(key));
      if (!fresh) {
        report(o.at(key), std::string(key) + " of node " + quote(*node_id) + " is already prescribed at " +
                              first->second + "; prescribe each component once");
      }
    }
    model_.constraints.push_back(c);
  }
}

void Reader::read_loads(const Obj& root) {
  // Every node has a temperature; without a temperature load it is the stress-free one.
  model_.loads.node_temperature.assign(model_.nodes.size(), model_.reference_temperature);
  const json* v = root.find("loads");
  if (v == nullptr || !object(*v, root.at("loads"), {}, {"nodal_forces", "pressures", "temperatures", "body_force"})) {
    return;
  }
  const Obj loads{*v, root.at("loads")};
  read_nodal_forces(loads);
  read_pressures(loads);
  read_temperatures(loads);
  read_body_force(loads);
}

/// {node, fr?, fz?}; forces on one node add up.
void Reader::read_nodal_forces(const Obj& loads) {
  const json* list = array_field(loads, "nodal_forces", 0);
  if (list == nullptr) return;
  for (std::size_t i = 0; i < list->size(); ++i) {
    const std::string pointer = pointer_append(loads.at("nodal_forces"), i);
    if (!object((*list)[i], pointer, {"node"}, {"fr", "fz"})) continue;
    const Obj o{(*list)[i], pointer};
    const json* node_id = o.find("node");
    const Entry* node = node_id == nullptr ? nullptr : resolve_node(*node_id, o.at("node"));
    NodalForce f;
    f.f_r = number_field(o, "fr").value_or(0.0);
    f.f_z = number_field(o, "fz").value_or(0.0);
    if (node == nullptr) continue;
    f.node = node->index;
    model_.loads.nodal_forces.push_back(f);
  }
}

/// {nodes: [a, b], normal?, shear?} on an edge of exactly one solid element.
void Reader::read_pressures(const Obj& loads) {
  const json* list = array_field(loads, "pressures", 0);
  if (list == nullptr) return;
  // Solid elements owning each edge, keyed by the ordered pair of node indices. Gap elements never
  // own a pressure edge: their stiffness is the program's, not a body's.
  std::map<std::pair<int, int>, std::vector<int>> owners;
  for (std::size_t e = 0; e < model_.elements.size(); ++e) {
    const Element& element = model_.elements[e];
    const auto corners = static_cast<std::size_t>(element.node_count);
    for (std::size_t k = 0; k < corners; ++k) {
      const int a = element.nodes[k];
      const int b = element.nodes[(k + 1) % corners];
      if (a >= 0 && b >= 0) owners[std::minmax(a, b)].push_back(as_index(e));
    }
  }
  for (std::size_t i = 0; i < list->size(); ++i) {
    const std::string pointer = pointer_append(loads.at("pressures"), i);
    if (!object((*list)[i], pointer, {"nodes"}, {"normal", "shear"})) continue;
    const Obj o{(*list)[i], pointer};
    EdgePressure p;
    p.normal = number_field(o, "normal").value_or(0.0);
    p.shear = number_field(o, "shear").value_or(0.0);
    const auto edge = read_node_list(o, 2, 2, "a pressure edge has exactly 2 nodes");
    if (!edge || !edge->complete() || !solids_complete_) continue;
    const json& ids = *o.find("nodes");
    const auto found = owners.find(std::minmax(edge->nodes[0], edge->nodes[1]));
    if (found == owners.end()) {
      report(o.at("nodes"), "no solid element has the edge " + quote(ids) +
                                ": the two nodes must be consecutive corners of one solid element (gap elements "
                                "carry no pressure)");
      continue;
    }
    if (found->second.size() > 1) {
      std::string names;
      for (const int e : found->second) {
        names += (names.empty() ? "" : " and ") + std::to_string(model_.elements[static_cast<std::size_t>(e)].id);
      }
      report(o.at("nodes"), "the edge " + quote(ids) + " is shared by elements " + names +
                                "; a pressure acts on a boundary edge, which exactly one solid element has");
      continue;
    }
    p.element = found->second.front();
    p.node_a = edge->nodes[0];
    p.node_b = edge->nodes[1];
    model_.loads.pressures.push_back(p);
  }
}

/// {default?, nodal?: [{node, T}]}; one temperature per node.
void Reader::read_temperatures(const Obj& loads) {
  const json* v = loads.find("temperatures");
  if (v == nullptr || !object(*v, loads.at("temperatures"), {}, {"default", "nodal"})) return;
  const Obj temperatures{*v, loads.at("temperatures")};
  if (const auto fallback = number_field(temperatures, "default")) {
    model_.loads.node_temperature.assign(model_.nodes.size(), *fallback);
  }
  const json* list = array_field(temperatures, "nodal", 0);
  if (list == nullptr) return;
  std::unordered_map<int, std::string> given;  // node index -> pointer of its temperature
  for (std::size_t i = 0; i < list->size(); ++i) {
    const std::string pointer = pointer_append(temperatures.at("nodal"), i);
    if (!object((*list)[i], pointer, {"node", "T"})) continue;
    const Obj o{(*list)[i], pointer};
    const json* node_id = o.find("node");
    const Entry* node = node_id == nullptr ? nullptr : resolve_node(*node_id, o.at("node"));
    const auto T = number_field(o, "T");
    if (node == nullptr) continue;
    const auto [first, fresh] = given.emplace(node->index, pointer);
    if (!fresh) {
      report(o.at("node"), "node " + quote(*node_id) + " already has a temperature at " + first->second +
                               "; give each node one temperature");
      continue;
    }
    if (T) model_.loads.node_temperature[static_cast<std::size_t>(node->index)] = *T;
  }
}

/// {accel_r?, accel_z?, omega?}; omega != 0 only in axisymmetric analyses.
void Reader::read_body_force(const Obj& loads) {
  const json* v = loads.find("body_force");
  if (v == nullptr || !object(*v, loads.at("body_force"), {}, {"accel_r", "accel_z", "omega"})) return;
  const Obj o{*v, loads.at("body_force")};
  BodyForce& b = model_.loads.body_force;
  b.accel_r = number_field(o, "accel_r").value_or(0.0);
  b.accel_z = number_field(o, "accel_z").value_or(0.0);
  b.omega = number_field(o, "omega").value_or(0.0);
  if (b.omega != 0.0 && analysis_ && *analysis_ != AnalysisType::axisymmetric) {
    report(o.at("omega"), "omega = " + quote(*o.find("omega")) + " spins the body about the z axis, which only an "
                          "axisymmetric analysis represents; this model is " +
                              std::string(analysis_names[static_cast<std::size_t>(*analysis_)]) +
                              " (remove omega or set it to 0)");
  }
}

/// {max_iterations?: integer >= 1, plastic_tolerance?: > 0}.
void Reader::read_solver(const Obj& root) {
  const json* v = root.find("solver");
  if (v == nullptr || !object(*v, root.at("solver"), {}, {"max_iterations", "plastic_tolerance"})) return;
  const Obj o{*v, root.at("solver")};
  model_.solver.max_iterations = integer_field(o, "max_iterations", 1).value_or(model_.solver.max_iterations);
  model_.solver.plastic_tolerance =
      number_field(o, "plastic_tolerance", positive).value_or(model_.solver.plastic_tolerance);
}

void Reader::read_output(const Obj& root) {
  const json* v = root.find("output");
  if (v == nullptr || !object(*v, root.at("output"), {}, {"watch_elements", "watch_gaps"})) return;
  const Obj o{*v, root.at("output")};
  model_.output.watch_elements = read_watch_list(o, "watch_elements", false);
  model_.output.watch_gaps = read_watch_list(o, "watch_gaps", true);
}

/// Ids of solid elements (watch_elements) or gap elements (watch_gaps), each once.
std::vector<int> Reader::read_watch_list(const Obj& output, std::string_view key, bool gaps) {
  const json* list = array_field(output, key, 0);
  if (list == nullptr) return {};
  std::vector<int> indices;
  std::unordered_map<int, std::string> watched;  // index -> pointer that first named it
  for (std::size_t i = 0; i < list->size(); ++i) {
    const std::string pointer = pointer_append(output.at(key), i);
    const Entry* e =
        resolve(elements_, elements_complete(), (*list)[i], pointer, "element", "/elements or /gaps/elements");
    if (e == nullptr) continue;
    if (e->gap != gaps) {
      report(pointer, gaps ? "element " + quote((*list)[i]) +
                                 " is a solid element; watch_gaps lists gap elements (watch it in watch_elements)"
                           : "element " + quote((*list)[i]) +
                                 " is a gap element; watch_elements lists solid elements (watch it in watch_gaps)");
      continue;
    }
    const auto [first, fresh] = watched.emplace(e->index, pointer);
    if (!fresh) {
      report(pointer, "element " + quote((*list)[i]) + " is already watched at " + first->second);
      continue;
    }
    indices.push_back(e->index);
  }
  return indices;
}

// ------------------------------------------------------------------------------------------------
// Text: the parser forgets where it was and keeps only the last of repeated keys, so a first pass
// over the text with a SAX handler tracks the path of each value. (A parse callback would do the
// same in one pass, but nlohmann 3.11.2's callback parser rescans the enclosing array at every
// object end: quadratic in the number of nodes.)

class PathTracker : public json::json_sax_t {
 public:
  bool null() override { return value(); }
  bool boolean(bool) override { return value(); }
  bool number_integer(json::number_integer_t) override { return value(); }
  bool number_unsigned(json::number_unsigned_t) override { return value(); }
  bool number_float(json::number_float_t, const json::string_t&) override { return value(); }
  bool string(json::string_t&) override { return value(); }
  bool binary(json::binary_t&) override { return value(); }
  bool start_object(std::size_t) override {
    frames_.push_back(Frame{true, {}, 0, {}});
    return true;
  }
  bool key(json::string_t& name) override {
    Frame& top = frames_.back();
    top.key = name;
    if (!top.keys.insert(top.key).second) {
      repeated_.push_back(InputIssue{pointer(), "key " + quote_string(top.key) +
                                                    " appears more than once in this object; a JSON reader keeps "
                                                    "only one of the values, so give each key once"});
    }
    return true;
  }
  bool end_object() override { return end_container(); }
  bool start_array(std::size_t) override {
    frames_.push_back(Frame{false, {}, 0, {}});
    return true;
  }
  bool end_array() override { return end_container(); }
  bool parse_error(std::size_t byte, const std::string&, const nlohmann::detail::exception& e) override {
    // A number beyond the range of a double (out_of_range.406, e.g. 1e400) stops the parser inside
    // the value the tracker is at; anything else is text that is not JSON.
    if (e.id == 406) {
      error_ = InputIssue{pointer(), without_exception_tag(e.what()) +
                                         "; numbers must be finite and within the range of a double"};
    } else {
      error_ = InputIssue{"", "the document is not valid JSON: " + without_exception_tag(e.what()) + " (byte " +
                                  std::to_string(byte) + ")"};
    }
    return false;
  }

  /// The pointer of the value being parsed now.
  [[nodiscard]] std::string pointer() const {
    std::string text;
    for (const Frame& f : frames_) text = f.is_object ? pointer_append(text, f.key) : pointer_append(text, f.index);
    return text;
  }

  std::vector<InputIssue>& repeated_keys() { return repeated_; }
  [[nodiscard]] const std::optional<InputIssue>& error() const { return error_; }

 private:
  struct Frame {
    bool is_object = false;
    std::string key;        ///< objects: the current member
    std::size_t index = 0;  ///< arrays: the current item
    std::unordered_set<std::string> keys;
  };

  /// nlohmann's what() starts with "[json.exception.parse_error.101] "; the user needs the rest.
  static std::string without_exception_tag(const char* what) {
    std::string text = what;
    if (const auto end = text.find("] "); text.starts_with("[json.exception.") && end != std::string::npos) {
      text.erase(0, end + 2);
    }
    return text;
  }

  bool value() {
    next_item();
    return true;
  }
  bool end_container() {
    frames_.pop_back();
    next_item();
    return true;
  }
  void next_item() {
    if (!frames_.empty() && !frames_.back().is_object) ++frames_.back().index;
  }

  std::vector<Frame> frames_;
  std::vector<InputIssue> repeated_;
  std::optional<InputIssue> error_;
};

/// Parses text, tracking the path so that repeated keys (returned) and number overflows (thrown)
/// name their pointer. Text that is not JSON throws one issue at "".
json parse_text(std::string_view text, std::vector<InputIssue>& repeated_keys) {
  PathTracker tracker;
  json::sax_parse(text.begin(), text.end(), &tracker);
  if (tracker.error()) throw ModelError({*tracker.error()});
  repeated_keys = std::move(tracker.repeated_keys());
  return json::parse(text.begin(), text.end());
}

}  // namespace

Model read_model(const nlohmann::json& document) { return Reader().read(document); }

nlohmann::json parse_document(std::string_view text) {
  std::vector<InputIssue> repeated_keys;
  json document = parse_text(text, repeated_keys);
  if (!repeated_keys.empty()) throw ModelError(std::move(repeated_keys));
  return document;
}

Model parse_model(std::string_view text) {
  std::vector<InputIssue> issues;
  const json document = parse_text(text, issues);
  try {
    Model model = read_model(document);
    if (issues.empty()) return model;
  } catch (const ModelError& e) {
    issues.insert(issues.end(), e.issues().begin(), e.issues().end());
  }
  throw ModelError(std::move(issues));
}

}  // namespace saasgaps::io
