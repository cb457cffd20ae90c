#pragma once
/// The families the program has (element_family.hpp), one file each; element_family.cpp lists
/// them in its table, which is the only place that names them all.

#include "solver/fe/element_family.hpp"

namespace saasgaps {

extern const ElementFamily saas_family;    ///< the report's quadrilateral (saas.cpp)
extern const ElementFamily tri3_family;    ///< the constant-strain triangle (tri3.cpp)
extern const ElementFamily tri6_family;    ///< the quadratic triangle (tri6.cpp)
extern const ElementFamily quad8_family;   ///< the serendipity quadrilateral (quad8.cpp)
extern const ElementFamily quad9_family;   ///< the Lagrange quadrilateral (quad9.cpp)
extern const ElementFamily quad4i_family;  ///< the bilinear quad with incompatible modes (quad4i.cpp)

}  // namespace saasgaps
