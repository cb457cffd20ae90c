// Shrink fit by heating: a quarter of two concentric steel rings in plane strain, the inner one
// (r 1.0 .. 1.5 in) to be heated into the outer one (r 1.502 .. 2.2 in) across a 0.002 in gap.
// The same mesh as ../ring-shrink-fit-plane-strain.json (8 radial x 24 hoop quadrilaterals per
// ring): transfinite curves put the nodes of the two faces of the gap at the same angles, so each
// node faces one node across the gap. Drawn in the plane z = 0 (Gmsh x is r, y is z).
a1 = 1.0; b1 = 1.5; delta = 0.002; a2 = b1 + delta; b2 = 2.2;
radial = 8; hoop = 24;

Point(1) = {0, 0, 0};
Point(2) = {a1, 0, 0}; Point(3) = {b1, 0, 0}; Point(4) = {0, b1, 0}; Point(5) = {0, a1, 0};
Point(6) = {a2, 0, 0}; Point(7) = {b2, 0, 0}; Point(8) = {0, b2, 0}; Point(9) = {0, a2, 0};

// Inner ring: x axis, outside arc, y axis, bore arc.
Line(1) = {2, 3}; Circle(2) = {3, 1, 4}; Line(3) = {4, 5}; Circle(4) = {5, 1, 2};
// Outer ring: x axis, outside arc, y axis, inside arc.
Line(5) = {6, 7}; Circle(6) = {7, 1, 8}; Line(7) = {8, 9}; Circle(8) = {9, 1, 6};

Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};
Curve Loop(2) = {5, 6, 7, 8}; Plane Surface(2) = {2};

Transfinite Curve{1, 3, 5, 7} = radial + 1;
Transfinite Curve{2, 4, 6, 8} = hoop + 1;
Transfinite Surface{1, 2};
Recombine Surface{1, 2};

Physical Surface("inner_ring") = {1};
Physical Surface("outer_ring") = {2};
Physical Curve("x_axis") = {1, 5};
Physical Curve("y_axis") = {3, 7};
Physical Curve("inner_ring_outside") = {2};
Physical Curve("outer_ring_inside") = {8};
