// The Poiseuille channel (docs/scenes.md scene 1) as a gmsh surface: fluid 10 long (x) and 10 wide (z): the test channel,
// gmsh's x-y plane being the box's x-z plane (extrudeAxis y in constant/dpdProperties).
L = 5;  H = 5;
Point(1) = {-L, -H, 0};  Point(2) = {L, -H, 0};  Point(3) = {L, H, 0};  Point(4) = {-L, H, 0};
Line(1) = {1, 2};  Line(2) = {2, 3};  Line(3) = {3, 4};  Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Physical Surface("fluid") = {1};
