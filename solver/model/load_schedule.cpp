#include "solver/model/load_schedule.hpp"

#include <cassert>
#include <cmath>
#include <limits>

namespace saasgaps {

namespace {

constexpr double free_component = std::numeric_limits<double>::quiet_NaN();

void prescribe(std::vector<double>& values, const std::vector<Constraint>& constraints) {
  for (const Constraint& c : constraints) {
    if (c.u_r) values[2 * static_cast<std::size_t>(c.node)] = *c.u_r;
    if (c.u_z) values[2 * static_cast<std::size_t>(c.node) + 1] = *c.u_z;
  }
}

}  // namespace

const Loads& final_loads(const Model& model) {
  const Loads* last = &model.loads;
  for (const Step& step : model.steps) {
    if (step.loads) last = &*step.loads;
  }
  return *last;
}

std::vector<double> final_prescribed(const Model& model) {
  std::vector<double> prescribed(2 * model.nodes.size(), free_component);
  prescribe(prescribed, model.constraints);
  for (const Step& step : model.steps) prescribe(prescribed, step.constraints);
  return prescribed;
}

LoadSchedule::LoadSchedule(const Model& model) : model_(model) {
  std::vector<double> prescribed(2 * model.nodes.size(), free_component);
  prescribe(prescribed, model.constraints);
  const Loads* previous = &model.loads;
  for (const Step& step : model.steps) {
    if (step.loads) previous = &*step.loads;
    end_loads_.push_back(*previous);
    prescribe(prescribed, step.constraints);
    end_prescribed_.push_back(prescribed);
  }
}

StepPosition LoadSchedule::first() const {
  StepPosition p;
  p.step_start.assign(2 * model_.nodes.size(), 0.0);
  return p;
}

bool LoadSchedule::advance(StepPosition& position, std::span<const double> displacement) const {
  assert(stepped());
  position.iterations = 0;
  if (position.increment < model_.steps[static_cast<std::size_t>(position.step)].increments) {
    position.increment += 1;
    return true;
  }
  if (position.step + 1 >= static_cast<int>(model_.steps.size())) return false;
  position.step += 1;
  position.increment = 1;
  position.step_start.assign(displacement.begin(), displacement.end());
  return true;
}

StepPosition LoadSchedule::previous(const StepPosition& position) const {
  assert(position.step > 0 || position.increment > 1);
  StepPosition p = position;
  p.iterations = 0;
  if (p.increment > 1) {
    p.increment -= 1;
  } else {
    // The previous step's last increment solves its end values (lambda = 1): its own start is not read.
    p.step -= 1;
    p.increment = model_.steps[static_cast<std::size_t>(p.step)].increments;
  }
  return p;
}

bool LoadSchedule::holds(const StepPosition& p, std::size_t node_count) const {
  return p.step >= 0 && p.step < static_cast<int>(model_.steps.size()) && p.increment >= 1 &&
         p.increment <= model_.steps[static_cast<std::size_t>(p.step)].increments && p.iterations >= 0 &&
         p.step_start.size() == 2 * node_count;
}

double LoadSchedule::factor(const StepPosition& position) const {
  const int n = model_.steps[static_cast<std::size_t>(position.step)].increments;
  return position.increment == n ? 1.0 : static_cast<double>(position.increment) / n;
}

Model LoadSchedule::increment_model(const StepPosition& position) const {
  const auto k = static_cast<std::size_t>(position.step);
  const double lambda = factor(position);
  const Loads start = k == 0 ? unloaded_loads(model_.nodes.size(), model_.reference_temperature) : end_loads_[k - 1];
  const Loads& end = end_loads_[k];

  Model m = model_;
  m.steps.clear();  // the increment's model is one plain load case
  m.loads = interpolate_loads(start, end, lambda, model_.nodes.size(), model_.reference_temperature);

  m.constraints.clear();
  const std::vector<double>& prescribed = end_prescribed_[k];
  for (std::size_t n = 0; n < model_.nodes.size(); ++n) {
    Constraint c;
    c.node = static_cast<int>(n);
    for (int dir = 0; dir < 2; ++dir) {
      const double value = prescribed[2 * n + dir];
      if (std::isnan(value)) continue;
      (dir == 0 ? c.u_r : c.u_z) = along_path(position.step_start[2 * n + dir], value, lambda);
    }
    if (c.u_r || c.u_z) m.constraints.push_back(c);
  }
  return m;
}

}  // namespace saasgaps
