#include "io/sections/contact_check.hpp"

#include <sstream>

#include "io/json/json_pointer.hpp"
#include "solver/gaps/contact_pairs.hpp"
#include "solver/mortar/contact_surface.hpp"

namespace saasgaps::io {

std::vector<InputIssue> contact_pairing_input_issues(const Model& model) {
  std::vector<InputIssue> issues;
  if (!model.gaps || model.gaps->method != GapMethod::exact) return issues;
  // The reader keeps gap elements in document order, so index i is /gaps/elements/i.
  for (const PairingIssue& issue : contact_pairing_issues(model)) {
    issues.push_back({pointer_append("/gaps/elements", issue.gap), issue.detail});
  }
  return issues;
}

std::vector<InputIssue> contact_surface_input_issues(const Model& model) {
  std::vector<InputIssue> issues;
  if (!model.contact) return issues;
  // The reader keeps surfaces in document order (a refused one stops the read before this check).
  for (std::size_t i = 0; i < model.contact->surfaces.size(); ++i) {
    try {
      (void)contact_surface(model, model.contact->surfaces[i].edges);
    } catch (const ContactSurfaceError& e) {
      const std::string edges = pointer_append(pointer_append("/contact/surfaces", i), "edges");
      for (const SurfaceEdgeIssue& issue : e.issues()) {
        issues.push_back({pointer_append(edges, issue.edge), "surface \"" + model.contact->surfaces[i].name + "\": " + issue.detail});
      }
    }
  }
  // Friction needs the surfaces' own solver: exact gaps solve the rows with their frictionless node
  // pairs (solver/mortar_method.hpp).
  if (model.gaps && model.gaps->method == GapMethod::exact) {
    for (std::size_t k = 0; k < model.contact->pairs.size(); ++k) {
      const double mu = model.contact->pairs[k].friction;
      if (mu <= 0.0) continue;
      std::ostringstream text;
      text << "friction " << mu << " on a contact pair needs gaps.method \"classic\" (or no gap elements): with "
           << "\"exact\" gaps the surfaces are solved frictionless together with the gaps' node pairs";
      issues.push_back({pointer_append(pointer_append("/contact/pairs", k), "friction"), text.str()});
    }
  }
  return issues;
}

}  // namespace saasgaps::io
