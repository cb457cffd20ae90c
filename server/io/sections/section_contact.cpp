/// The `contact` section: contact surfaces (chains of boundary edges of solid elements) and the pairs
/// of them that may touch (solver/contact_surface.hpp, solver/mortar_method.hpp). The chain rules
/// (boundary edge of exactly one solid element, one chain) are judged on a model otherwise valid, by
/// contact_surface_input_issues (io/contact_check.hpp).
#include "io/json/value_quote.hpp"
#include "io/sections/section_reader.hpp"
#include "solver/assembly/element_data.hpp"

namespace saasgaps::io {

/// Optional: {surfaces: [{name, edges: [[a, b], ...]}], pairs: [{surfaces: [A, B], friction?,
/// conductance?}]}; names unique and non-empty, each edge two distinct node ids that resolve; a pair
/// names two different known surfaces; friction (Coulomb mu) a number >= 0.
void SectionReader::read_contact(const Obj& root) {
  const json* v = root.find("contact");
  if (v == nullptr) return;
  const std::string pointer = root.at("contact");
  if (!object(*v, pointer, {"surfaces", "pairs"})) return;
  const Obj c{v, pointer};
  ContactSettings& settings = model_.contact.emplace();
  std::unordered_map<std::string, std::size_t> named;  // name -> index in the document's surfaces
  bool surfaces_complete = true;
  if (const json* list = array_field(c, "surfaces", 1)) {
    for (std::size_t i = 0; i < list->size(); ++i) {
      auto surface = read_surface((*list)[i], pointer_append(c.at("surfaces"), i));
      if (!surface) {
        surfaces_complete = false;
        continue;
      }
      const auto [first, fresh] = named.emplace(surface->name, i);
      if (!fresh) {
        report(pointer_append(pointer_append(c.at("surfaces"), i), "name"),
               "surface name " + quote_string(surface->name) + " is already used at " +
                   pointer_append(c.at("surfaces"), first->second) + "; give each surface its own name");
        surfaces_complete = false;
        continue;
      }
      settings.surfaces.push_back(std::move(*surface));
    }
  } else {
    surfaces_complete = false;
  }
  if (const json* list = array_field(c, "pairs", 1)) {
    for (std::size_t i = 0; i < list->size(); ++i) {
      auto pair = read_surface_pair((*list)[i], pointer_append(c.at("pairs"), i), surfaces_complete);
      if (pair) settings.pairs.push_back(*pair);
    }
  }
}

std::optional<SurfaceDefinition> SectionReader::read_surface(const json& item, const std::string& pointer) {
  if (!object(item, pointer, {"name", "edges"})) return std::nullopt;
  const Obj o{&item, pointer};
  SurfaceDefinition surface;
  bool valid = true;
  if (const auto name = string_field(o, "name")) {
    if (name->empty()) {
      report(o.at("name"), "name must be a non-empty surface name, got \"\"");
      valid = false;
    }
    surface.name = *name;
  } else {
    valid = false;
  }
  const json* edges = array_field(o, "edges", 1);
  if (edges == nullptr) return std::nullopt;
  std::optional<EdgeOwners> owners;  // for the mid-side nodes named in [a, m, b]
  for (std::size_t k = 0; k < edges->size(); ++k) {
    const json& edge = (*edges)[k];
    const std::string edge_pointer = pointer_append(o.at("edges"), k);
    if (!edge.is_array() || (edge.size() != 2 && edge.size() != 3)) {
      report(edge_pointer, "an edge must be an array of two node ids [a, b] (or [a, m, b] with the mid-side node "
                           "of a quadratic element's edge), got " + describe(edge));
      valid = false;
      continue;
    }
    std::array<int, 3> named{-1, -1, -1};
    for (std::size_t end = 0; end < edge.size(); ++end) {
      if (const Entry* node = resolve_node(edge[end], Where(edge_pointer, end))) named[end] = node->index;
    }
    const std::array<int, 2> nodes{named[0], named[edge.size() - 1]};
    if (nodes[0] < 0 || nodes[1] < 0 || (edge.size() == 3 && named[1] < 0)) {
      valid = false;
      continue;
    }
    if (edge.size() == 3 && solids_complete_) {
      // The middle node must be the mid-side node of the edge between the corners (when one solid
      // element has that edge: the surface check reports the others).
      if (!owners) owners = solid_edge_owners();
      const auto found = owners->find(std::minmax(nodes[0], nodes[1]));
      if (found != owners->end() && found->second.size() == 1) {
        const auto e = static_cast<std::size_t>(found->second.front());
        const ElementEdge side = element_edge(model_, e, nodes[0], nodes[1]);
        if (side.count != 3 || side.node[1] != named[1]) {
          report(edge_pointer, "the middle node of " + quote(edge) + " is not the mid-side node of element " +
                                   std::to_string(model_.elements[e].id) + "'s edge between its corners" +
                                   (side.count == 3 ? " (that is node " +
                                                          std::to_string(model_.nodes[static_cast<std::size_t>(side.node[1])].id) + ")"
                                                    : " (a straight edge, which has none: name its two corners)"));
          valid = false;
          continue;
        }
      }
    }
    surface.edges.push_back(nodes);
  }
  if (!valid) return std::nullopt;
  return surface;
}

std::optional<SurfacePair> SectionReader::read_surface_pair(const json& item, const std::string& pointer,
                                                           bool surfaces_complete) {
  if (!object(item, pointer, {"surfaces"}, {"friction", "conductance"})) return std::nullopt;
  const Obj o{&item, pointer};
  SurfacePair pair;
  bool valid = true;
  if (const json* names = o.find("surfaces")) {
    if (!names->is_array() || names->size() != 2) {
      report(o.at("surfaces"), "surfaces must name the pair's two surfaces [A, B], got " + describe(*names));
      valid = false;
    } else {
      for (std::size_t j = 0; j < 2; ++j) {
        const std::string name_pointer = pointer_append(o.at("surfaces"), j);
        const json& name = (*names)[j];
        if (!name.is_string()) {
          report(name_pointer, "a surface name must be a string, got " + describe(name));
          valid = false;
          continue;
        }
        const auto& surfaces = model_.contact->surfaces;
        const auto found = std::find_if(surfaces.begin(), surfaces.end(),
                                        [&](const SurfaceDefinition& s) { return s.name == name.get<std::string>(); });
        if (found == surfaces.end()) {
          // A surface that failed its own checks is reported there, not again here.
          if (surfaces_complete) {
            report(name_pointer, "surface " + quote(name) + " is not defined: no entry of /contact/surfaces has that name");
          }
          valid = false;
          continue;
        }
        pair.surfaces[j] = static_cast<int>(found - surfaces.begin());
      }
      if (valid && pair.surfaces[0] == pair.surfaces[1]) {
        report(pointer_append(o.at("surfaces"), 1),
               "a pair needs two different surfaces, got " + quote((*names)[1]) + " twice (a surface cannot touch itself)");
        valid = false;
      }
    }
  }
  if (o.find("friction") != nullptr) {
    if (const auto mu = number_field(o, "friction", non_negative)) {
      pair.friction = *mu;
    } else {
      valid = false;
    }
  }
  if (const json* v = o.find("conductance")) {
    if (auto conductance = read_conductance(*v, o.at("conductance"))) {
      pair.conductance = std::move(*conductance);
    } else {
      valid = false;
    }
  }
  if (!valid) return std::nullopt;
  return pair;
}

/// {closed: h or [{p, h}] in strictly increasing p, gas_conductivity?: >= 0}: the one reader of a
/// conductance, for contact pairs and for gap elements (GapSettings::conductance).
std::optional<InterfaceConductance> SectionReader::read_conductance(const json& value, const std::string& pointer) {
  if (!object(value, pointer, {"closed"}, {"gas_conductivity"})) return std::nullopt;
  const Obj o{&value, pointer};
  InterfaceConductance conductance;
  bool valid = true;
  if (const json* closed = o.find("closed")) {
    if (closed->is_array()) {
      const std::string table = o.at("closed");
      if (array(*closed, table, "closed", 1) == nullptr) return std::nullopt;
      const json* previous_p = nullptr;
      for (std::size_t i = 0; i < closed->size(); ++i) {
        const std::string row_pointer = pointer_append(table, i);
        const json& row = (*closed)[i];
        if (!object(row, row_pointer, {"p", "h"})) {
          valid = false;
          continue;
        }
        const Obj r{&row, row_pointer};
        const auto p = number_field(r, "p", non_negative);
        const auto h = number_field(r, "h", non_negative);
        if (p && previous_p != nullptr && !(*p > previous_p->get<double>())) {
          report(r.at("p"), "p = " + quote(row.at("p")) + " does not follow p = " + quote(*previous_p) +
                                " of an earlier row; rows must be in strictly increasing contact pressure p");
          valid = false;
        }
        if (p) previous_p = &row.at("p");
        if (!p || !h) {
          valid = false;
          continue;
        }
        conductance.closed.push_back({*p, *h});
      }
    } else if (const auto h = number(*closed, o.at("closed"), "closed", non_negative)) {
      conductance.closed.push_back({0.0, *h});  // a constant: one row, held beyond its ends
    } else {
      valid = false;
    }
  }
  if (o.find("gas_conductivity") != nullptr) {
    const auto k = number_field(o, "gas_conductivity", non_negative);
    valid = valid && k.has_value();
    conductance.gas_conductivity = k.value_or(0.0);
  }
  if (!valid) return std::nullopt;
  return conductance;
}

}  // namespace saasgaps::io
