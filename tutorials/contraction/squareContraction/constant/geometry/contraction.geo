// Square contraction (docs/scenes.md scene 7): a channel 60 long and 30 wide, narrowed in the middle
// by a square step to 10 over a length of 20: two blocks 20 x 10, 400 of solid, so that the flow area
// is the published 1,400 (16,800 particles at rho 4, 3 thick), the ramp contraction's. gmsh's x-y
// plane is the box's x-z plane (extrudeAxis y in constant/dpdProperties); the fluid is the surface of
// the group "fluid".
L = 30;  H = 15;  c = 10;  h = 5;
Point(1) = {-L, -H, 0};  Point(2) = {-c, -H, 0};  Point(3) = {-c, -h, 0};  Point(4) = {c, -h, 0};
Point(5) = {c, -H, 0};   Point(6) = {L, -H, 0};   Point(7) = {L, H, 0};    Point(8) = {c, H, 0};
Point(9) = {c, h, 0};    Point(10) = {-c, h, 0};  Point(11) = {-c, H, 0};  Point(12) = {-L, H, 0};
For k In {1:11}
  Line(k) = {k, k + 1};
EndFor
Line(12) = {12, 1};
Curve Loop(1) = {1:12};
Plane Surface(1) = {1};
Physical Surface("fluid") = {1};
