#pragma once
/// Where superconvergent patch recovery (Zienkiewicz and Zhu 1992) samples an element's stresses:
/// the points where the element's stress is most accurate, and the stress there as the kernel
/// computed it at its material points (thermal, initial and plastic parts included: the total stress
/// of the point). Only the element's geometry and its material points' states are read: sampling is
/// cheap enough to repeat for each patch that holds the element, so no model-sized array of samples
/// is kept (patch_recovery.hpp).
///
///   saas    its centre (the mean of the corners) and its one material point's stress there, the
///           volume-weighted mean of its four constant-strain triangles: the superconvergent point of
///           a four-node quadrilateral, which ZZ sample at its centre
///   tri3    its centroid (its constant stress)
///   tri6    the 3-point rule of degree 2, (1/6, 1/6), (2/3, 1/6), (1/6, 2/3): its material points
///   quad8,  the 2 x 2 Gauss points xi, eta = +-1/sqrt(3); with full (3 x 3) integration the values
///   quad9   there are the biquadratic through the nine material points' stresses, evaluated at the
///           2 x 2 points (exact when the stress is biquadratic in xi, eta); reduced: the material points
///   quad4i  its 2 x 2 material points. The centre is the classical superconvergent point of a
///           bilinear quad, but the incompatible modes make the element's stress exact for a linear
///           variation (pure bending), so the 2 x 2 points are as good for a linear fit and give four
///           times the samples: a patch at a boundary corner (one element) can still fit its plane.
///
/// Coordinates are the points' (r, z); values Voigt (rr, zz, rz, th).

#include <array>
#include <span>

#include "solver/fe/element_kernel.hpp"

namespace saasgaps {

inline constexpr int max_sampling_points = 4;

struct SamplingPoint {
  Vec2 x = Vec2::Zero();
  Vec4 value = Vec4::Zero();
};

struct ElementSamples {
  std::array<SamplingPoint, max_sampling_points> point{};
  int count = 0;
};

/// The sampling points of an element (its geometry: solid_element_geometry's, no law needed) whose
/// kernel states at its material points are `point_states` (its family's point count of them).
ElementSamples stress_samples(const ElementData& geometry, std::span<const ElementState> point_states);

/// The 2 x 2 Gauss points' values from a 3 x 3 rule's (both xi fastest): value(q) = sum_p W[q][p] value(p).
const std::array<std::array<double, 9>, 4>& gauss3_to_gauss2();

}  // namespace saasgaps
