#pragma once
/// The node pairs of the exact contact mode (gaps.method = "exact"): geometry only.
///
/// Each gap element has two faces across its M axis (the two opposite edges most nearly
/// perpendicular to M; a 3-node gap has one edge and its lone opposite node). A quadrilateral gap
/// pairs each node of one face with the node of the other face that faces it along M; a triangle
/// pairs its lone node with the point of the opposite edge that faces it along M (linear weights).
/// Pair i has a unit normal n_i (along M, from side a to side b), an initial separation
/// g0_i = n_i . (x_b - x_a) > 0, and the gap function
///   g_i(u) = g0_i + n_i . (u_b - u_a) = g0_i + n_i . sum_k w_ik u_k   (w = +1 on side b, -1 or the
///                                                                      edge weights -(1-s), -s on a).
/// A pair shared by adjacent gap elements is one constraint; its normal is the normalized sum of the
/// elements' M axes (on a curved interface: the direction across it at the shared nodes).

#include <array>
#include <span>
#include <string>
#include <vector>

#include "solver/base/errors.hpp"
#include "solver/base/voigt.hpp"
#include "solver/contact/contact_pair.hpp"
#include "solver/model/model.hpp"

namespace saasgaps {

/// A gap element that cannot give node pairs (faces not across M, a node facing no node, zero or
/// crossing separation). The io layer names it by JSON Pointer /gaps/elements/<gap>.
struct PairingIssue {
  std::size_t gap = 0;  ///< index into GapSettings::elements
  std::string detail;
};

class GapPairingError : public SolverError {
 public:
  explicit GapPairingError(std::vector<PairingIssue> issues);
  [[nodiscard]] const std::vector<PairingIssue>& issues() const { return issues_; }

 private:
  std::vector<PairingIssue> issues_;
};

/// Every gap element that cannot be paired (empty when all can).
std::vector<PairingIssue> contact_pairing_issues(const Model& model);

/// The deduplicated pairs of every gap element. Throws GapPairingError naming each gap that fails.
ContactPairs contact_pairs(const Model& model);

}  // namespace saasgaps
