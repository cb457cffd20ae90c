#include "solver/model/loads.hpp"

#include <cmath>

namespace saasgaps {

namespace {

double temperature(const Loads& loads, std::size_t node, double reference_temperature) {
  // Loads built in code may leave the temperatures out: the stress-free one (as the reader's default).
  return node < loads.node_temperature.size() ? loads.node_temperature[node] : reference_temperature;
}

}  // namespace

Loads unloaded_loads(std::size_t node_count, double reference_temperature) {
  Loads l;
  l.node_temperature.assign(node_count, reference_temperature);
  return l;
}

Loads interpolate_loads(const Loads& start, const Loads& end, double lambda, std::size_t node_count,
                        double reference_temperature) {
  Loads l;
  const auto add_scaled = [&l](const Loads& from, double weight) {
    if (weight == 0.0) return;
    for (NodalForce f : from.nodal_forces) {
      f.f_r *= weight;
      f.f_z *= weight;
      l.nodal_forces.push_back(f);
    }
    for (EdgePressure p : from.pressures) {
      p.normal *= weight;
      p.shear *= weight;
      l.pressures.push_back(p);
    }
  };
  add_scaled(start, lambda == 1.0 ? 0.0 : 1.0 - lambda);
  add_scaled(end, lambda);
  l.node_temperature.resize(node_count);
  for (std::size_t n = 0; n < node_count; ++n) {
    l.node_temperature[n] = along_path(temperature(start, n, reference_temperature),
                                    temperature(end, n, reference_temperature), lambda);
  }
  l.body_force.accel_r = along_path(start.body_force.accel_r, end.body_force.accel_r, lambda);
  l.body_force.accel_z = along_path(start.body_force.accel_z, end.body_force.accel_z, lambda);
  l.body_force.omega = lambda == 1.0 ? end.body_force.omega
                                     : std::sqrt(along_path(start.body_force.omega * start.body_force.omega,
                                                         end.body_force.omega * end.body_force.omega, lambda));
  return l;
}

}  // namespace saasgaps
