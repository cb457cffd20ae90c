#pragma once
/// The element families a model names (elements[].type, elements[].integration), as data: what
/// each family is lives in fe/element_family.hpp.

#include <cstdint>

#include "solver/base/name_table.hpp"

namespace saasgaps {

enum class ElementType : std::uint8_t { saas, tri3, tri6, quad8, quad9, quad4i };
inline constexpr NameTable<ElementType, 6> element_type_names{{{{ElementType::saas, "saas"},
                                                                {ElementType::tri3, "tri3"},
                                                                {ElementType::tri6, "tri6"},
                                                                {ElementType::quad8, "quad8"},
                                                                {ElementType::quad9, "quad9"},
                                                                {ElementType::quad4i, "quad4i"}}}};

/// The quadrilaterals' rule: full (3 x 3 for quad8 and quad9) or reduced (2 x 2).
enum class Integration : std::uint8_t { full, reduced };
inline constexpr NameTable<Integration, 2> integration_names{
    {{{Integration::full, "full"}, {Integration::reduced, "reduced"}}}};

inline constexpr int max_element_nodes = 9;

}  // namespace saasgaps
