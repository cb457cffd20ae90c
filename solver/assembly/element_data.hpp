#pragma once
/// Gathers one element's kernel input from the model: coordinates, temperatures, body forces.

#include <span>

#include "solver/fe/element_kernel.hpp"
#include "solver/model/model.hpp"

namespace saasgaps {

/// Mean temperature of an element's nodes: the temperature its properties are read at.
double element_temperature(const Model& model, const std::array<int, 4>& nodes, int node_count);

/// Kernel input of solid element e with its constitutive law.
ElementData solid_element_data(const Model& model, std::size_t e, const Constitutive& law);

/// Kernel input of gap element g: no thermal strain and no body force (its properties are fictitious).
ElementData gap_element_data(const Model& model, std::size_t g, const Constitutive& law);

/// The element's nodal displacements (u_r, u_z per corner; zero past node_count) from the full vector
/// of (u_r, u_z) per node.
Vec8 element_displacements(std::span<const double> u, const std::array<int, 4>& nodes, int node_count);

/// Corner coordinates of an element by node indices.
std::array<Vec2, 4> corner_coordinates(const Model& model, const std::array<int, 4>& nodes, int node_count);

}  // namespace saasgaps
