#pragma once
/// Superconvergent patch recovery (Zienkiewicz and Zhu 1992, "The superconvergent patch recovery
/// and a posteriori error estimates", IJNME 33): a continuous nodal field from values sampled at
/// the elements' superconvergent points (sampling_points.hpp).
///
/// Patches are taken per material: the patch of corner node n in material m is the elements of
/// material m that have n as a corner. On each patch a polynomial p(x) = P(x) a with the monomials
/// of the patch's shape functions is fitted by least squares to the sampled values, in coordinates
/// centred on n and scaled by the patch's size (minimise sum_points |P(x_k) a - value_k|^2), as
/// Zienkiewicz and Zhu prescribe:
///   saas, tri3, quad4i:  P = [1, x, y];
///   tri6:                P = [1, x, y, x^2, x y, y^2];
///   quad8:               the same and x^2 y, x y^2;   quad9: and x^2 y^2
/// (a patch of several families takes the polynomial they share: linear with a linear element in
/// it, else the complete quadratic, or quad8's with quad9). A patch with fewer points than terms, or
/// whose points do not determine the terms (rank below the count, relative pivot 1e-10), is fitted
/// with the next smaller polynomial (quad9's, quad8's, quadratic, linear, constant: the mean).
///
/// Which patch gives which node its value (the method's rules):
///  - a corner interior to its material region (every edge of the patch at n is shared by two of
///    its elements) takes its own patch's p(x_n);
///  - every other node of a patch whose centre is interior (the region's boundary corners, mid-side
///    and centre nodes) takes the mean of p(x_node) over the interior patches it belongs to: boundary
///    nodes from interior patches, mid-side nodes from the patches of their edge's corners;
///  - a node that no interior patch reaches (a region one element thick, a lone element) takes the
///    mean over the boundary patches it belongs to, its own included.
///
/// Symmetry lines (symmetry_lines.hpp) refine those rules at the region's boundary, where values
/// are extrapolated: the patch of a corner on a line is completed by the mirror images of its
/// points, and its edges along the line count as shared, so such a corner is interior when its other
/// edges are; a node on a line that takes a mean counts each patch whose corner is off its line
/// twice, as itself and as its mirror image (the mesh mirrored).
///
/// Each side of a material interface is recovered on its own: a node where materials meet holds
/// one value per material (a "side"). One pass over the patches, each fitted once, in parallel,
/// then one over the sides that are not interior corners: O(nodes) time and memory, the fits kept
/// only of the patches such sides read.

#include <functional>
#include <span>
#include <vector>

#include "solver/model/model.hpp"
#include "solver/state/recovered_field.hpp"
#include "solver/recovery/sampling_points.hpp"
#include "solver/recovery/symmetry_lines.hpp"

namespace saasgaps {

/// Element e's samples, asked for by every patch that holds the element (up to four times for a
/// quad: once per corner), from any thread: sampling is repeated rather than kept in a model-sized
/// array (200 bytes an element, 100 MB at 10^6 unknowns of the report's element, whose fresh pages
/// cost more than the sampling on a virtual machine).
using ElementSampler = std::function<ElementSamples(std::size_t e)>;

/// Recovers a field from the samples of every solid element. With symmetry lines
/// (symmetry_lines.hpp), patches at a line are completed by their mirror images.
RecoveredField recover_field(const Model& model, const ElementSampler& sample, const SymmetryLines* symmetry = nullptr);

/// The same from samples computed beforehand, one per Model::elements entry.
RecoveredField recover_field(const Model& model, std::span<const ElementSamples> samples,
                             const SymmetryLines* symmetry = nullptr);

/// The recovered field at element e's nodes (its material's side at each), in the element's node order.
std::array<Vec4, max_element_nodes> element_nodal_values(const Model& model, const RecoveredField& field, std::size_t e);

}  // namespace saasgaps
