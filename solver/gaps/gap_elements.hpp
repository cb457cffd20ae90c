#pragma once
/// The gap elements as the contact methods that use them see them (contact_method.hpp): their
/// fictitious material under this iteration's moduli, their assembly on top of the solids, and the
/// closure and normal stress they measure. Both built-in methods keep them: the classic method as its
/// whole model of contact, the exact method at the floor modulus, where they hold bodies supported
/// only by gaps.

#include <span>
#include <string_view>
#include <vector>

#include "solver/contact/contact_method.hpp"
#include "solver/gaps/gap_closure.hpp"
#include "solver/model/model.hpp"

namespace saasgaps {

/// The load a gap's floor spring carries: |sigma_m| times its face area (gap_face_area), gap index.
struct FloorLoad {
  double force = 0.0;
  std::size_t gap = 0;
};

/// |f|_1, the load of one solve: the sum of the magnitudes of the right-hand side's entries.
double load_norm(std::span<const double> rhs);

class GapElements {
 public:
  GapElements(const Model& model, const GapSettings& settings);

  [[nodiscard]] const GapSettings& settings() const { return settings_; }
  /// Section II's modulus rules and test (e) for these settings.
  [[nodiscard]] const GapClosure& closure() const { return closure_; }

  /// The floor modulus (the schedule's last value) in every gap, M and N alike.
  [[nodiscard]] GapModuli floor_moduli() const;

  /// Iteration K+1 uses `next`: the moduli and strains of K become the previous ones (from K = 1 on).
  static void advance(GapHistory& history, GapModuli next, int finished_iterations);

  /// Adds the gap elements under `moduli` to the system, on top of its last solid assembly.
  void assemble(StiffnessSystem& system, const GapModuli& moduli) const;

  /// Per gap element, from the full displacement vector under the moduli history.used: id, eps_M
  /// (normal strain across the gap), closure = -100 eps_M, E_M used and sigma_m (normal stress across
  /// it). Leaves state, converged and failure to the method.
  void measure(const GapHistory& history, std::span<const double> displacement, ContactOutcome& outcome) const;

  /// Adds the forces the gap elements under history.used exert on their nodes, -(K_g u_g), to
  /// `forces` (f_r, f_z per node).
  void add_nodal_forces(const GapHistory& history, std::span<const double> displacement,
                        std::span<double> forces) const;

  /// Records the outcome's strains in history.strain after a solve. Resuming, the saved strains go on
  /// (the same build recomputes them to the last bit; a binary built differently may differ by
  /// round-off, and that is still this model's state); anything more throws SolverError: the state
  /// belongs to another model.
  void keep_strains(const ContactOutcome& outcome, GapHistory& history) const;

  /// The area gap g's normal stress acts on (gap_faces.hpp: gap_face_area).
  [[nodiscard]] double face_area(std::size_t g) const { return face_area_[g]; }

  /// The floor springs of gaps that do not touch are there to hold bodies supported only by gaps, not
  /// to carry load. The contact problem has no solution when the floor springs of the gaps in `floor`
  /// carry more than `largest_share` of `carried` (the load: |f|_1 plus what contact carries): a body
  /// is pushed away from every support, or the floor modulus is not negligible. Then throws
  /// SolverError "the contact problem has no solution" naming the share and the gaps carrying the most
  /// (`which` says what they are), with their nodes and closures.
  void check_floor_share(std::vector<FloorLoad> floor, double carried, double largest_share,
                         const ContactOutcome& outcome, std::string_view which) const;

  /// The gap columns every gap-element method fills: the tensile modulus and the extrapolation flag.
  static void add_columns(const GapHistory& history, IterationRecord& row);

 private:
  const Model& model_;
  GapSettings settings_;
  GapClosure closure_;
  std::vector<double> face_area_;
};

}  // namespace saasgaps
