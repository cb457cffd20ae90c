#pragma once
/// The one place that chooses a run's contact method (contact/contact_method.hpp): a new method is its
/// own file pair implementing ContactMethod plus one case here.

#include <memory>

#include "solver/contact/contact_method.hpp"

namespace saasgaps {

/// The method gaps.method names: none without gaps, "classic" GapModulusMethod, "exact"
/// NodePairMethod; with contact surface pairs, that one wrapped in a MortarMethod. Adding a method:
/// its own file pair implementing ContactMethod, one case here.
std::unique_ptr<ContactMethod> make_contact_method(const ContactSetup& setup);

}  // namespace saasgaps
