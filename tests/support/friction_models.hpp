#pragma once
/// Models for the friction solver's tests and benchmark (FrictionalContact at solver level): two
/// bodies of one material in plane strain with matching meshes on their interface, joined by
/// node-to-node contact pairs, and the system K u = f on a pattern that couples each pair's nodes.

#include <memory>
#include <span>
#include <vector>

#include "solver/assembly/dof_map.hpp"
#include "solver/gaps/contact_pairs.hpp"
#include "solver/lac/csc_pattern.hpp"
#include "solver/lac/sparse_cholesky.hpp"
#include "solver/model/model.hpp"

namespace saasgaps::testing {

/// K of a model (initial materials, solids only) on a pattern that also couples each pair's nodes,
/// and the rhs of any load state with the same prescribed components.
class CoupledSystem {
 public:
  CoupledSystem(const Model& model, const ContactPairs& pairs);

  /// f of a load state (its prescribed values lifted: K_fp u_p moved to the right).
  [[nodiscard]] std::vector<double> rhs(const Model& state) const;
  /// (u_r, u_z) per node from the free displacements and the prescribed values of `state`.
  [[nodiscard]] std::vector<double> full(const Model& state, std::span<const double> u) const;
  /// max |K u - f - contact| over the free equations (contact: C^T lambda as a load vector).
  [[nodiscard]] double imbalance(std::span<const double> u, std::span<const double> f,
                                 std::span<const double> contact) const;

  [[nodiscard]] const DofMap& dofs() const { return dofs_; }
  [[nodiscard]] const CscPattern& pattern() const { return pattern_; }
  [[nodiscard]] std::span<const double> values() const { return values_; }
  SparseCholesky& cholesky() { return *cholesky_; }

 private:
  DofMap dofs_;
  CscPattern pattern_;
  std::vector<double> values_;
  std::unique_ptr<SparseCholesky> cholesky_;
};

/// Cattaneo-Mindlin in plane strain: two bodies of one material (so that normal and tangential
/// responses uncouple) touching along z = 0 with the initial gap x^2 / (2 R) of two cylinders (the
/// node pairs' g0), pressed by a rigid platen on the upper body's top (z prescribed to -sink), then
/// sheared by a force Q on that top below mu P. Half-spaces give the Hertz half-width
/// a^2 = 4 P R / (pi E*), 1 / E* = 2 (1 - nu^2) / E, and a central stick zone of half-width
/// c = a sqrt(1 - Q / (mu P)). Interface and depth: nodes every `spacing` over |x| < 1.3 (and the
/// first 0.5 of depth), then growing by `growth` out to 8 each way.
struct Cylinders {
  static constexpr double radius = 10.0;
  static constexpr double E = 1000.0, nu = 0.3;
  Model model;
  ContactPairs pairs;
  std::vector<double> x;  ///< the interface nodes' r, in the pairs' order
  std::vector<int> top;   ///< the upper body's top nodes
};

Cylinders cylinders(double sink, double spacing, double growth = 1.25);

/// The model with a shear force Q on the upper body's top (consistent loads of a uniform traction).
Model sheared(const Cylinders& c, double Q);

}  // namespace saasgaps::testing
