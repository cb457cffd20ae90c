#pragma once
/// Gap elements between two boundary curves that face each other across a clearance: pure geometry,
/// no JSON, no Gmsh.
///
/// Each node of face A is paired with the node of face B that faces it: the node of B nearest to
/// the point where the ray from the A node along A's outward normal meets B. The pairing must be
/// one to one and cover every node of both faces (matching node distributions: transfinite curves
/// in Gmsh); a node whose facing point lies farther than tolerance x (local element length) from
/// the nearest B node is reported with both positions. Between consecutive pairs (a_i, b_i),
/// (a_i+1, b_i+1) lies one quadrilateral gap element [a_i, a_i+1, b_i+1, b_i], reordered
/// counter-clockwise, whose M axis is the mean pair direction
///   angle = atan2(dz, dr) of (b_i - a_i) + (b_i+1 - a_i+1), in degrees from +r,
/// pointing from A across the gap to B.

#include <array>
#include <span>
#include <string>
#include <vector>

#include "solver/base/voigt.hpp"

namespace saasgaps::io {

/// A chain of boundary edges in order: nodes[k] - nodes[k+1] is an edge for every k.
struct FaceChain {
  std::vector<int> nodes;      ///< node indices
  std::vector<Vec2> outward;   ///< per edge (nodes.size() - 1): unit normal out of the solid that owns it
};

/// Orders line elements (node index pairs) into one open chain. Returns an explanation instead
/// when they are not one: branched, closed or in several pieces (`problem` non-empty).
struct ChainResult {
  std::vector<int> nodes;
  std::string problem;
};
ChainResult order_chain(std::span<const std::array<int, 2>> edges, std::span<const int> node_ids);

struct GeneratedGap {
  std::array<int, 4> nodes{};  ///< node indices, counter-clockwise
  double angle_deg = 0.0;      ///< M, from A across the gap
};

/// Gap elements, or the problems that prevent them (each a sentence naming nodes by id and
/// position). `problems` empty means `gaps` holds one element per edge of A.
struct GapGeneration {
  std::vector<GeneratedGap> gaps;
  std::vector<std::pair<int, int>> pairs;  ///< (A node, B node) indices, in A's order
  std::vector<std::string> problems;
};

/// positions[i] is node i at (r, z); ids[i] its id for messages. `tolerance` is the fraction of the
/// local element length within which a facing point must meet a node of B.
GapGeneration generate_gaps(const FaceChain& a, const FaceChain& b, std::span<const Vec2> positions,
                            std::span<const int> ids, double tolerance);

}  // namespace saasgaps::io
