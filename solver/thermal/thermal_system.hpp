#pragma once
/// The heat conduction system of a model's `thermal` section on its mesh: one unknown T per node,
/// the prescribed temperatures eliminated, every solid element one clique (its film edges, fluxes
/// and source added into its own block) and, when gap elements conduct, every gap element one more
/// (conduction_kernel.hpp gives the report's elements' formulas, isoparametric_conduction.hpp those of
/// tri6, quad8, quad9 and quad4i, Assembler the scatter). A boundary edge of a quadratic element
/// carries its mid-side node: a prescribed temperature holds it, films and fluxes integrate along it.
///
/// Gap elements conduct across their M axis only: a gap of conductance H (power / area /
/// temperature) is a conduction element with k_M = H w and k_L = 0, w its width across M (the
/// distance of its two faces), so that the heat through it is H (T_a - T_b) per area of face.
///
/// Contact pairs with a `conductance` conduct through their mortar rows (contact_conductance.hpp):
/// every row one more clique over its nodes, after the gap elements.
///
/// A node that nothing conducts to (no solid element has it, and the gaps do not conduct or every
/// gap element that has it is at conductance 0, as an open gap without gas: a ground node of gap
/// elements, a node of no element) has no capacity and no conduction, so its temperature is not a
/// result of the solve: its row is T = held, held being its temperature of the step before in a
/// time step (the initial temperature until something conducts to it) and the reference
/// temperature in a steady solve. Without that its row would be zero and the matrix singular.
/// Contact rows join nodes of solid elements only.

#include <span>
#include <utility>
#include <vector>

#include "solver/assembly/assembler.hpp"
#include "solver/assembly/dof_map.hpp"
#include "solver/model/model.hpp"
#include "solver/thermal/conduction_kernel.hpp"
#include "solver/thermal/conduction_loads.hpp"
#include "solver/thermal/contact_conductance.hpp"
#include "solver/thermal/isoparametric_conduction.hpp"

namespace saasgaps {

/// The width w of a gap element across its M axis: the distance of its two faces (gap_faces.hpp).
double gap_width(const Model& model, const GapElement& gap);

class ThermalSystem {
 public:
  /// The model must have `thermal`. Gap elements join the pattern when model.gaps has a conductance.
  explicit ThermalSystem(const Model& model);

  [[nodiscard]] const DofMap& dofs() const { return dofs_; }
  [[nodiscard]] const CscPattern& pattern() const { return assembler_.pattern(); }
  [[nodiscard]] bool gaps_conduct() const { return gaps_conduct_; }
  [[nodiscard]] const ContactConductance& contact() const { return contact_; }
  /// Whether some edge radiates: the system is then nonlinear in T (assemble's `current`).
  [[nodiscard]] bool radiates() const { return radiates_; }

  /// Each solid element's conductivity (k1, k2) at the mean of its nodes' temperatures T (one per node).
  [[nodiscard]] std::vector<Conductivity> conductivities(std::span<const double> T) const;

  /// Assembles A = K + films (+ C / dt for a time step) and f into values (pattern().nnz()) and
  /// rhs (dofs().size()), both zeroed here. k: conductivities(); inverse_dt: 1 / dt (0 for a steady
  /// solve), with previous the node temperatures of the step before (the capacity density c is
  /// taken at their element means); gap_conductance: H per gap element (gaps_conduct() only, else
  /// empty); contact_conductance: H per row of contact(); current: the node temperatures at which
  /// radiating edges are linearized (read only when radiates()).
  ///
  /// Radiation, q_out = es (T^4 - Ta^4) with es = emissivity sigma, is a film on the edge linearized
  /// at the edge's mean current temperature T0 (Newton): q_out ~ es (T0^4 - Ta^4) + 4 es T0^3 (T - T0),
  /// a film h = 4 es T0^3 with ambient T0 - (T0^4 - Ta^4) / (4 T0^3). At T0 <= 0 (a start at zero
  /// absolute) the secant film es (T0^2 + Ta^2)(T0 + Ta) with ambient Ta instead.
  /// loads (optional): receives each solid element's load parts (conduction_loads.hpp) for
  /// assemble_rhs. A node nothing conducts to gets the row T = held (above): previous's value, or
  /// the reference temperature when previous is empty.
  void assemble(std::span<const Conductivity> k, double inverse_dt, std::span<const double> previous,
                std::span<const double> gap_conductance, std::span<const double> contact_conductance,
                std::span<const double> current, std::span<double> values, std::span<double> rhs,
                ConductionLoads* loads = nullptr) const;

  /// Each solid element's capacity rate density c / dt, c at the mean of its nodes' previous
  /// temperatures (what assemble uses); empty for inverse_dt = 0.
  [[nodiscard]] std::vector<double> capacity_rates(double inverse_dt, std::span<const double> previous) const;

  /// The rhs of assemble, to the last bit, without the matrix: valid while k, the capacity rates,
  /// the conductances and loads (from the assemble that filled it) are those of that assemble and
  /// no edge radiates. Elements with a nonzero prescribed temperature are computed whole (their K
  /// lifts it); every other element of every family from its load parts with no kernel.
  void assemble_rhs(std::span<const Conductivity> k, double inverse_dt, std::span<const double> previous,
                    std::span<const double> gap_conductance, std::span<const double> contact_conductance,
                    const ConductionLoads& loads, std::span<double> rhs) const;

  /// Node temperatures from the free unknowns x (prescribed nodes take their values).
  [[nodiscard]] std::vector<double> node_temperatures(std::span<const double> x) const;

  /// Heat flux per solid element (q_r, q_z) at node temperatures T.
  [[nodiscard]] std::vector<Vec2> fluxes(std::span<const Conductivity> k, std::span<const double> T) const;

 private:
  /// Gap elements in the pattern: all of model.gaps when they conduct, else none.
  [[nodiscard]] std::size_t gap_count() const { return gaps_conduct_ ? model_.gaps->elements.size() : 0; }
  [[nodiscard]] ConductionData data(const Element& el, const Conductivity& k) const;
  [[nodiscard]] IsoConductionData iso_data(const Element& el, const Conductivity& k) const;
  [[nodiscard]] ConductionLoad load(std::size_t e, double rate, std::span<const double> previous) const;
  /// Adds element e's flux, film and radiation edges (node coordinates x, in the element's order)
  /// into K and f (Matrix4d and Vector4d for the report's elements, ConductionMatrix and
  /// ConductionVector for the others).
  template <class Matrix, class Vector>
  void add_edges(std::size_t e, std::span<const Vec2> x, std::span<const double> current, Matrix& K, Vector& f) const;
  [[nodiscard]] Eigen::Matrix4d gap_matrix(std::size_t g, double conductance) const;
  /// Gives every node outside the solids that nothing conducts to at these gap conductances the
  /// row T = held: a unit diagonal in values (skipped when empty) and held in rhs.
  void hold_isolated(std::span<const double> gap_conductance, std::span<const double> previous,
                     std::span<double> values, std::span<double> rhs) const;

  const Model& model_;
  DofMap dofs_;
  bool gaps_conduct_ = false;
  bool radiates_ = false;
  ContactConductance contact_;  // before assembler_: its rows are cliques of the pattern
  Assembler assembler_;
  std::vector<double> source_;          // per solid element: power density of its material
  std::vector<double> gap_width_;       // per gap element
  struct EdgeLoad {
    std::array<int, 3> at{-1, -1, -1};  // positions within the element of the edge's nodes, a (m) b
    int count = 2;
    ThermalBoundary::Kind kind = ThermalBoundary::Kind::flux;
    double value = 0.0, ambient = 0.0;
  };
  std::vector<std::vector<EdgeLoad>> edges_;  // per solid element, its film and flux edges
  /// A free node of no solid element: the gap elements that have it (when the gaps conduct) are all
  /// that can conduct to it. Usually none in a model.
  struct OutsideNode {
    int node = 0;
    Index equation = 0;
    std::vector<std::pair<std::size_t, int>> gaps;  // (gap element, the node's corner in it)
  };
  std::vector<OutsideNode> outside_;
};

}  // namespace saasgaps
