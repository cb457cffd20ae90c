#include "solver/recovery/patch_recovery.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cassert>
#include <cmath>
#include <memory>
#include <optional>

#include "solver/base/index_ranges.hpp"
#include "solver/fe/element_family.hpp"

namespace saasgaps {

namespace {

/// The patch polynomials, each with its monomials x^i y^j and the next smaller one to fall back on.
enum class Polynomial : std::uint8_t { constant, linear, quadratic, serendipity, lagrange };

constexpr int max_terms = 9;

struct Monomials {
  int count;
  std::array<std::array<int, 2>, max_terms> power;
  Polynomial smaller;
};

constexpr std::array<Monomials, 5> monomials{{
    {1, {{{0, 0}}}, Polynomial::constant},
    {3, {{{0, 0}, {1, 0}, {0, 1}}}, Polynomial::constant},
    {6, {{{0, 0}, {1, 0}, {0, 1}, {2, 0}, {1, 1}, {0, 2}}}, Polynomial::linear},
    {8, {{{0, 0}, {1, 0}, {0, 1}, {2, 0}, {1, 1}, {0, 2}, {2, 1}, {1, 2}}}, Polynomial::quadratic},
    {9, {{{0, 0}, {1, 0}, {0, 1}, {2, 0}, {1, 1}, {0, 2}, {2, 1}, {1, 2}, {2, 2}}}, Polynomial::serendipity},
}};

const Monomials& monomials_of(Polynomial p) { return monomials[static_cast<std::size_t>(p)]; }

using Basis = Eigen::Matrix<double, Eigen::Dynamic, 1, Eigen::ColMajor, max_terms, 1>;
using TermMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::ColMajor, max_terms, max_terms>;
using Coefficients = Eigen::Matrix<double, Eigen::Dynamic, 4, Eigen::ColMajor, max_terms, 4>;

/// P(x) of a polynomial.
Basis basis(const Vec2& x, Polynomial p) {
  const Monomials& m = monomials_of(p);
  const std::array<double, 3> xp{1.0, x.x(), x.x() * x.x()};
  const std::array<double, 3> yp{1.0, x.y(), x.y() * x.y()};
  Basis P(m.count);
  for (int k = 0; k < m.count; ++k) {
    P[k] = xp[static_cast<std::size_t>(m.power[static_cast<std::size_t>(k)][0])] *
           yp[static_cast<std::size_t>(m.power[static_cast<std::size_t>(k)][1])];
  }
  return P;
}

/// The patch polynomial of a family: the monomials of its own shape functions, complete to its order.
Polynomial polynomial_of(ElementType type) {
  switch (type) {
    case ElementType::tri6: return Polynomial::quadratic;
    case ElementType::quad8: return Polynomial::serendipity;
    case ElementType::quad9: return Polynomial::lagrange;
    default: return Polynomial::linear;
  }
}

/// The polynomial two families' patch shares: the smaller (a quadratic for quad8 with quad9).
Polynomial common(Polynomial a, Polynomial b) {
  if (a == b) return a;
  const auto rank = [](Polynomial p) { return monomials_of(p).count; };
  const Polynomial low = rank(a) < rank(b) ? a : b;
  const Polynomial high = low == a ? b : a;
  // serendipity and lagrange share the serendipity terms; tri6's quadratic is within both.
  if (low == Polynomial::serendipity && high == Polynomial::lagrange) return low;
  return low == Polynomial::linear || low == Polynomial::constant ? low : Polynomial::quadratic;
}

/// One patch's polynomial: value(x) = c^T P((x - centre) / scale).
struct Fit {
  Vec2 centre = Vec2::Zero();
  double scale = 1.0;
  bool made = false;  ///< false: no patch (the node is no corner in this material)
  Polynomial polynomial = Polynomial::constant;
  Coefficients c;

  [[nodiscard]] Vec4 at(const Vec2& x) const {
    return made ? Vec4(c.transpose() * basis((x - centre) / scale, polynomial)) : Vec4::Zero();
  }
};

/// The corners of an element: its family's, or 3 for a report element given 3 nodes (a tri3 that
/// older models and tests type as saas).
int corner_count(const Element& el) { return std::min(family(el.type).corner_count, el.node_count); }

/// Node -> solid elements incidence: element index and the node's local index in it.
struct Incidence {
  std::vector<std::uint32_t> first;
  std::vector<std::uint32_t> element;
  std::vector<std::uint8_t> local;

  /// Whether entry k, an element of node n, is in the patch of corner n in material m: an element of
  /// material m with n among its corners.
  [[nodiscard]] bool in_patch(const Model& model, std::uint32_t k, int m) const {
    const Element& el = model.elements[element[k]];
    return el.material == m && local[k] < corner_count(el);
  }
};

Incidence incidence(const Model& model) {
  Incidence in;
  in.first.assign(model.nodes.size() + 1, 0);
  for (const Element& el : model.elements) {
    for (int a = 0; a < el.node_count; ++a) in.first[static_cast<std::size_t>(el.nodes[a]) + 1] += 1;
  }
  for (std::size_t n = 0; n < model.nodes.size(); ++n) in.first[n + 1] += in.first[n];
  in.element.resize(in.first.back());
  in.local.resize(in.first.back());
  std::vector<std::uint32_t> next(in.first.begin(), in.first.end() - 1);
  for (std::size_t e = 0; e < model.elements.size(); ++e) {
    const Element& el = model.elements[e];
    for (int a = 0; a < el.node_count; ++a) {
      const std::uint32_t k = next[static_cast<std::size_t>(el.nodes[a])]++;
      in.element[k] = static_cast<std::uint32_t>(e);
      in.local[k] = static_cast<std::uint8_t>(a);
    }
  }
  return in;
}

/// Cholesky factor L L^T = A of the n x n normal matrix A (lower triangle, row-major with stride
/// max_terms), in place. False when a pivot falls to 1e-8 of its diagonal or below: a term the
/// points (nearly) do not determine apart from the others (the sine of its column's angle to the
/// earlier columns' span below 1e-4), left to the rank-revealing decomposition.
bool cholesky_in_place(std::array<double, max_terms * max_terms>& L, int n) {
  for (int j = 0; j < n; ++j) {
    double* row_j = &L[static_cast<std::size_t>(j * max_terms)];
    const double diagonal = row_j[j];
    double d = diagonal;
    for (int k = 0; k < j; ++k) d -= row_j[k] * row_j[k];
    if (!(d > 1e-8 * diagonal)) return false;
    row_j[j] = std::sqrt(d);
    for (int i = j + 1; i < n; ++i) {
      double* row_i = &L[static_cast<std::size_t>(i * max_terms)];
      double v = row_i[j];
      for (int k = 0; k < j; ++k) v -= row_i[k] * row_j[k];
      row_i[j] = v / row_j[j];
    }
  }
  return true;
}

/// Least squares with the highest polynomial the points determine (see the header). The normal
/// equations A c = b (A = sum P P^T, b = sum P value^T) are accumulated in fixed-size arrays and
/// solved by Cholesky; a rank-deficient A goes to the complete orthogonal decomposition.
Fit fit_patch(const Vec2& centre, Polynomial most, std::span<const SamplingPoint> points) {
  Fit f;
  f.centre = centre;
  double scale = 0.0;
  for (const SamplingPoint& p : points) scale = std::max(scale, (p.x - centre).norm());
  f.scale = scale > 0.0 ? scale : 1.0;
  if (points.empty()) return f;
  f.made = true;
  for (Polynomial poly = most;; poly = monomials_of(poly).smaller) {
    const Monomials& m = monomials_of(poly);
    const int terms = m.count;
    if (static_cast<int>(points.size()) < terms) continue;
    std::array<double, max_terms * max_terms> A{};  // lower triangle, row i at i * max_terms
    std::array<double, max_terms * 4> b{};          // row i at 4 i
    for (const SamplingPoint& p : points) {
      const Vec2 x = (p.x - centre) / f.scale;
      const std::array<double, 3> xp{1.0, x.x(), x.x() * x.x()};
      const std::array<double, 3> yp{1.0, x.y(), x.y() * x.y()};
      std::array<double, max_terms> P{};
      for (int k = 0; k < terms; ++k) {
        P[static_cast<std::size_t>(k)] = xp[static_cast<std::size_t>(m.power[static_cast<std::size_t>(k)][0])] *
                                         yp[static_cast<std::size_t>(m.power[static_cast<std::size_t>(k)][1])];
      }
      for (std::size_t i = 0; i < static_cast<std::size_t>(terms); ++i) {
        for (std::size_t j = 0; j <= i; ++j) A[i * max_terms + j] += P[i] * P[j];
        for (std::size_t c = 0; c < 4; ++c) b[4 * i + c] += P[i] * p.value[static_cast<Eigen::Index>(c)];
      }
    }
    f.polynomial = poly;
    f.c.resize(terms, 4);
    if (terms == 1) {
      for (Eigen::Index c = 0; c < 4; ++c) f.c(0, c) = b[static_cast<std::size_t>(c)] / A[0];
      return f;
    }
    std::array<double, max_terms * max_terms> L = A;
    if (cholesky_in_place(L, terms)) {
      const auto n = static_cast<std::size_t>(terms);
      for (std::size_t c = 0; c < 4; ++c) {
        std::array<double, max_terms> y{};
        for (std::size_t i = 0; i < n; ++i) {  // L y = b
          double v = b[4 * i + c];
          for (std::size_t k = 0; k < i; ++k) v -= L[i * max_terms + k] * y[k];
          y[i] = v / L[i * max_terms + i];
        }
        for (std::size_t i = n; i-- > 0;) {  // L^T c = y
          double v = y[i];
          for (std::size_t k = i + 1; k < n; ++k) v -= L[k * max_terms + i] * y[k];
          y[i] = v / L[i * max_terms + i];
        }
        for (std::size_t i = 0; i < n; ++i) f.c(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(c)) = y[i];
      }
      return f;
    }
    // Points that do not determine every term (all on two lines, say: a patch one element high)
    // leave the undetermined combinations at zero: the minimum-norm least-squares solution.
    TermMatrix full(terms, terms);
    Coefficients rhs(terms, 4);
    for (Eigen::Index i = 0; i < terms; ++i) {
      for (Eigen::Index j = 0; j <= i; ++j) {
        full(i, j) = full(j, i) = A[static_cast<std::size_t>(i * max_terms + j)];
      }
      for (Eigen::Index c = 0; c < 4; ++c) rhs(i, c) = b[static_cast<std::size_t>(4 * i + c)];
    }
    Eigen::CompleteOrthogonalDecomposition<TermMatrix> cod(full);
    cod.setThreshold(1e-10);
    f.c = cod.solve(rhs);
    return f;
  }
}

/// A fit as pass 2 reads it, 16 bytes a side: a model-sized array of Fits (330 bytes each) is
/// hundreds of MB at 10^6 unknowns, and fresh memory costs about 4 us a page on first touch on a
/// virtual machine. Its numbers live in the pass's FitPool.
struct StoredFit {
  const double* data = nullptr;  ///< centre (r, z), scale, then c (terms x 4, column-major)
  Polynomial polynomial = Polynomial::constant;
  bool made = false;  ///< false: no patch (the node is no corner in this material)

  [[nodiscard]] Vec4 at(const Vec2& x) const {
    if (data == nullptr) return Vec4::Zero();
    const Vec2 centre(data[0], data[1]);
    const Eigen::Map<const Coefficients> c(data + 3, monomials_of(polynomial).count, 4);
    return c.transpose() * basis((x - centre) / data[2], polynomial);
  }
};

/// The numbers of one thread's fits, in chunks that never move (StoredFit points into them).
class FitPool {
 public:
  StoredFit keep(const Fit& f) {
    StoredFit s;
    s.polynomial = f.polynomial;
    s.made = f.made;
    if (!f.made) return s;
    const auto size = static_cast<std::size_t>(f.c.size());
    double* d = take(3 + size);
    d[0] = f.centre.x();
    d[1] = f.centre.y();
    d[2] = f.scale;
    std::copy_n(f.c.data(), size, d + 3);
    s.data = d;
    return s;
  }

 private:
  static constexpr std::size_t chunk = std::size_t{1} << 14;  // doubles (128 KiB)
  double* take(std::size_t n) {
    if (used_ + n > chunk) {
      chunks_.push_back(std::make_unique_for_overwrite<double[]>(chunk));
      used_ = 0;
    }
    double* p = chunks_.back().get() + used_;
    used_ += n;
    return p;
  }
  std::vector<std::unique_ptr<double[]>> chunks_;
  std::size_t used_ = chunk;
};

/// The sampling points of one patch: those of corner node n's elements in material m, and their
/// mirror images when n is on a symmetry line. Kept in the caller's buffer (reused per patch).
class PatchPoints {
 public:
  PatchPoints(const Model& model, const Incidence& in, const ElementSampler& sample, const SymmetryLines* symmetry)
      : model_(model), in_(in), sample_(sample), symmetry_(symmetry) {}

  /// Gathers corner n's patch in material m; nullopt when n is a corner of none of them.
  std::optional<Polynomial> gather(std::size_t n, int m) {
    points_.clear();
    std::optional<Polynomial> poly;
    for (std::uint32_t k = in_.first[n]; k < in_.first[n + 1]; ++k) {
      if (!in_.in_patch(model_, k, m)) continue;
      const Element& el = model_.elements[in_.element[k]];
      poly = poly ? common(*poly, polynomial_of(el.type)) : polynomial_of(el.type);
      const ElementSamples es = sample_(in_.element[k]);
      points_.insert(points_.end(), es.point.begin(), es.point.begin() + es.count);
    }
    if (mirrored(n)) {
      const std::size_t own = points_.size();
      for (std::size_t p = 0; p < own; ++p) {
        points_.push_back({symmetry_->mirror_point(model_, n, points_[p].x), symmetry_->mirror_value(n, points_[p].value)});
      }
    }
    return poly;
  }

  [[nodiscard]] bool mirrored(std::size_t n) const { return symmetry_ != nullptr && symmetry_->on_line(n); }
  [[nodiscard]] std::span<const SamplingPoint> points() const { return points_; }

 private:
  const Model& model_;
  const Incidence& in_;
  const ElementSampler& sample_;
  const SymmetryLines* symmetry_;
  std::vector<SamplingPoint> points_;
};

/// The sides: the distinct materials of each node's elements, in increasing order (values zero).
RecoveredField field_sides(const Model& model, const Incidence& in) {
  const std::size_t node_count = model.nodes.size();
  RecoveredField f;
  f.first.assign(node_count + 1, 0);
  f.material.reserve(node_count);
  for (std::size_t n = 0; n < node_count; ++n) {
    std::array<int, 16> seen{};
    int count = 0;
    for (std::uint32_t k = in.first[n]; k < in.first[n + 1]; ++k) {
      const int m = model.elements[in.element[k]].material;
      if (std::find(seen.begin(), seen.begin() + count, m) == seen.begin() + count) {
        if (count < static_cast<int>(seen.size())) seen[static_cast<std::size_t>(count++)] = m;
      }
    }
    std::sort(seen.begin(), seen.begin() + count);
    for (int s = 0; s < count; ++s) f.material.push_back(seen[static_cast<std::size_t>(s)]);
    f.first[n + 1] = static_cast<std::uint32_t>(f.material.size());
  }
  f.value.assign(f.material.size(), Vec4::Zero());
  return f;
}

/// What a side is to the patches (the header's rules).
enum class SideKind : std::uint8_t {
  not_corner,       ///< only a mid-side or centre node in its material: no patch of its own
  boundary_corner,  ///< a corner on its material region's boundary: its patch is extrapolated
  interior_corner,  ///< every edge at the corner shared by two of its elements (or along its
                    ///< symmetry line): its own patch's value
};

/// The kind of node n's side in material m, from the edges at n to its neighbouring corners.
/// `neighbours` is the caller's buffer.
SideKind side_kind(const Model& model, const Incidence& in, const SymmetryLines* symmetry, std::size_t n, int m,
                   std::vector<int>& neighbours) {
  neighbours.clear();
  bool corner = false;
  for (std::uint32_t k = in.first[n]; k < in.first[n + 1]; ++k) {
    if (!in.in_patch(model, k, m)) continue;
    const Element& el = model.elements[in.element[k]];
    const int a = in.local[k];
    const int corners = corner_count(el);
    corner = true;
    neighbours.push_back(el.nodes[(a + 1) % corners]);
    neighbours.push_back(el.nodes[(a + corners - 1) % corners]);
  }
  if (!corner) return SideKind::not_corner;
  // Interior: every edge at n (to a neighbouring corner) is shared by exactly two elements, or lies
  // along n's symmetry line (its mirror image is the other).
  const bool on_line = symmetry != nullptr && symmetry->on_line(n);
  std::sort(neighbours.begin(), neighbours.end());
  for (std::size_t i = 0; i < neighbours.size();) {
    std::size_t j = i;
    while (j < neighbours.size() && neighbours[j] == neighbours[i]) ++j;
    const bool along_line = on_line && symmetry->same_line(model, n, static_cast<std::size_t>(neighbours[i]));
    if (!(j - i == 2 || (j - i == 1 && along_line))) return SideKind::boundary_corner;
    i = j;
  }
  return SideKind::interior_corner;
}

}  // namespace

std::array<Vec4, max_element_nodes> element_nodal_values(const Model& model, const RecoveredField& field, std::size_t e) {
  const Element& el = model.elements[e];
  std::array<Vec4, max_element_nodes> out{};
  for (int a = 0; a < el.node_count; ++a) {
    out[static_cast<std::size_t>(a)] = field.at(static_cast<std::size_t>(el.nodes[a]), el.material);
  }
  return out;
}

RecoveredField recover_field(const Model& model, const ElementSampler& sample, const SymmetryLines* symmetry) {
  assert(symmetry == nullptr || symmetry->empty() || symmetry->kind.size() == model.nodes.size());
  if (symmetry != nullptr && symmetry->empty()) symmetry = nullptr;
  const std::size_t node_count = model.nodes.size();
  const Incidence in = incidence(model);
  RecoveredField f = field_sides(model, in);
  const std::size_t side_count = f.material.size();

  // Pass 1, per side: its kind, from the mesh alone.
  std::vector<SideKind> kind(side_count, SideKind::not_corner);
  for_each_range(node_count, [&](std::size_t begin, std::size_t end, unsigned) {
    std::vector<int> neighbours;
    for (std::size_t n = begin; n < end; ++n) {
      for (std::uint32_t s = f.first[n]; s < f.first[n + 1]; ++s) {
        kind[s] = side_kind(model, in, symmetry, n, f.material[s], neighbours);
      }
    }
  });
  // Whether a side other than an interior corner reads the patch of corner n in material m (pass
  // 3): a node of one of the patch's elements, n itself included.
  const auto read_by_pass_3 = [&](std::size_t n, int m) {
    for (std::uint32_t k = in.first[n]; k < in.first[n + 1]; ++k) {
      if (!in.in_patch(model, k, m)) continue;
      const Element& el = model.elements[in.element[k]];
      for (int a = 0; a < el.node_count; ++a) {
        const int side = f.side(static_cast<std::size_t>(el.nodes[static_cast<std::size_t>(a)]), m);
        if (kind[static_cast<std::size_t>(side)] != SideKind::interior_corner) return true;
      }
    }
    return false;
  };

  // Pass 2, per corner side: its patch's fit, the value of an interior corner, and the fits pass 3
  // reads kept (near the regions' boundaries and at mid-side nodes: a block of the report's
  // elements keeps a few in a thousand).
  std::vector<StoredFit> fits(side_count);
  std::vector<FitPool> pools(range_count(node_count));
  for_each_range(node_count, [&](std::size_t begin, std::size_t end, unsigned r) {
    PatchPoints patch(model, in, sample, symmetry);
    for (std::size_t n = begin; n < end; ++n) {
      const Vec2 x(model.nodes[n].r, model.nodes[n].z);
      for (std::uint32_t s = f.first[n]; s < f.first[n + 1]; ++s) {
        if (kind[s] == SideKind::not_corner) continue;
        const int m = f.material[s];
        const std::optional<Polynomial> poly = patch.gather(n, m);
        assert(poly);
        const Fit fit = fit_patch(x, *poly, patch.points());
        if (kind[s] == SideKind::interior_corner) f.value[s] = fit.at(x);
        if (read_by_pass_3(n, m)) fits[s] = pools[r].keep(fit);
      }
    }
  });

  // Pass 3, per side that is not an interior corner: the value from the patches that reach it (see
  // the header), pulled so that each side is written by one thread.
  for_each_range(node_count, [&](std::size_t begin, std::size_t end, unsigned) {
    struct Reached {
      std::uint32_t side;
      std::size_t node;
    };
    std::vector<Reached> reached;
    for (std::size_t n = begin; n < end; ++n) {
      const Vec2 x(model.nodes[n].r, model.nodes[n].z);
      const bool on_line = symmetry != nullptr && symmetry->on_line(n);
      for (std::uint32_t s = f.first[n]; s < f.first[n + 1]; ++s) {
        if (kind[s] == SideKind::interior_corner) continue;
        const int m = f.material[s];
        // The corner sides of material m whose patches hold node n: the corners of n's elements in m.
        reached.clear();
        if (kind[s] != SideKind::not_corner) reached.push_back({s, n});
        for (std::uint32_t k = in.first[n]; k < in.first[n + 1]; ++k) {
          const Element& el = model.elements[in.element[k]];
          if (el.material != m) continue;
          const int corners = corner_count(el);
          for (int c = 0; c < corners; ++c) {
            const auto node = static_cast<std::size_t>(el.nodes[c]);
            if (node == n) continue;
            const auto cs = static_cast<std::uint32_t>(f.side(node, m));
            if (std::none_of(reached.begin(), reached.end(), [&](const Reached& r) { return r.side == cs; })) {
              reached.push_back({cs, node});
            }
          }
        }
        // A patch's value at n; a patch off n's symmetry line also with its mirror image (weight 2:
        // the mirrored mesh's patch too).
        const auto value_from = [&](const Reached& r, Vec4& sum, double& weight) {
          const Vec4 v = fits[r.side].at(x);
          if (on_line && !symmetry->same_line(model, n, r.node)) {
            sum += v + symmetry->mirror_value(n, v);
            weight += 2.0;
          } else {
            sum += v;
            weight += 1.0;
          }
        };
        Vec4 sum = Vec4::Zero();
        double weight = 0.0;
        for (const Reached& r : reached) {
          if (kind[r.side] == SideKind::interior_corner) value_from(r, sum, weight);
        }
        if (weight == 0.0) {
          for (const Reached& r : reached) value_from(r, sum, weight);
        }
        f.value[s] = sum / std::max(weight, 1.0);
      }
    }
  });
  return f;
}

RecoveredField recover_field(const Model& model, std::span<const ElementSamples> samples, const SymmetryLines* symmetry) {
  assert(samples.size() == model.elements.size());
  return recover_field(model, [samples](std::size_t e) { return samples[e]; }, symmetry);
}

}  // namespace saasgaps
