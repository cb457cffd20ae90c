// The press fit of press-fit-interference.study.json: the radial interference d is a parameter
// (DefineConstant: the study sets it through the assembly's /mesh_parameters/d; alone, 1.5e-4 in).
// A press fit of two rings of different materials (axisymmetric slice, height h), each meshed on its
// own without Transfinite: the interface carries 9 nodes on the shaft and 13 on the hub, so the
// meshes do not match. The shaft's outer radius b + d/2 exceeds the hub's bore b - d/2 by the
// interference d. ring-press-fit.assembly.json pairs the two faces as contact surfaces.
DefineConstant[ d = 1.5e-4 ];
a1 = 1.0; b = 1.5; b2 = 2.2; h = 0.2;
lc_shaft = 0.025; lc_hub = 0.0167;

Point(1) = {a1, 0, 0, lc_shaft}; Point(2) = {b + d/2, 0, 0, lc_shaft};
Point(3) = {b + d/2, h, 0, lc_shaft}; Point(4) = {a1, h, 0, lc_shaft};
Point(5) = {b - d/2, 0, 0, lc_hub}; Point(6) = {b2, 0, 0, lc_hub};
Point(7) = {b2, h, 0, lc_hub}; Point(8) = {b - d/2, h, 0, lc_hub};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Line(5) = {5, 6}; Line(6) = {6, 7}; Line(7) = {7, 8}; Line(8) = {8, 5};
Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};
Curve Loop(2) = {5, 6, 7, 8}; Plane Surface(2) = {2};
Recombine Surface{1, 2};

Physical Surface("shaft") = {1};
Physical Surface("hub") = {2};
Physical Curve("shaft_outside") = {2};
Physical Curve("hub_bore") = {8};
Physical Curve("ends") = {1, 3, 5, 7};
