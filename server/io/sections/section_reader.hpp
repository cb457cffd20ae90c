#pragma once
/// The model reader's rules, section by section (internal to io/). A SectionReader judges the
/// values of one document, accumulating issues, and builds the Model. It is driven either by a
/// document tree (read_model) or by the streaming pass over the text (model_stream.cpp), which hands
/// it each item of nodes, elements and constraints as a small tree of its own and every other
/// section whole; both give the same issues in the same order.
///
/// Files: section_reader.cpp (the sections, in document order), section_steps.cpp (load steps),
/// section_contact.cpp (contact surfaces and pairs), section_sets.cpp (named sets of nodes, edges
/// and elements, and the constraints and pressures that name them),
/// section_thermal.cpp (heat conduction: the thermal section and the materials' k and c),
/// section_checks.cpp (generic
/// value checks and temperature tables), section_references.cpp (ids, references and element
/// shapes), section_items.cpp (the typed fast path of valid items), value_quote.cpp (how values
/// are quoted in messages).

#include <algorithm>
#include <array>
#include <cstdint>
#include <initializer_list>
#include <limits>
#include <map>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <unordered_map>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "io/json/json_pointer.hpp"
#include "io/json/value_rules.hpp"
#include "solver/base/errors.hpp"
#include "solver/model/model.hpp"

namespace saasgaps::io {

using nlohmann::json;

template <class Row>
struct Field {
  std::string_view key;
  double Row::*member;
  const Range* range;
  bool optional = false;  ///< the row may omit it (the member keeps its default)
};

/// materials[].elastic (Material::isotropic).
enum class ElasticKind { isotropic, orthotropic };
inline constexpr NameTable<ElasticKind, 2> elastic_kind_names{
    {{{ElasticKind::isotropic, "isotropic"}, {ElasticKind::orthotropic, "orthotropic"}}}};
constexpr std::array<std::string_view, 4> unit_names{"length", "force", "stress", "temperature"};

/// An object of the document (already checked by SectionReader::object) and its pointer; or a
/// view of the document's root that holds one member only (a section read on its own).
struct Obj {
  const json* value;          ///< the object; in a one-member view, that member's value (nullptr: absent)
  std::string pointer;
  std::string_view member{};  ///< non-empty: a one-member view of the root

  [[nodiscard]] const json* find(std::string_view key) const {
    if (!member.empty()) return key == member ? value : nullptr;
    const auto it = value->find(key);
    return it == value->end() ? nullptr : &*it;
  }
  [[nodiscard]] std::string at(std::string_view key) const { return pointer_append(pointer, key); }
};

/// A JSON Pointer spelled only when an issue needs it: a pointer, or a pointer and one more token
/// (a member's key or an item's index). The checks of a valid value build no text at all.
class Where {
 public:
  Where(const std::string& pointer) : base_(pointer) {}  // NOLINT: a spelled pointer is a Where
  Where(const std::string& base, std::string_view key) : base_(base), key_(key), kind_(Kind::key) {}
  Where(const std::string& base, std::size_t index) : base_(base), index_(index), kind_(Kind::index) {}
  [[nodiscard]] std::string str() const {
    if (kind_ == Kind::key) return pointer_append(base_, key_);
    if (kind_ == Kind::index) return pointer_append(base_, index_);
    return base_;
  }

 private:
  enum class Kind { whole, key, index };
  const std::string& base_;  // outlives the Where: the Where lives for one call
  std::string_view key_{};
  std::size_t index_ = 0;
  Kind kind_ = Kind::whole;
};

/// Where an id was defined, so a repeated id can name the first definition. (The item's index,
/// not its pointer text: a registry holds an entry per node and element, 10^6 of them.)
struct Entry {
  int index = 0;     ///< into Model::nodes, Model::materials, Model::elements or GapSettings::elements
  bool gap = false;  ///< element ids: a gap element
  int item = 0;      ///< index in the document's array (/nodes/item, /gaps/elements/item, ...)
};

/// Ids of one kind (solid and gap elements share one kind). Models number their items 1..n or
/// nearly so: such ids index a vector (a hash lookup per reference cost a tenth of the reading of a
/// large model); ids far beyond the count go to a hash map, so memory stays linear in the count.
class Registry {
 public:
  /// The entry of id; nullptr when there is none.
  [[nodiscard]] const Entry* find(int id) const {
    if (id >= 1 && static_cast<std::size_t>(id) <= dense_.size()) {
      const Entry& e = dense_[static_cast<std::size_t>(id) - 1];
      if (e.index >= 0) return &e;
    }
    if (sparse_.empty()) return nullptr;
    const auto found = sparse_.find(id);
    return found == sparse_.end() ? nullptr : &found->second;
  }
  [[nodiscard]] bool contains(int id) const { return find(id) != nullptr; }
  /// Adds an id that find() does not know.
  void emplace(int id, Entry entry) {
    ++count_;
    const auto slot = static_cast<std::size_t>(id);
    if (id >= 1 && slot > dense_.size() && slot <= 2 * count_ + 4096) {
      dense_.resize(std::max(slot, 2 * dense_.size()), Entry{-1, false, 0});
    }
    if (id >= 1 && slot <= dense_.size()) {
      dense_[slot - 1] = entry;
    } else {
      sparse_.emplace(id, entry);
    }
  }

 private:
  std::vector<Entry> dense_;  ///< by id - 1; index -1 where no id
  std::unordered_map<int, Entry> sparse_;
  std::size_t count_ = 0;
};

/// Up to four node indices of an element, a gap element or a pressure edge; -1 where an id did not
/// resolve (the rest still serve, e.g. as edges that a pressure may name).
struct NodeList {
  std::array<int, max_element_nodes> nodes{-1, -1, -1, -1, -1, -1, -1, -1, -1};
  int count = 0;
  [[nodiscard]] bool complete() const {
    return std::none_of(nodes.begin(), nodes.begin() + count, [](int n) { return n < 0; });
  }
};

inline int as_index(std::size_t i) { return static_cast<int>(i); }

/// The top-level members of a model document, in the order the reader judges them.
enum class Section {
  schema_version, title, description, units, analysis, nodes, materials, elements, gaps, sets, constraints, loads,
  solver, output, steps, contact, thermal
};
constexpr std::size_t section_count = 17;

/// The member name of a section.
std::string_view section_key(Section s);
/// The section of a member name; nullopt for a key the document may not have.
std::optional<Section> section_of(std::string_view key);
/// The sections that must be read before this one (analysis before nodes, nodes and materials
/// before elements, ...). A streaming reader reads a section when these are done, else later.
std::span<const Section> dependencies(Section s);
/// nodes, elements and constraints: arrays that may be read item by item.
bool streams_items(Section s);

/// A JSON number as the text wrote it: an integer keeps its exact value and kind (as nlohmann's
/// parser does: unsigned when it has no sign), anything with a fraction or an exponent is a double.
struct Number {
  enum class Kind { signed_integer, unsigned_integer, floating };
  Kind kind = Kind::floating;
  std::int64_t integer = 0;     ///< signed_integer
  std::uint64_t unsigned_ = 0;  ///< unsigned_integer
  double floating = 0.0;        ///< floating
  /// The value as nlohmann's get<double>() gives it.
  [[nodiscard]] double value() const {
    switch (kind) {
      case Kind::signed_integer: return static_cast<double>(integer);
      case Kind::unsigned_integer: return static_cast<double>(unsigned_);
      case Kind::floating: break;
    }
    return floating;
  }
  /// An id: a JSON integer in 1..INT_MAX; nullopt for anything else.
  [[nodiscard]] std::optional<int> id() const {
    constexpr auto largest = static_cast<std::uint64_t>(std::numeric_limits<int>::max());
    if (kind == Kind::signed_integer && integer >= 1 && static_cast<std::uint64_t>(integer) <= largest) {
      return static_cast<int>(integer);
    }
    if (kind == Kind::unsigned_integer && unsigned_ >= 1 && unsigned_ <= largest) return static_cast<int>(unsigned_);
    return std::nullopt;
  }
};

/// The values of an item of nodes, elements or constraints that has exactly the keys its rule
/// allows, each once, each a number (elements: nodes an array of 3 or 4 numbers). The streaming
/// driver hands such items to SectionReader::read_*_values without building a tree.
struct NodeValues {
  Number id, r, z;
};
struct ElementValues {
  Number id;
  std::array<Number, max_element_nodes> nodes;
  int node_count = 0;
  Number material;
  std::optional<Number> angle;
};
struct ConstraintValues {
  Number node;
  std::optional<Number> r, z;
};
/// An item of the top-level loads.temperatures.nodal with exactly the keys node and T, each once,
/// each a number (a thermal model has one per heated node: 258,000 at 10^6 unknowns).
struct TemperatureValues {
  Number node, T;
};

/// Reads one document, accumulating issues; one function per section of the document. Every
/// check reports its own issue and returns nullopt / nullptr / false, and the caller carries on, so
/// one pass finds every independent problem.
class SectionReader {
 public:
  /// The tree driver: the whole document; the Model or ModelError with every issue.
  Model read(const json& document);

  // The streaming driver (model_stream.cpp). Calls may come in any order that respects
  // dependencies(); finish() orders the issues as read() would.
  /// The document is an object with this key, which it may not have.
  void unknown_root_key(std::string_view key);
  /// The document object has ended: present[s] tells which sections it had.
  void check_required_root_keys(const std::array<bool, section_count>& present);
  /// A key repeated in one object of the text (listed before every other issue).
  void repeated_key(std::string pointer, std::string detail);
  /// A section read whole; value nullptr when the document does not have it.
  void read_section(Section s, const json* value);
  /// A streamed array (streams_items(s)): begin, each item in order, end with their count.
  void begin_items(Section s, std::size_t count_hint = 0);
  void read_item(Section s, const json& item, std::size_t index);
  void end_items(Section s, std::size_t count);
  /// The fast path of read_item for an item of the usual shape (section_items.cpp): true when the
  /// item is valid and has been read, with exactly the effect read_item has; false (nothing
  /// changed, nothing reported) when some rule fails, and read_item must judge the item's tree.
  bool read_node_values(const NodeValues& item, std::size_t index);
  bool read_element_values(const ElementValues& item, std::size_t index);
  bool read_constraint_values(const ConstraintValues& item, std::size_t index);
  /// The fast path of the top-level /loads/temperatures/nodal, called after the nodes are read and
  /// before read_section(loads): true when every item is valid (its node resolves, no node is given
  /// twice); read_section(loads) then takes these values in place of the tree's nodal array, which
  /// the driver leaves empty. False (nothing changed, nothing reported) when some item breaks a
  /// rule, and the tree's nodal array must be judged as usual.
  bool take_nodal_temperatures(std::span<const TemperatureValues> items);
  /// The Model, or ModelError with every issue.
  Model finish();

 private:
  // Generic checks.
  void report(std::string pointer, std::string detail) {
    issues_.push_back(RankedIssue{rank_, InputIssue{std::move(pointer), std::move(detail)}});
  }
  void report(const Where& where, std::string detail) { report(where.str(), std::move(detail)); }
  /// report() as a callable, for the shared checks of value_rules.hpp.
  auto reporter() {
    return [this](const auto& pointer, std::string detail) { report(pointer, std::move(detail)); };
  }
  /// True when value is an object; reports each unknown key at its own pointer and each missing
  /// required key at the object's pointer (the object is still read).
  bool check_object(const json& value, const std::string& pointer, std::span<const std::string_view> required,
                    std::span<const std::string_view> optional);
  bool object(const json& value, const std::string& pointer, std::initializer_list<std::string_view> required,
              std::initializer_list<std::string_view> optional = {}) {
    return check_object(value, pointer, {required.begin(), required.size()}, {optional.begin(), optional.size()});
  }
  bool object(const json& value, const std::string& pointer, std::span<const std::string_view> required,
              std::span<const std::string_view> optional) {
    return check_object(value, pointer, required, optional);
  }
  /// The array, or nullptr (reported) when value is not an array or has fewer than min_items.
  const json* array(const json& value, const std::string& pointer, std::string_view name, std::size_t min_items);
  /// A finite number inside range (booleans are not numbers).
  std::optional<double> number(const json& value, const Where& pointer, std::string_view name,
                               const Range& range);
  /// A JSON integer (1.0 is not one) from minimum to INT_MAX.
  std::optional<int> integer(const json& value, const Where& pointer, std::string_view name, int minimum,
                             int maximum = std::numeric_limits<int>::max());

  // Optional fields of a checked object: absent gives nullopt silently (object() has already
  // reported a missing required key).
  std::optional<double> number_field(const Obj& o, std::string_view key, const Range& range = any_number);
  std::optional<int> integer_field(const Obj& o, std::string_view key, int minimum,
                                   int maximum = std::numeric_limits<int>::max());
  std::optional<std::string> string_field(const Obj& o, std::string_view key);
  /// A string naming one of a table's values (NameTable: solver/base/name_table.hpp).
  template <class E, std::size_t N>
  std::optional<E> choice_field(const Obj& o, std::string_view key, const NameTable<E, N>& table) {
    const auto names = table.names();
    const auto index = choice_index(o, key, names);
    if (!index) return std::nullopt;
    return table.entries()[*index].value;
  }
  /// The position of the string at `key` in `choices` (reported when it is none of them).
  std::optional<std::size_t> choice_index(const Obj& o, std::string_view key, std::span<const std::string_view> choices);
  const json* array_field(const Obj& o, std::string_view key, std::size_t min_items);

  // Ids and references.
  /// False (reported) when id is already in the registry.
  bool is_new(const Registry& registry, int id, const Where& pointer, std::string_view what);
  /// The entry a reference names; nullptr when the value is no id or names nothing (reported
  /// unless the registry is incomplete).
  const Entry* resolve(const Registry& registry, bool complete, const json& value, const Where& pointer,
                       std::string_view what, std::string_view where);
  const Entry* resolve_node(const json& value, const Where& pointer) {
    return resolve(nodes_, nodes_complete_, value, pointer, "node", "/nodes");
  }
  std::optional<int> new_element_id(const Obj& o);
  /// o["nodes"]: min_count..max_count distinct node ids that resolve.
  std::optional<NodeList> read_node_list(const Obj& o, std::size_t min_count, std::size_t max_count,
                                         std::string_view expectation);
  /// An element's 3 or 4 corners, with their shape checked when all are placed.
  std::optional<NodeList> read_corners(const Obj& o);
  /// A solid element's 3, 4, 6, 8 or 9 nodes (a gap element's: 3 or 4).
  std::optional<NodeList> read_element_nodes(const Obj& o);
  /// elements[].type and .integration, checked against the node count; nullopt when they do not fit.
  bool read_element_family(const Obj& o, int node_count, Element& e);
  /// The family's shape rules (fe/element_shape.hpp) on an element whose nodes are all placed.
  void check_element_shape(const Element& e, const json& ids, const Where& pointer);
  /// Counter-clockwise with positive area; for a quadrilateral, each triangle around the centre.
  void check_shape(const NodeList& corners, const json& ids, const Where& pointer);
  /// A gap element's M axis can be judged: its corners are placed and its shape is valid.
  [[nodiscard]] bool gap_axis_judgeable(const NodeList& corners) const;
  /// Each gap's M axis runs across it (solver/gap_faces.hpp: gap_axis_problems, which needs every
  /// solid element and every gap at once), else an issue at its angle's pointer.
  void check_gap_axes(std::span<const GapElement> gaps, std::span<const std::string> angle_pointers);

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

  // Sections, in document order. Each reads its own member of `root`.
  void read_schema_version(const Obj& root);
  void read_units(const Obj& root);
  void read_analysis(const Obj& root);
  void read_item_section(Section s, const Obj& root);
  void incomplete(Section s);
  void read_node(const json& item, const std::string& pointer);
  void read_materials(const Obj& root);
  void read_element(const json& item, const std::string& pointer);
  void read_gaps(const Obj& root);
  void read_constraint(const json& item, const std::string& pointer);
  /// Where a component was prescribed, and its value when a node set prescribed it (two sets that
  /// share a node may prescribe the same value there).
  struct Prescribed {
    Prescribed(std::string at) : pointer(std::move(at)) {}  // NOLINT: a node's own constraint
    Prescribed(std::string at, double value) : pointer(std::move(at)), set_value(value) {}
    std::string pointer;
    std::optional<double> set_value;
  };
  /// (node index, component) -> where the value that prescribed it is.
  using PrescribedAt = std::map<std::pair<int, char>, Prescribed>;
  /// {node, r?, z?}: one constraint; {set, r?, z?}: one per node of the set (section_sets.cpp).
  std::vector<Constraint> read_constraint_item(const json& item, const std::string& pointer, PrescribedAt& seen);
  // section_sets.cpp
  void read_sets(const Obj& root);
  void read_node_sets(const Obj& sets);
  void read_edge_sets(const Obj& sets);
  void read_element_sets(const Obj& sets);
  /// The constraints of {set, r?, z?} (checked by the caller), each component once per node unless
  /// another set gave it the same value; the set joins the model's reaction groups.
  std::vector<Constraint> read_set_constraint(const Obj& o, PrescribedAt& seen);
  /// {set, normal?, shear?} (at o, not yet checked): the pressure on every edge of an edge set, each
  /// a boundary edge (one owner in `owners`).
  void read_set_pressure(const Obj& o, const std::map<std::pair<int, int>, std::vector<int>>& owners, Loads& into);
  /// The nodes (indices) of the node set o["set"] names; nullptr when it names none (reported).
  const std::vector<int>* resolve_set(const Obj& o, std::string_view kind);
  /// The edges of the edge set o["set"] names; nullptr when it names none (reported).
  const std::vector<std::array<int, 2>>* resolve_edge_set(const Obj& o);
  void read_loads(const Obj& root);
  void read_loads_object(const Obj& loads, Loads& into);
  void read_nodal_forces(const Obj& loads, Loads& into);
  void read_pressures(const Obj& loads, Loads& into);
  void read_temperatures(const Obj& loads, Loads& into);
  void read_body_force(const Obj& loads, Loads& into);
  void read_solver(const Obj& root);
  void read_output(const Obj& root);
  std::vector<int> read_watch_list(const Obj& output, std::string_view key, bool gaps);
  // section_steps.cpp
  void read_steps(const Obj& root);
  std::optional<Step> read_step(const json& item, const std::string& pointer);
  // section_contact.cpp
  void read_contact(const Obj& root);
  std::optional<SurfaceDefinition> read_surface(const json& item, const std::string& pointer);
  /// surfaces_complete: every surface was read, so an unknown name is the pair's own issue.
  std::optional<SurfacePair> read_surface_pair(const json& item, const std::string& pointer, bool surfaces_complete);
  std::optional<InterfaceConductance> read_conductance(const json& value, const std::string& pointer);
  // section_thermal.cpp
  /// Solid elements owning each edge, keyed by the ordered pair of node indices (gap elements own none).
  using EdgeOwners = std::map<std::pair<int, int>, std::vector<int>>;
  void read_heat_properties(const Obj& material, Material& m);
  void read_thermal(const Obj& root);
  std::optional<ThermalBoundary> read_thermal_boundary(const json& item, const std::string& pointer,
                                                        const EdgeOwners& owners);
  std::optional<ThermalEdge> read_thermal_edge(const json& ids, const std::string& pointer, const EdgeOwners& owners);
  /// Whether `middle` is the mid-side node of solid element e's edge between corners a and b (an
  /// edge named [a, m, b]); if not, reports so at `pointer`, naming the edge `ids` and the node that is.
  bool check_middle_node(const json& ids, const std::string& pointer, int e, int a, int middle, int b);
  void check_thermal_materials(const Thermal& thermal);
  void read_output_times(const Obj& o, Thermal& thermal);
  [[nodiscard]] EdgeOwners solid_edge_owners() const;

  struct RankedIssue {
    int rank = 0;  ///< -1 repeated keys, 0 the root object, 1 + Section: found reading that section
    InputIssue issue;
  };
  std::vector<RankedIssue> issues_;
  int rank_ = 0;
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
  // State of a streamed array between begin_items and end_items.
  const Range* radius_ = &any_number;  ///< nodes: the range of r
  std::size_t item_ = 0;               ///< index of the item being read
  PrescribedAt prescribed_;  ///< constraints: (node index, component) -> pointer
  // Named sets (section_sets.cpp), by name: node indices (ascending), edges [a, b] by node index,
  // element ids. sets_complete_ is false when the sets section could not be read whole, so that a
  // name it may have defined is not reported as unknown.
  std::map<std::string, std::vector<int>> node_sets_;
  std::map<std::string, std::vector<std::array<int, 2>>> edge_sets_;
  std::map<std::string, std::vector<int>> element_sets_;
  bool sets_complete_ = true;
  std::vector<std::string> temperature_pointers_;  ///< every loads.temperatures given (thermal excludes them)
  /// take_nodal_temperatures: (node index, T) of /loads/temperatures/nodal, in the text's order.
  std::optional<std::vector<std::pair<int, double>>> typed_temperatures_;
};

}  // namespace saasgaps::io

