/// The `steps` section: load steps, each with a name, its increments, and optionally the loads and
/// constraints at its end (solver/load_schedule.hpp says how they are reached).
#include "io/json/value_quote.hpp"
#include "io/sections/run_limits.hpp"
#include "io/sections/section_reader.hpp"

namespace saasgaps::io {

/// Optional: a non-empty array of {name, increments?, loads?, constraints?}; names unique and
/// non-empty; 1 <= increments <= max_increments_limit; loads as the top-level loads; constraints as
/// the top-level constraints (each component once per step; the array may be empty).
void SectionReader::read_steps(const Obj& root) {
  const json* list = array_field(root, "steps", 1);
  if (list == nullptr) return;
  std::unordered_map<std::string, std::string> named;  // name -> pointer of the step that has it
  for (std::size_t i = 0; i < list->size(); ++i) {
    const std::string pointer = pointer_append(root.at("steps"), i);
    auto step = read_step((*list)[i], pointer);
    if (!step) continue;
    const auto [first, fresh] = named.emplace(step->name, pointer);
    if (!fresh) {
      report(pointer_append(pointer, "name"), "step name " + quote_string(step->name) + " is already used at " +
                                                  first->second + "; give each step its own name");
      continue;
    }
    model_.steps.push_back(std::move(*step));
  }
}

std::optional<Step> SectionReader::read_step(const json& item, const std::string& pointer) {
  if (!object(item, pointer, {"name"}, {"increments", "loads", "constraints"})) return std::nullopt;
  const Obj o{&item, pointer};
  Step step;
  bool valid = true;
  if (const auto name = string_field(o, "name")) {
    if (name->empty()) {
      report(o.at("name"), "name must be a non-empty step name, got \"\"");
      valid = false;
    }
    step.name = *name;
  } else {
    valid = false;
  }
  if (o.find("increments") != nullptr) {
    const auto increments = integer_field(o, "increments", 1, max_increments_limit);
    valid = valid && increments.has_value();
    step.increments = increments.value_or(1);
  }
  if (const json* v = o.find("loads")) {
    if (object(*v, o.at("loads"), {}, load_kind_names.names())) {
      // The loads at the step's end replace the previous ones whole: what they omit is absent
      // (temperatures: the stress-free one), as in the top-level loads.
      Loads& loads = step.loads.emplace();
      loads.node_temperature.assign(model_.nodes.size(), model_.reference_temperature);
      read_loads_object(Obj{v, o.at("loads")}, loads);
    } else {
      valid = false;
    }
  }
  if (const json* constraints = array_field(o, "constraints", 0)) {
    PrescribedAt seen;
    for (std::size_t i = 0; i < constraints->size(); ++i) {
      for (const Constraint& c : read_constraint_item((*constraints)[i], pointer_append(o.at("constraints"), i), seen)) {
        step.constraints.push_back(c);
      }
    }
  }
  if (!valid) return std::nullopt;
  return step;
}

}  // namespace saasgaps::io
