#include "solver/analysis/contact_registry.hpp"

#include <cassert>

#include "solver/gaps/gap_modulus_method.hpp"
#include "solver/gaps/node_pair_method.hpp"
#include "solver/mortar/mortar_method.hpp"

namespace saasgaps {

namespace {

/// A model without gaps: nothing to add, nothing to measure, never a veto.
class NoContact final : public ContactMethod {
 public:
  void begin_iteration(RestartState&, StiffnessSystem&) override {}
  void evaluate(RestartState&, ContactOutcome& outcome) const override { outcome = ContactOutcome{}; }
};

}  // namespace

namespace {

/// The gap elements' method; with exact gaps, `surface_rows` (null: none) appended to its node pairs.
std::unique_ptr<ContactMethod> gap_method(const ContactSetup& setup, const ContactPairs* surface_rows) {
  if (setup.gaps == nullptr) return nullptr;
  switch (setup.gaps->method) {
    case GapMethod::classic: return std::make_unique<GapModulusMethod>(setup.model, *setup.gaps);
    case GapMethod::exact:
      return std::make_unique<NodePairMethod>(setup.model, *setup.gaps, setup.dofs, setup.pattern, surface_rows);
  }
  assert(false && "every GapMethod has its case");
  return nullptr;
}

}  // namespace

std::unique_ptr<ContactMethod> make_contact_method(const ContactSetup& setup) {
  const bool surfaces = setup.surfaces != nullptr && setup.surfaces->pair_count() > 0;
  if (!surfaces) {
    std::unique_ptr<ContactMethod> gaps = gap_method(setup, nullptr);
    if (gaps) return gaps;
    return std::make_unique<NoContact>();
  }
  // Exact gaps solve the surfaces' rows with their node pairs: one active set, one factorization.
  const bool exact_gaps = setup.gaps != nullptr && setup.gaps->method == GapMethod::exact;
  return std::make_unique<MortarMethod>(setup, *setup.surfaces, gap_method(setup, &setup.surfaces->pairs), exact_gaps);
}

}  // namespace saasgaps
