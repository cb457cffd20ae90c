#pragma once
/// The load path of a run (model.steps): which increments there are, and the model each one
/// solves. Without steps a run is one step of one increment with the model's own loads and
/// constraints, and the analysis uses the model itself (nothing here is consulted).
///
/// With steps, step k (0-based) ends at
///   loads_k       = steps[k].loads, else loads_{k-1}; loads_{-1} = the model's loads for k = 0 only
///                   when step 1 has none (then it takes the top-level loads);
///   prescribed_k  = the top-level constraints, overlaid by the constraints of steps 0..k in order
///                   (a component keeps its last prescribed value until a step names it again),
/// and increment i of n_k solves at the load factor lambda = i / n_k
///   f(lambda) = (1 - lambda) f_start + lambda f_end   (forces, pressures, accelerations, temperatures;
///                                                      omega^2, since the spin load is density omega^2 r)
///   u_p(lambda) = (1 - lambda) u_start + lambda u_end (prescribed components)
/// where the start is the end of step k-1; step 1 starts unloaded (no force, every node at the
/// reference temperature, u = 0). u_start of a prescribed component is the displacement the run
/// reached at the end of the previous step (its prescribed value there, or the free displacement of
/// a component a step prescribes for the first time). At lambda = 1 every value is the end value
/// exactly, so the last increment of a step solves the step's own loads.

#include <span>
#include <vector>

#include "solver/model/model.hpp"

namespace saasgaps {

/// Where a stepped run stands: the increment of iteration K and what it needs to rebuild its loads.
struct StepPosition {
  int step = 0;        ///< 0-based index into Model::steps
  int increment = 1;   ///< 1-based within the step
  int iterations = 0;  ///< iterations of this increment finished
  std::vector<double> step_start;  ///< (u_r, u_z) per node at the end of the previous step (zeros for step 1)

  friend bool operator==(const StepPosition&, const StepPosition&) = default;
};

/// The loads at the end of the run's load path: the last step's (with steps), else the model's.
const Loads& final_loads(const Model& model);

/// The prescribed displacement components at the end of the run's load path (prescribed_k of the
/// last step, the model's constraints without steps): 2 per node, (u_r, u_z); NaN where free.
std::vector<double> final_prescribed(const Model& model);

class LoadSchedule {
 public:
  explicit LoadSchedule(const Model& model);

  [[nodiscard]] bool stepped() const { return !model_.steps.empty(); }

  /// The position of a run that has not started: step 1, increment 1, no iteration yet.
  [[nodiscard]] StepPosition first() const;

  /// Moves `position` to the next increment (a new step takes `displacement` as its start); false
  /// when it was the last increment of the last step.
  bool advance(StepPosition& position, std::span<const double> displacement) const;

  /// The increment before `position` (not the first of the run), whose model increment_model gives:
  /// the same step's previous one, or the last of the previous step.
  [[nodiscard]] StepPosition previous(const StepPosition& position) const;

  /// True when a saved position names an increment of this model (node_count nodes).
  [[nodiscard]] bool holds(const StepPosition& position, std::size_t node_count) const;

  /// The load factor lambda = increment / increments of a position.
  [[nodiscard]] double factor(const StepPosition& position) const;

  /// The model that increment `position` solves: the model with the increment's loads and
  /// constraints (everything else shared by value).
  [[nodiscard]] Model increment_model(const StepPosition& position) const;

 private:
  const Model& model_;
  std::vector<Loads> end_loads_;  // per step: the loads at its end
  /// Per step: the prescribed value of each component at its end (2 per node, NaN = free).
  std::vector<std::vector<double>> end_prescribed_;
};

}  // namespace saasgaps
