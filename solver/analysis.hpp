#pragma once
/// The SAASGAPS analysis: one bounded loop over iterations, each one
///   1. setting the gap moduli by section II (a)-(d) and the solid moduli by strain invariance,
///   2. assembling (solids only when their moduli changed) and solving K u = f,
///   3. testing convergence (e) of the gaps and of the plastic and bimodulus materials,
///   4. handing its history row and restart state to the observer,
/// until everything has converged, max_iterations is reached, or a stop is requested.

#include <memory>
#include <optional>
#include <vector>

#include "iteration_record.hpp"
#include "ordering_cache.hpp"
#include "model.hpp"
#include "restart_state.hpp"
#include "resume_options.hpp"
#include "solution.hpp"

namespace saasgaps {

/// Runs a model from the start, or from `resume` when given. Throws SingularModelError for a
/// mechanism, SolverError for a state that does not belong to the model. cache (optional): where
/// fill-reducing orderings are kept between runs (see OrderingCache); the answer does not depend
/// on it.
Solution solve(const Model& model, IterationObserver* observer = nullptr, const RestartState* resume = nullptr,
               const ResumeOptions& options = {}, const OrderingCache* cache = nullptr);

}  // namespace saasgaps
