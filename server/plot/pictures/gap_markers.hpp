#pragma once
/// Gap elements on a contour plot, marked by state so that contact can be read off the picture:
/// closed dark grey, overclosed black, partial light grey, open white with a dashed outline.
///
/// Real gaps are far thinner than a pixel on a plot of the whole body (0.009 in on a 9 in beam),
/// and once displacements are magnified a closed gap turns inside out (its faces move s times the
/// closure apart, the other way). So a gap is drawn as a strip of fixed width: along the face of
/// the body it belongs to, outwards, when a body lies on one side only (a beam on a rigid wall,
/// whose wall nodes belong to no solid element), or centred on the middle of the gap when bodies
/// lie on both sides. A gap that is drawn wider than the strip and the right way round (an open gap
/// on a magnified deformed mesh) is drawn as it is.

#include <vector>

#include "plot/draw/canvas.hpp"
#include "plot/result/result_mesh.hpp"

namespace saasgaps::plot {

/// Draws every gap element. at: node positions as drawn (deformed or not), undeformed: the same
/// nodes undeformed (which side of a gap is which), both in px; strip: the marker width, px.
void draw_gap_markers(const Canvas& canvas, const ResultMesh& mesh, const std::vector<Point>& at,
                      const std::vector<Point>& undeformed, double strip);

/// The legend: a swatch per state with the number of gaps in it, from top_left down; returns its height.
double draw_gap_legend(const Canvas& canvas, const ResultMesh& mesh, Point top_left);

/// The legend's size before drawing it, px.
double gap_legend_width(const Canvas& canvas);
double gap_legend_height(const Canvas& canvas);

}  // namespace saasgaps::plot
