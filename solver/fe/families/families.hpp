#pragma once
/// The families the program has (element_family.hpp), one file each; element_family.cpp lists
/// them in its table, which is the only place that names them all.

#include <array>

#include "solver/fe/element_family.hpp"

namespace saasgaps {

extern const ElementFamily saas_family;    ///< the report's quadrilateral (saas.cpp)
extern const ElementFamily tri3_family;    ///< the constant-strain triangle (tri3.cpp)
extern const ElementFamily tri6_family;    ///< the quadratic triangle (tri6.cpp)
extern const ElementFamily quad8_family;   ///< the serendipity quadrilateral (quad8.cpp)
extern const ElementFamily quad9_family;   ///< the Lagrange quadrilateral (quad9.cpp)
extern const ElementFamily quad4i_family;  ///< the bilinear quad with incompatible modes (quad4i.cpp)

/// The quadratic quadrilaterals' layout (quad8 takes the first 8 nodes, quad9 all 9): each edge runs
/// corner, mid-side, corner; reference positions (xi, eta) of the corners, the mid-sides and the centre.
inline constexpr std::array<EdgeNodes, 4> quadratic_quad_edges{
    {{{0, 4, 1}, 3}, {{1, 5, 2}, 3}, {{2, 6, 3}, 3}, {{3, 7, 0}, 3}}};
inline constexpr std::array<std::array<double, 2>, 9> quadratic_quad_nodes{
    {{-1.0, -1.0}, {1.0, -1.0}, {1.0, 1.0}, {-1.0, 1.0}, {0.0, -1.0}, {1.0, 0.0}, {0.0, 1.0}, {-1.0, 0.0}, {0.0, 0.0}}};

}  // namespace saasgaps
