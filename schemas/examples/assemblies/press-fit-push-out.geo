// Press fit and push-out of two steel cylinders (axisymmetric, mm): an inner cylinder ID 20 /
// OD 40.005 inside an outer one ID 40 / OD 60, both 19 long. The inner's outside (r = 20.0025)
// overlaps the outer's bore (r = 20) by the radial interference 0.0025; each body is meshed on its
// own (quadrilaterals, coarse: the answer is a resultant). press-fit-push-out.assembly.json pairs
// the two faces as contact surfaces with friction and pushes the inner cylinder out.
// d is a parameter (DefineConstant): studies/press-fit-push-out.study.json sets it through the
// assembly's /mesh_parameters/d; alone, or from the assembly without mesh_parameters, 0.0025.
DefineConstant[ d = 0.0025 ];
a = 10.0; b = 20.0; c = 30.0; L = 19.0;
lc = 2.0;

Point(1) = {a, 0, 0, lc}; Point(2) = {b + d, 0, 0, lc};
Point(3) = {b + d, L, 0, lc}; Point(4) = {a, L, 0, lc};
Point(5) = {b, 0, 0, lc}; Point(6) = {c, 0, 0, lc};
Point(7) = {c, L, 0, lc}; Point(8) = {b, L, 0, lc};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Line(5) = {5, 6}; Line(6) = {6, 7}; Line(7) = {7, 8}; Line(8) = {8, 5};
Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};
Curve Loop(2) = {5, 6, 7, 8}; Plane Surface(2) = {2};
Recombine Surface{1, 2};

Physical Surface("inner") = {1};
Physical Surface("outer") = {2};
Physical Curve("inner_outside") = {2};
Physical Curve("outer_bore") = {8};
Physical Curve("pushed") = {1};       // the inner cylinder's bottom face, pushed along +z
Physical Curve("outer_support") = {7}; // the outer cylinder's top face, held in z
