// The Poiseuille channel (docs/scenes.md scene 1) as a gmsh surface: fluid 60 long (x) and 40 wide (z),
// gmsh's x-y plane being the box's x-z plane (extrudeAxis y in constant/dpdProperties).
L = 30;  H = 20;
Point(1) = {-L, -H, 0};  Point(2) = {L, -H, 0};  Point(3) = {L, H, 0};  Point(4) = {-L, H, 0};
Line(1) = {1, 2};  Line(2) = {2, 3};  Line(3) = {3, 4};  Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Physical Surface("fluid") = {1};
