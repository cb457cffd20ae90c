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

#include "errors.hpp"
#include "model.hpp"
#include "voigt.hpp"

namespace saasgaps {

struct ContactPair {
  std::vector<int> node;       ///< node indices, any number (gap elements give 2: node to node, or 3: node to edge)
  std::vector<double> weight;  ///< w_k per node: g = g0 + n . sum_k w_k u_k
  Vec2 normal{1.0, 0.0};                ///< unit, from side a to side b
  double g0 = 0.0;                      ///< initial separation along the normal (> 0)
  /// The face area the pair stands for: the sum, over the gap elements sharing it, of the load a unit
  /// pressure on the face puts on the pair's node (consistent nodal load; thickness in plane analyses,
  /// the full ring 2 pi r in axisymmetry; for a quad the mean of its two faces; for a triangle half its
  /// edge's area).
  double area = 0.0;
  /// Optional, per node: the gradient (dg/du_r, dg/du_z) of the gap, when the row's direction varies
  /// along it (contact surfaces integrate the gap along a normal field: mortar_coupling.hpp). Empty:
  /// the gradient is weight[k] * normal.
  std::vector<Vec2> gradient;

  [[nodiscard]] Vec2 coefficient(std::size_t k) const { return gradient.empty() ? Vec2(weight[k] * normal) : gradient[k]; }
};

/// g_i(u) of a pair for the full displacement vector (u_r, u_z per node, prescribed ones included).
double gap_function(const ContactPair& pair, std::span<const double> displacement);

/// Pair `pair` carries `area` of gap element g's face.
struct PairShare {
  int pair = -1;
  double area = 0.0;
};

struct ContactPairs {
  std::vector<ContactPair> pairs;
  std::vector<std::array<PairShare, 2>> of_gap;  ///< per gap element: its pairs (a triangle has one)
  std::vector<int> share_count;                  ///< per gap element: 1 or 2
};

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
