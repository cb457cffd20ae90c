// NAFEMS LE1, the elliptic membrane: a quarter of the plate between the ellipses (x/2)^2 + y^2 = 1
// and (x/3.25)^2 + (y/2.75)^2 = 1, in the plane z = 0 (Gmsh x is r, y is z). An unstructured mesh of
// quadrilaterals (triangles recombined in pairs) with one size, so that the adaptive loop (le1-adapt.assembly.json)
// decides where to refine. The target: sigma_yy = 92.7 MPa at D = (2, 0).
lc = 0.25;
Point(1) = {0, 0, 0};
Point(2) = {2, 0, 0, lc};     // D
Point(3) = {3.25, 0, 0, lc};  // C
Point(4) = {0, 2.75, 0, lc};  // B
Point(5) = {0, 1, 0, lc};     // A

Line(1) = {2, 3};            // y = 0
Ellipse(2) = {3, 1, 3, 4};   // outer edge, C to B
Line(3) = {4, 5};            // x = 0
Ellipse(4) = {5, 1, 2, 2};   // inner edge, A to D

Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Recombine Surface{1};

Physical Surface("plate") = {1};
Physical Curve("x_axis") = {1};
Physical Curve("y_axis") = {3};
Physical Curve("outer") = {2};
Physical Curve("inner") = {4};
Physical Point("D") = {2};
