#pragma once
/// Projections between the two sides of a pair along side A's normal field (docs/contact-surfaces.md,
/// section 2, "Normal field and projection"). On a segment x(xi) = (1 - xi) x_1 + xi x_2 of A with
/// nodal normals n_1, n_2 a point looks across along n(xi) = normalize((1 - xi) n_1 + xi n_2); B's
/// nodes are projected back onto A's segments along the same field (which cuts them into the pieces
/// that the overlap search pairs), a point of A onto B's chord and a node of A onto B's smooth curve.

#include <cstddef>
#include <optional>
#include <span>
#include <utility>

#include "solver/base/voigt.hpp"
#include "solver/mortar/surface_geometry.hpp"

namespace saasgaps {

/// Pieces shorter than this (in a segment's parameter) are round-off slivers where nodes project onto
/// nodes.
inline constexpr double parameter_round_off = 1.0e-12;

/// The normal field of a segment of A at xi: n(xi) = normalize((1 - xi) n1 + xi n2) (unit).
Vec2 normal_at(const Vec2& n1, const Vec2& n2, double xi);

/// The segment parameter xi at which the line from x(xi) = x1 + xi (x2 - x1) along the normal field
/// n(xi) = n1 + xi (n2 - n1) passes through y:  (x(xi) - y) x n(xi) = 0, a quadratic
/// c2 xi^2 + c1 xi + c0 = 0. Of its real roots, the one nearest [0, 1] (the other, on a nearly
/// straight side, lies where the normals of the two ends would cross, far outside).
std::optional<double> project_onto_segment(const Vec2& x1, const Vec2& x2, const Vec2& n1, const Vec2& n2,
                                           const Vec2& y);

/// The same on half h of a 3-node edge's curve X (surface_geometry.hpp): the half's parameter xi at
/// which the line from X((h + xi) / 2) along n(xi) = (1 - xi) n1 + xi n2 passes through y (a cubic:
/// Newton from `start`, the chord's root).
double project_onto_curve(const QuadraticEdge& curve, int h, const Vec2& n1, const Vec2& n2, const Vec2& y,
                          double start);

/// Where the line x + t n meets half h of a 3-node edge's curve: (its parameter eta, t), Newton from
/// `start` (the chord's eta).
std::pair<double, double> meet_curve(const Vec2& x, const Vec2& n, const QuadraticEdge& curve, int h, double start);

/// Where the line x + t n meets the line b1 + eta (b2 - b1): (eta, t), or nothing when parallel.
std::optional<std::pair<double, double>> meet(const Vec2& x, const Vec2& n, const Vec2& b1, const Vec2& b2);

/// The distance t along the unit direction n from x to the nearest of `near`'s segments of `surface`'s
/// smooth curve that face it (segment normal against n): x + t n on the curve, t < 0 behind x; nothing
/// when the line meets none of them.
std::optional<double> distance_to_curve(const SurfaceGeometry& surface, const Vec2& x, const Vec2& n,
                                        std::span<const std::size_t> near);

}  // namespace saasgaps
