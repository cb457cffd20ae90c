#pragma once
/// A contact constraint row as the exact solvers take it: any number of nodes with weights, a unit
/// normal and an initial separation,
///   g(u) = g0 + n . sum_k w_k u_k     (or sum_k c_k . u_k with a per-node gradient c_k),
/// and the face area it stands for. Gap elements give node pairs (gaps/contact_pairs.hpp), contact
/// surfaces give mortar rows (mortar/mortar_method.hpp).

#include <array>
#include <span>
#include <vector>

#include "solver/base/voigt.hpp"

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

}  // namespace saasgaps
