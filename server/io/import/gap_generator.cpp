#include "io/import/gap_generator.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>
#include <set>
#include <sstream>
#include <unordered_map>

#include "solver/gaps/gap_faces.hpp"

namespace saasgaps::io {

namespace {

double cross(const Vec2& u, const Vec2& v) { return u.x() * v.y() - u.y() * v.x(); }

/// Lists at most this many nodes in one message; the rest are counted.
constexpr std::size_t listed_nodes = 5;

/// One message per kind of failure, listing the first few occurrences.
class ProblemList {
 public:
  explicit ProblemList(std::string lead) : lead_(std::move(lead)) {}
  void add(std::string item) {
    if (items_.size() < listed_nodes) items_.push_back(std::move(item));
    ++count_;
  }
  void flush(std::vector<std::string>& out) const {
    if (count_ == 0) return;
    std::string text = lead_ + ": ";
    for (std::size_t i = 0; i < items_.size(); ++i) text += (i ? "; " : "") + items_[i];
    if (count_ > items_.size()) text += "; and " + std::to_string(count_ - items_.size()) + " more";
    out.push_back(std::move(text));
  }

 private:
  std::string lead_;
  std::vector<std::string> items_;
  std::size_t count_ = 0;
};

/// A length for a message: 6 significant digits, no trailing zeros.
std::string length(double v) {
  std::ostringstream text;
  text << v;
  return text.str();
}

std::string at(const Vec2& x) {
  std::ostringstream text;
  text.precision(8);
  text << '(' << x.x() << ", " << x.y() << ')';
  return text.str();
}

/// Unit outward normal at chain node k: the mean of the normals of the edges beside it.
Vec2 node_normal(const FaceChain& chain, std::size_t k) {
  Vec2 n = Vec2::Zero();
  if (k > 0) n += chain.outward[k - 1];
  if (k + 1 < chain.nodes.size()) n += chain.outward[k];
  return n.normalized();
}

/// The shorter of the chain edges beside node k: the local element length.
double local_length(const FaceChain& chain, std::span<const Vec2> x, std::size_t k) {
  double h = std::numeric_limits<double>::infinity();
  const auto length = [&](std::size_t e) {
    return (x[static_cast<std::size_t>(chain.nodes[e + 1])] - x[static_cast<std::size_t>(chain.nodes[e])]).norm();
  };
  if (k > 0) h = std::min(h, length(k - 1));
  if (k + 1 < chain.nodes.size()) h = std::min(h, length(k));
  return h;
}

struct Hit {
  double t = 0.0;        ///< distance along the ray
  std::size_t edge = 0;  ///< edge of B it meets
  double s = 0.0;        ///< position on that edge, 0 at its first node
};

/// Where the line p + t n meets chain B nearest to p (smallest |t|); edges are extended by `reach`
/// of their length at each end so that a ray at a chain's end still meets it.
std::optional<Hit> facing_point(const Vec2& p, const Vec2& n, const FaceChain& b, std::span<const Vec2> x,
                                double reach) {
  std::optional<Hit> best;
  for (std::size_t e = 0; e + 1 < b.nodes.size(); ++e) {
    const Vec2& q0 = x[static_cast<std::size_t>(b.nodes[e])];
    const Vec2 edge = x[static_cast<std::size_t>(b.nodes[e + 1])] - q0;
    // p + t n = q0 + s edge: Cramer's rule on [n, -edge] (t, s) = q0 - p.
    const double det = cross(n, edge);
    if (std::fabs(det) <= 1e-12 * edge.norm()) continue;  // parallel to the ray
    const Vec2 w = q0 - p;
    const double t = cross(w, edge) / det;
    const double s = cross(w, n) / det;
    if (s < -reach || s > 1.0 + reach) continue;
    if (!best || std::fabs(t) < std::fabs(best->t)) best = Hit{t, e, s};
  }
  return best;
}

}  // namespace

ChainResult order_chain(std::span<const std::array<int, 2>> edges, std::span<const int> node_ids) {
  ChainResult result;
  if (edges.empty()) {
    result.problem = "it has no line elements";
    return result;
  }
  // An edge listed twice (two curve entities sharing it) is one edge.
  std::set<std::pair<int, int>> unique;
  for (const auto& [a, b] : edges) unique.insert(std::minmax(a, b));
  std::unordered_map<int, std::vector<int>> neighbours;
  for (const auto& [a, b] : unique) {
    neighbours[a].push_back(b);
    neighbours[b].push_back(a);
  }
  std::vector<int> ends;
  for (const auto& [node, next] : neighbours) {
    if (next.size() > 2) {
      result.problem = "it branches at node " + std::to_string(node_ids[static_cast<std::size_t>(node)]) +
                       " (" + std::to_string(next.size()) + " line elements meet there); a face is one open curve";
      return result;
    }
    if (next.size() == 1) ends.push_back(node);
  }
  if (ends.empty()) {
    result.problem = "it is a closed curve; split the face into two physical curves and name a pair for each";
    return result;
  }
  // Start from the end with the smaller id, so the order does not depend on hashing.
  int current = *std::min_element(ends.begin(), ends.end(), [&](int p, int q) {
    return node_ids[static_cast<std::size_t>(p)] < node_ids[static_cast<std::size_t>(q)];
  });
  int previous = -1;
  // Each step follows the one neighbour not yet visited; a path visits each node once, so it ends.
  for (std::size_t step = 0; step <= neighbours.size(); ++step) {
    result.nodes.push_back(current);
    const std::vector<int>& next = neighbours[current];
    const auto forward = std::find_if(next.begin(), next.end(), [&](int n) { return n != previous; });
    if (forward == next.end() || (next.size() == 1 && previous >= 0)) break;
    previous = current;
    current = *forward;
  }
  if (result.nodes.size() != neighbours.size()) {
    result.problem = "its line elements do not form one connected curve (" + std::to_string(ends.size()) +
                     " loose ends); a face is one connected open curve";
    result.nodes.clear();
  }
  return result;
}

GapGeneration generate_gaps(const FaceChain& a, const FaceChain& b, std::span<const Vec2> x,
                            std::span<const int> ids, double tolerance) {
  GapGeneration out;
  const auto id = [&](int node) { return std::to_string(ids[static_cast<std::size_t>(node)]); };
  const auto pos = [&](int node) { return x[static_cast<std::size_t>(node)]; };
  ProblemList unfaced("these nodes of the first face face no part of the second face along their normal");
  ProblemList mismatched(
      "these nodes do not face a node of the second face within the tolerance (give both curves the same node "
      "distribution, e.g. transfinite curves with the same number of nodes and progression)");
  ProblemList closed("zero clearance: these facing nodes touch; leave a clearance between the parts");
  ProblemList overlapping("the second face lies behind the first face (the parts overlap) at these nodes");
  ProblemList doubled("these nodes of the second face face more than one node of the first face");

  std::unordered_map<int, std::size_t> b_position;  // node -> position along B
  for (std::size_t k = 0; k < b.nodes.size(); ++k) b_position[b.nodes[k]] = k;
  std::vector<int> matched_by(b.nodes.size(), -1);
  std::vector<std::size_t> partner(a.nodes.size(), 0);
  bool paired = true;
  for (std::size_t k = 0; k < a.nodes.size(); ++k) {
    const int node = a.nodes[k];
    const Vec2 p = pos(node);
    const Vec2 n = node_normal(a, k);
    const double h = local_length(a, x, k);
    const auto hit = facing_point(p, n, b, x, tolerance);
    if (!hit) {
      unfaced.add("node " + id(node) + " at " + at(p) + " (normal " + at(n) + ")");
      paired = false;
      continue;
    }
    const std::size_t near = hit->s < 0.5 ? hit->edge : hit->edge + 1;
    const int facing = b.nodes[near];
    const Vec2 q = p + hit->t * n;
    const double edge_length = (pos(b.nodes[hit->edge + 1]) - pos(b.nodes[hit->edge])).norm();
    const double local = std::min(h, edge_length);
    const double miss = (q - pos(facing)).norm();
    if (miss > tolerance * local) {
      mismatched.add("node " + id(node) + " at " + at(p) + " faces " + at(q) + ", " + length(miss) +
                     " from the nearest node " + id(facing) + " at " + at(pos(facing)) + " (allowed " +
                     length(tolerance * local) + ")");
      paired = false;
      continue;
    }
    const Vec2 across = pos(facing) - p;
    if (facing == node || across.norm() <= 1e-9 * local) {
      closed.add("node " + id(node) + " at " + at(p) + " and node " + id(facing));
      paired = false;
      continue;
    }
    if (across.dot(n) <= 0.0) {
      overlapping.add("node " + id(node) + " at " + at(p) + " faces node " + id(facing) + " at " + at(pos(facing)));
      paired = false;
      continue;
    }
    if (matched_by[near] >= 0) {
      doubled.add("node " + id(facing) + " at " + at(pos(facing)) + " faces nodes " + id(matched_by[near]) + " and " +
                  id(node));
      paired = false;
      continue;
    }
    matched_by[near] = node;
    partner[k] = near;
  }
  ProblemList unmatched("these nodes of the second face are faced by no node of the first face");
  if (paired) {
    for (std::size_t k = 0; k < b.nodes.size(); ++k) {
      if (matched_by[k] < 0) unmatched.add("node " + id(b.nodes[k]) + " at " + at(pos(b.nodes[k])));
    }
  }
  for (const ProblemList* list : {&unfaced, &mismatched, &closed, &overlapping, &doubled, &unmatched}) {
    list->flush(out.problems);
  }
  if (!out.problems.empty()) return out;

  // A one-to-one pairing of the nodes of two open chains pairs neighbours with neighbours.
  for (std::size_t k = 0; k + 1 < a.nodes.size(); ++k) {
    const std::size_t j0 = partner[k], j1 = partner[k + 1];
    const int a0 = a.nodes[k], a1 = a.nodes[k + 1], b0 = b.nodes[j0], b1 = b.nodes[j1];
    if (j0 + 1 != j1 && j1 + 1 != j0) {
      out.problems.push_back("nodes " + id(a0) + " and " + id(a1) + " are neighbours on the first face but face " +
                             id(b0) + " and " + id(b1) + ", which are not neighbours on the second");
      continue;
    }
    GeneratedGap g;
    g.nodes = {a0, a1, b1, b0};
    std::array<Vec2, 4> c{pos(a0), pos(a1), pos(b1), pos(b0)};
    double twice_area = 0.0;
    for (std::size_t i = 0; i < 4; ++i) twice_area += cross(c[i], c[(i + 1) % 4]);
    if (twice_area < 0.0) g.nodes = {a0, b0, b1, a1};
    const Vec2 m = (pos(b0) - pos(a0)) + (pos(b1) - pos(a1));
    g.angle_deg = std::atan2(m.y(), m.x()) * 180.0 / std::numbers::pi;
    // The model reader's rule (1) for M (solver/gap_faces.hpp), said here in the assembly's terms. (Its
    // rule (2) holds by construction: the faces lie on the two curves, the ends are shared.)
    std::array<Vec2, 4> corners{};
    for (std::size_t i = 0; i < 4; ++i) corners[i] = pos(g.nodes[i]);
    if (!runs_across(gap_faces(corners, 4, g.angle_deg))) {
      out.problems.push_back("the gap element between nodes " + id(a0) + "-" + id(a1) + " and " + id(b0) + "-" + id(b1) +
                             " would have its M axis (" + length(g.angle_deg) + " degrees, the mean direction from " +
                             id(a0) + " to " + id(b0) + " and " + id(a1) + " to " + id(b1) +
                             ") more than 30 degrees off perpendicular to its faces: the facing nodes are offset "
                             "along the faces; give both curves the same node distribution");
      continue;
    }
    out.gaps.push_back(g);
  }
  for (std::size_t k = 0; k < a.nodes.size(); ++k) out.pairs.emplace_back(a.nodes[k], b.nodes[partner[k]]);
  if (!out.problems.empty()) out.gaps.clear();
  return out;
}

}  // namespace saasgaps::io
