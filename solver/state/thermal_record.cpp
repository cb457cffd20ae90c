#include "solver/state/thermal_record.hpp"

namespace saasgaps {

bool ThermalRecord::same_numbers(const ThermalRecord& o) const {
  return kind == o.kind && index == o.index && pass == o.pass && iterations == o.iterations && time == o.time &&
         time_steps == o.time_steps && max_change == o.max_change && pass_change == o.pass_change &&
         min_T == o.min_T && max_T == o.max_T;
}

}  // namespace saasgaps
