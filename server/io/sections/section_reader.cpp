#include "io/sections/section_reader.hpp"

#include "io/json/value_quote.hpp"
#include "io/sections/contact_check.hpp"
#include "io/sections/family_limits.hpp"
#include "solver/assembly/element_data.hpp"
#include "io/sections/run_limits.hpp"

namespace saasgaps::io {

namespace {

constexpr std::array<std::string_view, section_count> section_keys{
    "schema_version", "title", "description", "units", "analysis", "nodes", "materials",
    "elements", "gaps", "sets", "constraints", "loads", "solver", "output", "steps", "contact", "thermal"};

constexpr std::array<std::string_view, 7> required_root_keys{"schema_version", "title", "analysis", "nodes",
                                                            "materials", "elements", "constraints"};
constexpr std::array<std::string_view, 10> optional_root_keys{"description", "units", "gaps", "sets", "loads",
                                                             "solver", "output", "steps", "contact", "thermal"};

}  // namespace

std::string_view section_key(Section s) { return section_keys[static_cast<std::size_t>(s)]; }

std::optional<Section> section_of(std::string_view key) {
  const auto it = std::ranges::find(section_keys, key);
  if (it == section_keys.end()) return std::nullopt;
  return static_cast<Section>(it - section_keys.begin());
}

std::span<const Section> dependencies(Section s) {
  // Order matters: analysis before nodes (r >= 0), nodes and materials before the elements that
  // use them, every element before pressures and watch lists; the stress-free temperature (in
  // analysis) before the node temperatures.
  static constexpr std::array<Section, 1> on_analysis{Section::analysis};
  static constexpr std::array<Section, 2> on_nodes_and_materials{Section::nodes, Section::materials};
  static constexpr std::array<Section, 2> on_nodes_and_elements{Section::nodes, Section::elements};
  static constexpr std::array<Section, 3> on_nodes_and_every_element{Section::nodes, Section::elements, Section::gaps};
  static constexpr std::array<Section, 2> on_nodes_and_sets{Section::nodes, Section::sets};
  static constexpr std::array<Section, 4> on_loads{Section::analysis, Section::nodes, Section::elements, Section::sets};
  static constexpr std::array<Section, 2> on_all_elements{Section::elements, Section::gaps};
  static constexpr std::array<Section, 5> on_loads_and_constraints{Section::analysis, Section::nodes, Section::elements,
                                                                   Section::sets, Section::constraints};
  // thermal judges its edges, sources and conflicts against every section before it.
  static constexpr std::array<Section, 8> on_everything_before{
      Section::analysis, Section::nodes, Section::materials, Section::elements,
      Section::gaps,     Section::constraints, Section::loads, Section::steps};
  switch (s) {
    case Section::nodes: return on_analysis;
    case Section::elements: return on_nodes_and_materials;
    case Section::gaps: return on_nodes_and_elements;
    case Section::sets: return on_nodes_and_every_element;
    case Section::constraints: return on_nodes_and_sets;
    case Section::loads: return on_loads;
    case Section::output: return on_all_elements;
    case Section::steps: return on_loads_and_constraints;
    case Section::contact: return on_nodes_and_elements;
    case Section::thermal: return on_everything_before;
    default: return {};
  }
}

bool streams_items(Section s) {
  return s == Section::nodes || s == Section::elements || s == Section::constraints;
}

Model SectionReader::read(const json& document) {
  if (object(document, "", required_root_keys, optional_root_keys)) {
    for (std::size_t k = 0; k < section_count; ++k) {
      const auto found = document.find(section_keys[k]);
      read_section(static_cast<Section>(k), found == document.end() ? nullptr : &*found);
    }
  }
  return finish();
}

void SectionReader::unknown_root_key(std::string_view key) {
  rank_ = 0;
  std::vector<std::string_view> names(required_root_keys.begin(), required_root_keys.end());
  names.insert(names.end(), optional_root_keys.begin(), optional_root_keys.end());
  report(pointer_append("", key), "unknown key " + quote_string(key) + " (allowed here: " + join(names) + ")");
}

void SectionReader::check_required_root_keys(const std::array<bool, section_count>& present) {
  rank_ = 0;
  for (const std::string_view key : required_root_keys) {
    if (!present[static_cast<std::size_t>(*section_of(key))]) report("", "missing required key " + quote_string(key));
  }
}

void SectionReader::repeated_key(std::string pointer, std::string detail) {
  rank_ = -1;
  report(std::move(pointer), std::move(detail));
}

void SectionReader::read_section(Section s, const json* value) {
  rank_ = 1 + static_cast<int>(s);
  // A view of the root with this one member, so that each section reads its own key as before.
  const Obj root{value, "", section_key(s)};
  switch (s) {
    case Section::schema_version: read_schema_version(root); break;
    case Section::title: model_.title = string_field(root, "title").value_or(""); break;
    case Section::description: model_.description = string_field(root, "description").value_or(""); break;
    case Section::units: read_units(root); break;
    case Section::analysis: read_analysis(root); break;
    case Section::materials: read_materials(root); break;
    case Section::gaps: read_gaps(root); break;
    case Section::loads: read_loads(root); break;
    case Section::solver: read_solver(root); break;
    case Section::output: read_output(root); break;
    case Section::steps: read_steps(root); break;
    case Section::sets: read_sets(root); break;
    case Section::contact: read_contact(root); break;
    case Section::thermal: read_thermal(root); break;
    case Section::nodes:
    case Section::elements:
    case Section::constraints: read_item_section(s, root); break;
  }
}

/// nodes, elements and constraints read whole: the checks of the streamed items, item by item.
void SectionReader::read_item_section(Section s, const Obj& root) {
  const json* list = array_field(root, section_key(s), 0);
  if (list == nullptr) {
    incomplete(s);
    return;
  }
  begin_items(s, list->size());
  for (std::size_t i = 0; i < list->size(); ++i) read_item(s, (*list)[i], i);
  end_items(s, list->size());
}

void SectionReader::incomplete(Section s) {
  if (s == Section::nodes) nodes_complete_ = false;
  if (s == Section::elements) solids_complete_ = false;
}

void SectionReader::begin_items(Section s, std::size_t count_hint) {
  rank_ = 1 + static_cast<int>(s);
  // The streaming driver knows the array's length: grow the model's arrays once.
  if (s == Section::nodes) {
    model_.nodes.reserve(count_hint);
    node_placed_.reserve(count_hint);
  }
  if (s == Section::elements) model_.elements.reserve(count_hint);
  if (s == Section::constraints) model_.constraints.reserve(count_hint);
  if (s == Section::nodes) radius_ = analysis_ == AnalysisType::axisymmetric ? &axisymmetric_radius : &any_number;
  prescribed_.clear();
}

void SectionReader::read_item(Section s, const json& item, std::size_t index) {
  rank_ = 1 + static_cast<int>(s);
  item_ = index;
  std::string pointer = "/";
  pointer += section_key(s);
  pointer += '/';
  pointer += std::to_string(index);
  if (s == Section::nodes) read_node(item, pointer);
  if (s == Section::elements) read_element(item, pointer);
  if (s == Section::constraints) read_constraint(item, pointer);
}

void SectionReader::end_items(Section s, std::size_t count) {
  rank_ = 1 + static_cast<int>(s);
  if (count > 0) return;
  if (s == Section::constraints) {
    report("/constraints", "the model has no constraints: it can move as a rigid body; prescribe r and/or z at "
                           "enough nodes to hold it");
  } else {
    report(pointer_append("", section_key(s)), std::string(section_key(s)) + " must not be empty");
    incomplete(s);
  }
}

Model SectionReader::finish() {
  if (issues_.empty()) {
    // What the quadratic families do not carry yet (gap elements along their edges).
    if (std::vector<InputIssue> limits = element_family_input_issues(model_); !limits.empty()) {
      throw ModelError(std::move(limits));
    }
    // Exact contact mode: the gap elements must give node pairs (checked on a model otherwise valid).
    if (std::vector<InputIssue> pairing = contact_pairing_input_issues(model_); !pairing.empty()) {
      throw ModelError(std::move(pairing));
    }
    // Contact surfaces: each a chain of boundary edges (judged with every solid element read).
    if (std::vector<InputIssue> chains = contact_surface_input_issues(model_); !chains.empty()) {
      throw ModelError(std::move(chains));
    }
    return std::move(model_);
  }
  // In the order of the sections (repeated keys first, then the document's own keys), each
  // section's issues in the order found, whatever order the sections came in.
  std::stable_sort(issues_.begin(), issues_.end(),
                   [](const RankedIssue& a, const RankedIssue& b) { return a.rank < b.rank; });
  std::vector<InputIssue> issues;
  issues.reserve(issues_.size());
  for (RankedIssue& i : issues_) issues.push_back(std::move(i.issue));
  throw ModelError(std::move(issues));
}

/// schema_version is the integer 1.
void SectionReader::read_schema_version(const Obj& root) {
  if (const json* version = root.find("schema_version")) {
    check_schema_version(*version, Where(root.pointer, "schema_version"), reporter());
  }
}

/// Optional names of the units (length, force, stress, temperature), each an optional non-empty
/// string; the solver never converts, so these are labels for results, plots and VTU fields.
void SectionReader::read_units(const Obj& root) {
  const json* v = root.find("units");
  if (v == nullptr) return;
  const std::string pointer = root.at("units");
  if (!check_object(*v, pointer, {}, unit_names)) return;
  const Obj o{v, pointer};
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
void SectionReader::read_analysis(const Obj& root) {
  const json* v = root.find("analysis");
  if (v == nullptr || !object(*v, root.at("analysis"), {"type"}, {"thickness", "reference_temperature"})) return;
  const Obj analysis{v, root.at("analysis")};
  if (const auto type = choice_field(analysis, "type", analysis_type_names)) {
    analysis_ = *type;
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

/// One of a non-empty array of {id, r, z}; ids unique; axisymmetric nodes at r >= 0.
void SectionReader::read_node(const json& item, const std::string& pointer) {
  if (!object(item, pointer, {"id", "r", "z"})) return;
  const Obj o{&item, pointer};
  const auto id = integer_field(o, "id", 1);
  const auto r = number_field(o, "r", *radius_);
  const auto z = number_field(o, "z");
  if (!id || !is_new(nodes_, *id, Where(o.pointer, "id"), "node")) return;
  nodes_.emplace(*id, Entry{as_index(model_.nodes.size()), false, as_index(item_)});
  model_.nodes.push_back(Node{*id, r.value_or(0.0), z.value_or(0.0)});
  node_placed_.push_back(r && z);
}

/// A non-empty array; ids unique; table rows shaped by elastic; density >= 0; optional plasticity.
void SectionReader::read_materials(const Obj& root) {
  const json* list = array_field(root, "materials", 1);
  materials_complete_ = list != nullptr;
  if (list == nullptr) return;
  for (std::size_t i = 0; i < list->size(); ++i) {
    const std::string pointer = pointer_append(root.at("materials"), i);
    if (!object((*list)[i], pointer, {"id", "elastic", "table"},
                {"name", "density", "compression_table", "plasticity"})) {
      continue;
    }
    const Obj o{&(*list)[i], pointer};
    Material m;
    const auto id = integer_field(o, "id", 1);
    m.name = string_field(o, "name").value_or("");
    m.density = number_field(o, "density", non_negative).value_or(0.0);
    // The row shape depends on the kind: without a valid kind the rows cannot be judged.
    if (const auto kind = choice_field(o, "elastic", elastic_kind_names)) {
      m.isotropic = *kind == ElasticKind::isotropic;
      m.table = read_property_table(o, "table", m.isotropic, 1);
      m.compression_table = read_property_table(o, "compression_table", m.isotropic, 0);
      read_heat_properties(o, m);
    }
    m.plasticity = read_plasticity(o);
    if (!id || !is_new(materials_, *id, o.at("id"), "material")) continue;
    m.id = *id;
    materials_.emplace(*id, Entry{as_index(model_.materials.size()), false, as_index(i)});
    model_.materials.push_back(std::move(m));
  }
}

/// One of a non-empty array of {id, nodes, material, angle?, type?, integration?}; ids unique among
/// all elements; the family's node count and shape (element_families.cpp).
void SectionReader::read_element(const json& item, const std::string& pointer) {
  if (!object(item, pointer, {"id", "nodes", "material"}, {"angle", "type", "integration"})) return;
  const Obj o{&item, pointer};
  Element e;
  const auto id = new_element_id(o);
  const auto corners = read_element_nodes(o);
  if (corners && !read_element_family(o, corners->count, e)) return;
  const json* material = o.find("material");
  const Entry* m = material == nullptr ? nullptr
                                       : resolve(materials_, materials_complete_, *material, Where(o.pointer, "material"),
                                                 "material", "/materials");
  e.angle_deg = number_field(o, "angle").value_or(0.0);
  if (!id) return;
  e.id = *id;
  if (corners) {
    e.nodes = corners->nodes;
    e.node_count = corners->count;
    const bool placed = corners->complete() &&
                        std::all_of(corners->nodes.begin(), corners->nodes.begin() + corners->count,
                                    [&](int n) { return node_placed_[static_cast<std::size_t>(n)]; });
    if (placed) check_element_shape(e, *o.find("nodes"), Where(o.pointer, "nodes"));
  }
  if (m != nullptr) e.material = m->index;
  elements_.emplace(*id, Entry{as_index(model_.elements.size()), false, as_index(item_)});
  model_.elements.push_back(e);
}

/// Optional. E0 > 0, a non-empty schedule of positive moduli, 0 <= XFACT < 1, 0 < tolerance < 1,
/// shear ratio > 0, and a non-empty array of gap elements {id, nodes, angle} (angle required).
void SectionReader::read_gaps(const Obj& root) {
  const json* v = root.find("gaps");
  if (v == nullptr) return;
  const std::string pointer = root.at("gaps");
  if (!object(*v, pointer, {"initial_modulus", "tensile_schedule", "elements"},
              {"method", "extrapolation_factor", "closure_tolerance", "shear_ratio", "convergence_test",
               "conductance"})) {
    gaps_complete_ = false;
    return;
  }
  const Obj g{v, pointer};
  GapSettings& s = model_.gaps.emplace();
  if (const auto method = choice_field(g, "method", gap_method_names)) s.method = *method;
  s.initial_modulus = number_field(g, "initial_modulus", positive).value_or(s.initial_modulus);
  if (const json* schedule = array_field(g, "tensile_schedule", 1)) {
    for (std::size_t i = 0; i < schedule->size(); ++i) {
      const std::string name = "tensile_schedule[" + std::to_string(i) + "]";
      if (const auto value = number((*schedule)[i], pointer_append(g.at("tensile_schedule"), i), name, positive)) {
        s.tensile_schedule.push_back(*value);
      }
    }
  }
  s.extrapolation_factor = number_field(g, "extrapolation_factor", extrapolation).value_or(s.extrapolation_factor);
  s.closure_tolerance = number_field(g, "closure_tolerance", tolerance_fraction).value_or(s.closure_tolerance);
  s.shear_ratio = number_field(g, "shear_ratio", positive).value_or(s.shear_ratio);
  if (const auto test = choice_field(g, "convergence_test", gap_convergence_test_names)) {
    s.convergence_test = *test;
  }
  if (const json* conductance = g.find("conductance")) s.conductance = read_conductance(*conductance, g.at("conductance"));
  const json* list = array_field(g, "elements", 1);
  gaps_complete_ = list != nullptr;
  if (list == nullptr) return;
  std::vector<GapElement> judged;  // the gaps whose M axis can be judged, and their angles' pointers
  std::vector<std::string> angle_pointers;
  for (std::size_t i = 0; i < list->size(); ++i) {
    const std::string item = pointer_append(g.at("elements"), i);
    if (!object((*list)[i], item, {"id", "nodes", "angle"})) continue;
    const Obj o{&(*list)[i], item};
    GapElement e;
    const auto id = new_element_id(o);
    const auto corners = read_corners(o);
    const auto angle = number_field(o, "angle");
    e.angle_deg = angle.value_or(0.0);
    if (!id) continue;
    e.id = *id;
    if (corners) {
      std::copy_n(corners->nodes.begin(), e.nodes.size(), e.nodes.begin());
      e.node_count = corners->count;
    }
    if (angle && corners && gap_axis_judgeable(*corners)) {
      judged.push_back(e);
      angle_pointers.push_back(o.at("angle"));
    }
    elements_.emplace(*id, Entry{as_index(s.elements.size()), true, as_index(i)});
    s.elements.push_back(e);
  }
  check_gap_axes(judged, angle_pointers);
}

/// One of a non-empty array of {node, r?, z?} with r and/or z; no component of a node twice.
void SectionReader::read_constraint(const json& item, const std::string& pointer) {
  for (const Constraint& c : read_constraint_item(item, pointer, prescribed_)) model_.constraints.push_back(c);
}

/// {node, r?, z?} with r and/or z; a component of a node not already in `seen` (which it joins).
/// {set, r?, z?}: the same for each node of a node set (read_set_constraint).
std::vector<Constraint> SectionReader::read_constraint_item(const json& item, const std::string& pointer,
                                                            PrescribedAt& seen) {
  if (item.is_object() && item.contains("set") && !item.contains("node")) {
    if (!object(item, pointer, {"set"}, {"r", "z"})) return {};
    return read_set_constraint(Obj{&item, pointer}, seen);
  }
  if (!object(item, pointer, {"node"}, {"r", "z"})) return {};
  const Obj o{&item, pointer};
  const json* node_id = o.find("node");
  const Entry* node = node_id == nullptr ? nullptr : resolve_node(*node_id, Where(o.pointer, "node"));
  Constraint c;
  c.u_r = number_field(o, "r");
  c.u_z = number_field(o, "z");
  if (o.find("r") == nullptr && o.find("z") == nullptr) {
    report(pointer, "the constraint of node " + (node_id ? quote(*node_id) : std::string("?")) +
                        " prescribes neither r nor z; give r and/or z (the prescribed displacement)");
  }
  if (node == nullptr) return {};
  c.node = node->index;
  for (const char component : {'r', 'z'}) {
    const std::string_view key = component == 'r' ? "r" : "z";
    if (o.find(key) == nullptr) continue;
    const auto [first, fresh] = seen.emplace(std::pair{node->index, component}, o.at(key));
    if (!fresh) {
      report(o.at(key), std::string(key) + " of node " + quote(*node_id) + " is already prescribed at " +
                            first->second.pointer + "; prescribe each component once");
    }
  }
  return {c};
}

void SectionReader::read_loads(const Obj& root) {
  // Every node has a temperature; without a temperature load it is the stress-free one.
  model_.loads.node_temperature.assign(model_.nodes.size(), model_.reference_temperature);
  const json* v = root.find("loads");
  if (v == nullptr || !object(*v, root.at("loads"), {}, load_kind_names.names())) {
    return;
  }
  read_loads_object(Obj{v, root.at("loads")}, model_.loads);
}

/// The members of a loads object (checked by the caller) into `into`, whose node temperatures are
/// already the default.
void SectionReader::read_loads_object(const Obj& loads, Loads& into) {
  read_nodal_forces(loads, into);
  read_pressures(loads, into);
  read_temperatures(loads, into);
  read_body_force(loads, into);
}

/// {node, fr?, fz?}; forces on one node add up.
void SectionReader::read_nodal_forces(const Obj& loads, Loads& into) {
  const json* list = array_field(loads, "nodal_forces", 0);
  if (list == nullptr) return;
  for (std::size_t i = 0; i < list->size(); ++i) {
    const std::string pointer = pointer_append(loads.at("nodal_forces"), i);
    if (!object((*list)[i], pointer, {"node"}, {"fr", "fz"})) continue;
    const Obj o{&(*list)[i], pointer};
    const json* node_id = o.find("node");
    const Entry* node = node_id == nullptr ? nullptr : resolve_node(*node_id, Where(o.pointer, "node"));
    NodalForce f;
    f.f_r = number_field(o, "fr").value_or(0.0);
    f.f_z = number_field(o, "fz").value_or(0.0);
    if (node == nullptr) continue;
    f.node = node->index;
    into.nodal_forces.push_back(f);
  }
}

/// {nodes: [a, b], normal?, shear?} on an edge of exactly one solid element.
void SectionReader::read_pressures(const Obj& loads, Loads& into) {
  const json* list = array_field(loads, "pressures", 0);
  if (list == nullptr) return;
  // Gap elements never own a pressure edge: their stiffness is the program's, not a body's.
  const EdgeOwners owners = solid_edge_owners();
  for (std::size_t i = 0; i < list->size(); ++i) {
    const std::string pointer = pointer_append(loads.at("pressures"), i);
    const json& item = (*list)[i];
    if (item.is_object() && item.contains("set") && !item.contains("nodes")) {
      read_set_pressure(Obj{&item, pointer}, owners, into);
      continue;
    }
    if (!object((*list)[i], pointer, {"nodes"}, {"normal", "shear"})) continue;
    const Obj o{&(*list)[i], pointer};
    EdgePressure p;
    p.normal = number_field(o, "normal").value_or(0.0);
    p.shear = number_field(o, "shear").value_or(0.0);
    const auto edge = read_node_list(o, 2, 3, "a pressure edge has 2 nodes, its corners [a, b] (or [a, m, b] with the mid-side node of a quadratic element's edge)");
    if (!edge || !edge->complete() || !solids_complete_) continue;
    const json& ids = *o.find("nodes");
    const bool middle_named = edge->count == 3;
    const int last = edge->nodes[middle_named ? 2 : 1];
    const auto found = owners.find(std::minmax(edge->nodes[0], last));
    if (found == owners.end()) {
      report(o.at("nodes"), "no solid element has the edge " + quote(ids) +
                                (middle_named ? ": its end nodes" : ": the two nodes") +
                                " must be consecutive corners of one solid element (gap elements carry no pressure)");
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
    if (middle_named && !check_middle_node(ids, o.at("nodes"), p.element, edge->nodes[0], edge->nodes[1], last)) {
      continue;
    }
    p.node_a = edge->nodes[0];
    p.node_b = last;
    into.pressures.push_back(p);
  }
}

bool SectionReader::check_middle_node(const json& ids, const std::string& pointer, int e, int a, int middle, int b) {
  // The owner has this edge (found by its corners); a straight one has no mid-side node.
  const ElementEdge side = element_edge(model_, static_cast<std::size_t>(e), a, b);
  const std::optional<int> own = side.count == 3 ? std::optional<int>(side.node[1]) : std::nullopt;
  if (own == middle) return true;
  const Element& el = model_.elements[static_cast<std::size_t>(e)];
  report(pointer, "the middle node of " + quote(ids) + " is not the mid-side node of element " + std::to_string(el.id) +
                      "'s edge between its corners" +
                      (own ? " (that is node " + std::to_string(model_.nodes[static_cast<std::size_t>(*own)].id) + ")"
                           : " (a straight edge of a " + std::string(element_type_names.name(el.type)) +
                                 " element, which has none: name its two corners)"));
  return false;
}

/// {default?, nodal?: [{node, T}]}; one temperature per node.
void SectionReader::read_temperatures(const Obj& loads, Loads& into) {
  const json* v = loads.find("temperatures");
  if (v == nullptr || !object(*v, loads.at("temperatures"), {}, {"default", "nodal"})) return;
  const Obj temperatures{v, loads.at("temperatures")};
  temperature_pointers_.push_back(temperatures.pointer);
  if (const auto fallback = number_field(temperatures, "default")) {
    into.node_temperature.assign(model_.nodes.size(), *fallback);
  }
  if (typed_temperatures_ && temperatures.pointer == "/loads/temperatures") {
    // Judged by take_nodal_temperatures (section_items.cpp); the tree's nodal array is empty.
    for (const auto& [node, T] : *typed_temperatures_) into.node_temperature[static_cast<std::size_t>(node)] = T;
    typed_temperatures_.reset();
  }
  const json* list = array_field(temperatures, "nodal", 0);
  if (list == nullptr) return;
  // Per node index, the item that gave its temperature (its pointer is spelled only for an issue:
  // a large model has a temperature per node).
  std::vector<std::size_t> given(model_.nodes.size(), list->size());
  const std::string nodal = temperatures.at("nodal");
  for (std::size_t i = 0; i < list->size(); ++i) {
    const std::string pointer = pointer_append(nodal, i);
    if (!object((*list)[i], pointer, {"node", "T"})) continue;
    const Obj o{&(*list)[i], pointer};
    const json* node_id = o.find("node");
    const Entry* node = node_id == nullptr ? nullptr : resolve_node(*node_id, Where(o.pointer, "node"));
    const auto T = number_field(o, "T");
    if (node == nullptr) continue;
    std::size_t& first = given[static_cast<std::size_t>(node->index)];
    if (first < i) {
      report(o.at("node"), "node " + quote(*node_id) + " already has a temperature at " + pointer_append(nodal, first) +
                               "; give each node one temperature");
      continue;
    }
    first = i;
    if (T) into.node_temperature[static_cast<std::size_t>(node->index)] = *T;
  }
}

/// {accel_r?, accel_z?, omega?}; omega != 0 only in axisymmetric analyses.
void SectionReader::read_body_force(const Obj& loads, Loads& into) {
  const json* v = loads.find("body_force");
  if (v == nullptr || !object(*v, loads.at("body_force"), {}, {"accel_r", "accel_z", "omega"})) return;
  const Obj o{v, loads.at("body_force")};
  BodyForce& b = into.body_force;
  b.accel_r = number_field(o, "accel_r").value_or(0.0);
  b.accel_z = number_field(o, "accel_z").value_or(0.0);
  b.omega = number_field(o, "omega").value_or(0.0);
  if (b.omega != 0.0 && analysis_ && *analysis_ != AnalysisType::axisymmetric) {
    report(o.at("omega"), "omega = " + quote(*o.find("omega")) + " spins the body about the z axis, which only an "
                          "axisymmetric analysis represents; this model is " +
                              std::string(analysis_type_names.name(*analysis_)) +
                              " (remove omega or set it to 0)");
  }
}

/// {max_iterations?: integer >= 1, plastic_tolerance?: > 0}.
void SectionReader::read_solver(const Obj& root) {
  const json* v = root.find("solver");
  if (v == nullptr || !object(*v, root.at("solver"), {}, {"max_iterations", "plastic_tolerance"})) return;
  const Obj o{v, root.at("solver")};
  model_.solver.max_iterations = integer_field(o, "max_iterations", 1, io::max_iterations_limit).value_or(model_.solver.max_iterations);
  model_.solver.plastic_tolerance =
      number_field(o, "plastic_tolerance", positive).value_or(model_.solver.plastic_tolerance);
}

void SectionReader::read_output(const Obj& root) {
  const json* v = root.find("output");
  if (v == nullptr || !object(*v, root.at("output"), {}, {"watch_elements", "watch_gaps"})) return;
  const Obj o{v, root.at("output")};
  model_.output.watch_elements = read_watch_list(o, "watch_elements", false);
  model_.output.watch_gaps = read_watch_list(o, "watch_gaps", true);
}

/// Ids of solid elements (watch_elements) or gap elements (watch_gaps), each once.
std::vector<int> SectionReader::read_watch_list(const Obj& output, std::string_view key, bool gaps) {
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

}  // namespace saasgaps::io
