#pragma once
/// The analysis model as the solver sees it: plain data, every cross reference already resolved to
/// an index (the io layer maps user ids to indices and reports bad input with JSON Pointers).
///
/// Coordinates are (r, z) in every analysis. Units are the user's own and must be consistent
/// (the 1976 report uses in, lbf, psi, degF).

#include <array>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "solver/base/name_table.hpp"
#include "solver/model/element_type.hpp"
#include "solver/model/loads.hpp"

namespace saasgaps {

enum class AnalysisType { plane_stress, plane_strain, axisymmetric };
inline constexpr NameTable<AnalysisType, 3> analysis_type_names{{{{AnalysisType::plane_stress, "plane_stress"},
                                                                  {AnalysisType::plane_strain, "plane_strain"},
                                                                  {AnalysisType::axisymmetric, "axisymmetric"}}}};

struct Node {
  int id = 0;
  double r = 0.0;
  double z = 0.0;
};

/// One row of a material property table, at temperature T. Axes 1 and 2 lie in the (r, z) plane,
/// axis 1 at the element's material angle; axis 3 is the hoop (out-of-plane) direction.
/// An isotropic row has E1 = E2 = E3 = E, nu12 = nu13 = nu23 = nu, alpha1..3 = alpha, and its
/// shear modulus follows from the interpolated E and nu (G12 is ignored).
struct PropertyRow {
  double T = 0.0;
  double E1 = 0.0, E2 = 0.0, E3 = 0.0;
  double nu12 = 0.0, nu13 = 0.0, nu23 = 0.0;
  double G12 = 0.0;
  double alpha1 = 0.0, alpha2 = 0.0, alpha3 = 0.0;  ///< secant expansion from the reference temperature
  /// Heat conduction (thermal runs only; Material::conducts / stores_heat say whether the rows gave
  /// them): conductivity along axes 1, 2, 3 (power / length / temperature; isotropic k1 = k2 = k3 =
  /// k) and specific heat c (energy / mass / temperature, with Material::density).
  double k1 = 0.0, k2 = 0.0, k3 = 0.0;
  double c = 0.0;
};

/// Bilinear effective stress-strain curve at temperature T: yield stress and PEMR, the ratio of the
/// secondary slope to E (0 <= PEMR < 1).
struct PlasticityRow {
  double T = 0.0;
  double yield_stress = 0.0;
  double hardening_ratio = 0.0;
};

struct Material {
  int id = 0;
  std::string name;
  double density = 0.0;  ///< body force per unit volume = density * acceleration
  bool isotropic = true;
  std::vector<PropertyRow> table;              ///< sorted by T, at least one row
  std::vector<PropertyRow> compression_table;  ///< empty: same properties in tension and compression
  std::vector<PlasticityRow> plasticity;       ///< empty: linear elastic
  bool conducts = false;     ///< every row of `table` gives k (or k1, k2, k3)
  bool stores_heat = false;  ///< every row of `table` gives c
};

/// A solid element of any family (fe/element_family.hpp): its nodes by index, corners
/// counter-clockwise first, then the mid-side nodes in the order of the edges, then the centre.
struct Element {
  int id = 0;
  std::array<int, max_element_nodes> nodes{-1, -1, -1, -1, -1, -1, -1, -1, -1};
  int node_count = 4;
  ElementType type = ElementType::saas;        ///< the family (default by node count: tri3, saas, tri6, quad8, quad9)
  Integration integration = Integration::full;  ///< quad8, quad9: full 3 x 3 or reduced 2 x 2
  int material = 0;          ///< index into Model::materials
  double angle_deg = 0.0;    ///< material axis 1, counter-clockwise from +r

  [[nodiscard]] std::span<const int> node_span() const { return std::span<const int>(nodes).first(static_cast<std::size_t>(node_count)); }
};

/// A gap element: geometry like a solid element; its properties are set by the program. angle_deg
/// is the M axis (across the gap).
struct GapElement {
  int id = 0;
  std::array<int, 4> nodes{-1, -1, -1, -1};
  int node_count = 4;
  double angle_deg = 0.0;

  [[nodiscard]] std::span<const int> node_span() const { return std::span<const int>(nodes).first(static_cast<std::size_t>(node_count)); }
};

/// How a gap passes the convergence test of section II (e).
enum class GapConvergenceTest {
  report,  ///< the report's behaviour (reproduces Tables I-III)
  strict,  ///< also demands that gaps which do not touch have fallen to the schedule's floor modulus
};
inline constexpr NameTable<GapConvergenceTest, 2> gap_convergence_test_names{
    {{{GapConvergenceTest::report, "report"}, {GapConvergenceTest::strict, "strict"}}}};

/// How the gap elements are solved.
enum class GapMethod {
  classic,  ///< the report's stress-invariance iteration of section II (reproduces Tables I-III)
  exact,    ///< gap elements give node pairs; frictionless unilateral contact solved exactly
};
inline constexpr NameTable<GapMethod, 2> gap_method_names{{{{GapMethod::classic, "classic"}, {GapMethod::exact, "exact"}}}};

/// Heat conductance across an interface (power / area / temperature): `closed` over the contact
/// pressure p for touching faces (linear in p between rows, constant beyond the ends; one row for a
/// constant), and gas conduction k_gas / gap for open ones. The same shape serves gap elements
/// (GapSettings::conductance) and contact pairs.
struct ConductanceRow {
  double p = 0.0;
  double h = 0.0;
};

struct InterfaceConductance {
  std::vector<ConductanceRow> closed;  ///< sorted by p, at least one row
  double gas_conductivity = 0.0;       ///< k_gas >= 0 (0: open faces insulate)
};

struct GapSettings {
  GapMethod method = GapMethod::classic;
  double initial_modulus = 100.0;          ///< E0, every gap's modulus in iteration 1
  std::vector<double> tensile_schedule;    ///< tensile moduli from iteration 2 on; last = floor
  double extrapolation_factor = 0.0;       ///< XFACT, 0 <= f < 1 (0: no extrapolation)
  double closure_tolerance = 0.05;         ///< converged when eps_M > -(1 + tolerance)
  double shear_ratio = 1.0e-6;             ///< gap shear modulus / current tensile modulus
  GapConvergenceTest convergence_test = GapConvergenceTest::report;
  std::vector<GapElement> elements;
  std::optional<InterfaceConductance> conductance;  ///< heat across the gaps (thermal runs); none: insulating
};

/// Prescribed displacement components of one node.
struct Constraint {
  int node = 0;
  std::optional<double> u_r;
  std::optional<double> u_z;
};

/// A node set that a constraint names (model.sets.nodes, docs/model.md "Named sets"): the support
/// reactions of its nodes are summed at the end of every converged increment and of the run
/// (results set_reactions). The reader expands the set's constraints to node constraints; the
/// solver only sums over the nodes here.
struct ReactionGroup {
  std::string name;
  std::vector<int> nodes;  ///< node indices, ascending, each once
};

struct SolverOptions {
  int max_iterations = 30;
  double plastic_tolerance = 0.01;  ///< relative stress change that marks N-L/CONV? = NO
};

/// One load step (model.steps). Its loads and constraints are the values at its end, reached
/// linearly over its increments from the end of the previous step (load_schedule.hpp).
struct Step {
  std::string name;
  int increments = 1;                   ///< >= 1
  std::optional<Loads> loads;           ///< nullopt: the previous step's (step 1: the model's loads)
  std::vector<Constraint> constraints;  ///< components prescribed at the step's end (others keep theirs)
};

/// A contact surface (model.contact.surfaces): a chain of boundary edges of solid elements, each
/// [a, b] by node index in the order and direction given (contact_surface.hpp validates and orients it).
struct SurfaceDefinition {
  std::string name;
  std::vector<std::array<int, 2>> edges;
};

/// A pair of contact surfaces (model.contact.pairs): side A (non-mortar) first, side B second.
struct SurfacePair {
  std::array<int, 2> surfaces{-1, -1};  ///< indices into ContactSettings::surfaces, distinct
  double friction = 0.0;                ///< Coulomb mu (0: frictionless, the only one solved today)
  std::optional<InterfaceConductance> conductance;  ///< heat across the pair (thermal runs)
};

struct ContactSettings {
  std::vector<SurfaceDefinition> surfaces;
  std::vector<SurfacePair> pairs;
};

/// One boundary edge of a thermal condition: a side of exactly one solid element.
struct ThermalEdge {
  int element = 0;  ///< index of the solid element that owns the edge
  int node_a = 0;
  int node_b = 0;
};

/// One entry of thermal.boundary: a prescribed temperature, a flux into the body (power / area), a
/// convection film whose outward flux is film (T - ambient), or radiation to an ambient whose
/// outward flux is emissivity sigma (T^4 - ambient^4) (temperatures absolute).
struct ThermalBoundary {
  enum class Kind { temperature, flux, film, radiation };
  Kind kind = Kind::temperature;
  std::vector<ThermalEdge> edges;
  double value = 0.0;    ///< the temperature, the flux, the film coefficient, or emissivity x sigma
  double ambient = 0.0;  ///< film and radiation only
};
/// The key of a thermal.boundary entry that gives each kind (radiation: its emissivity).
inline constexpr NameTable<ThermalBoundary::Kind, 4> thermal_boundary_keys{
    {{{ThermalBoundary::Kind::temperature, "temperature"},
      {ThermalBoundary::Kind::flux, "flux"},
      {ThermalBoundary::Kind::film, "film"},
      {ThermalBoundary::Kind::radiation, "emissivity"}}}};

/// Heat generated per unit volume in every element of a material.
struct HeatSource {
  int material = 0;  ///< index into Model::materials
  double power_density = 0.0;
};

enum class ThermalType { steady, transient };
inline constexpr NameTable<ThermalType, 2> thermal_type_names{
    {{{ThermalType::steady, "steady"}, {ThermalType::transient, "transient"}}}};

/// The thermal section: the temperatures of the stress analysis come from heat conduction on the
/// same mesh (thermal_analysis.hpp). Edges without a boundary entry are insulated.
struct Thermal {
  ThermalType type = ThermalType::steady;
  std::vector<ThermalBoundary> boundary;
  std::vector<HeatSource> sources;
  double initial_temperature = 0.0;  ///< transient
  double time_step = 0.0;            ///< transient, > 0
  double end_time = 0.0;             ///< transient, > 0
  std::vector<double> output_times;  ///< transient: strictly increasing in (0, end_time]
};

/// Indices tracked in every iteration's history row.
struct OutputOptions {
  std::vector<int> watch_elements;  ///< indices into Model::elements
  std::vector<int> watch_gaps;      ///< indices into GapSettings::elements
};

/// Names of the model's units, for people: the solver never converts (units must be consistent).
/// An empty name was not given.
struct Units {
  std::string length;
  std::string force;
  std::string stress;
  std::string temperature;
};

struct Model {
  std::string title;
  std::string description;
  Units units;
  AnalysisType analysis = AnalysisType::plane_stress;
  double thickness = 1.0;              ///< plane analyses
  double reference_temperature = 0.0;  ///< stress-free temperature
  std::vector<Node> nodes;
  std::vector<Material> materials;
  std::vector<Element> elements;
  std::optional<GapSettings> gaps;
  std::optional<ContactSettings> contact;  ///< contact surfaces and their pairs (mortar contact)
  std::vector<Constraint> constraints;
  Loads loads;
  std::vector<Step> steps;  ///< empty: one step of one increment with `loads` (no step output at all)
  std::optional<Thermal> thermal;  ///< present: node temperatures come from conduction, not loads
  std::vector<ReactionGroup> reaction_groups;  ///< node sets a constraint names, in the order first named
  SolverOptions solver;
  OutputOptions output;

  [[nodiscard]] std::size_t gap_count() const { return gaps ? gaps->elements.size() : 0; }
};

}  // namespace saasgaps
