#pragma once
/// The SAASGAPS analysis: one bounded loop over iterations, each one
///   1. setting the solid moduli by strain invariance and letting the contact method set what it adds
///      (contact_method.hpp; classic: the gap moduli by section II (a)-(d)),
///   2. assembling (solids only when their moduli changed) and solving K u = f through the method,
///   3. judging convergence: the plastic and bimodulus materials' verdict AND the method's,
///   4. handing its history row and restart state to the observer,
/// until both verdicts hold, max_iterations is reached, or a stop is requested.

#include <memory>
#include <optional>
#include <vector>

#include "solver/analysis/contact_registry.hpp"
#include "solver/lac/ordering_cache.hpp"
#include "solver/model/model.hpp"
#include "solver/state/iteration_record.hpp"
#include "solver/state/restart_state.hpp"
#include "solver/state/resume_options.hpp"
#include "solver/state/solution.hpp"

namespace saasgaps {

/// Runs a model from the start, or from `resume` when given. Throws SingularModelError for a
/// mechanism, SolverError for a state that does not belong to the model. cache (optional): where
/// fill-reducing orderings are kept between runs (see OrderingCache); the answer does not depend
/// on it. contact: builds the contact method (make_contact_method: the one gaps.method names).
Solution solve(const Model& model, IterationObserver* observer = nullptr, const RestartState* resume = nullptr,
               const ResumeOptions& options = {}, const OrderingCache* cache = nullptr,
               const ContactMethodFactory& contact = make_contact_method);

}  // namespace saasgaps
