#pragma once
/// The restraint check of solver/restraint_check in the model document's terms: each unrestrained
/// body or unused node becomes an InputIssue located by the JSON Pointer of a node, so `validate`
/// and POST /v1/jobs refuse a mechanism before it is queued (the solver would find it singular).

#include "solver/model/model.hpp"

namespace saasgaps::io {

/// Throws ModelError with one issue per unrestrained body (at its first node's pointer, listing its
/// nodes and free motions) and per node no element uses; returns when the model is restrained.
/// Expects a model read by read_model (node index k is the document's /nodes/k).
void require_restrained(const Model& model);

}  // namespace saasgaps::io
