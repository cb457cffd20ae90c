#pragma once
/// The loads of a model (model.loads, and each step's loads): their kinds, in one list, and how the
/// load path interpolates them. A new kind of load is a member of Loads, a row of load_kind_names
/// (the key of the model document that gives it), its reader (io/sections) and its branch of
/// interpolate_loads below; assembly reads it where it acts (nodal loads in
/// assembly/stiffness_system.cpp, element loads in assembly/element_data.cpp).

#include <cstddef>
#include <vector>

#include "solver/base/name_table.hpp"

namespace saasgaps {

/// Plane: force on the whole thickness. Axisymmetric: total force on the full ring (2 pi radians).
struct NodalForce {
  int node = 0;
  double f_r = 0.0;
  double f_z = 0.0;
};

/// Uniform traction on edge a-b of a solid element: normal > 0 pushes into the element, shear > 0
/// acts along a -> b (the order the user gave).
struct EdgePressure {
  int element = 0;  ///< index of the solid element that owns the edge
  int node_a = 0;
  int node_b = 0;
  double normal = 0.0;
  double shear = 0.0;
};

/// Body force per unit volume = density * (accel_r, accel_z); omega (rad/time) spins an
/// axisymmetric body about the z axis, adding density * omega^2 * r along r.
struct BodyForce {
  double accel_r = 0.0;
  double accel_z = 0.0;
  double omega = 0.0;
};

struct Loads {
  std::vector<NodalForce> nodal_forces;
  std::vector<EdgePressure> pressures;
  std::vector<double> node_temperature;  ///< one per node (the default where none is given)
  BodyForce body_force;
};

/// The kinds of load, by the key of a `loads` object that gives each.
enum class LoadKind { nodal_forces, pressures, temperatures, body_force };
inline constexpr NameTable<LoadKind, 4> load_kind_names{{{{LoadKind::nodal_forces, "nodal_forces"},
                                                          {LoadKind::pressures, "pressures"},
                                                          {LoadKind::temperatures, "temperatures"},
                                                          {LoadKind::body_force, "body_force"}}}};

/// (1 - lambda) a + lambda b, and b itself at lambda = 1 (a step's last increment solves its own
/// values to the last digit): every value the load path interpolates linearly.
inline double along_path(double a, double b, double lambda) {
  return lambda == 1.0 ? b : (1.0 - lambda) * a + lambda * b;
}

/// No force, every node at the reference (stress-free) temperature.
Loads unloaded_loads(std::size_t node_count, double reference_temperature);

/// The loads a fraction lambda of the way from `start` to `end` (0 < lambda <= 1): forces and
/// tractions side by side, scaled by 1 - lambda and lambda (the system adds them up; none of the
/// start's at lambda = 1); temperatures and accelerations linear in lambda; the spin so that omega^2
/// (the load it gives) is linear. At lambda = 1 every value is the end's own, to the last digit.
/// A node without a temperature in `start` or `end` is at `reference_temperature`.
Loads interpolate_loads(const Loads& start, const Loads& end, double lambda, std::size_t node_count,
                        double reference_temperature);

}  // namespace saasgaps
