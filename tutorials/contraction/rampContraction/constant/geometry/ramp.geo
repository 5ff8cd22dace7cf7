// Ramp contraction (docs/scenes.md scene 7): a channel 60 long and 30 wide, narrowed in the middle to
// a third of its width by a symmetric trapezoid on each wall: 45-degree ramps from the wall at |x| = b
// up to the throat, |z| = h over |x| < c. The throat is as wide as the square contraction's and the
// trapezoids hold as much solid as its blocks (2 x 200), so that both shapes have the published flow
// area 1,400 (16,800 particles at rho 4, 3 thick). gmsh's x-y plane is the box's x-z plane
// (extrudeAxis y in constant/dpdProperties); the fluid is the surface of the group "fluid".
L = 30;  H = 15;  c = 5;  h = 5;  b = 15;
Point(1) = {-L, -H, 0};  Point(2) = {-b, -H, 0};  Point(3) = {-c, -h, 0};  Point(4) = {c, -h, 0};
Point(5) = {b, -H, 0};   Point(6) = {L, -H, 0};   Point(7) = {L, H, 0};    Point(8) = {b, H, 0};
Point(9) = {c, h, 0};    Point(10) = {-c, h, 0};  Point(11) = {-b, H, 0};  Point(12) = {-L, H, 0};
For k In {1:11}
  Line(k) = {k, k + 1};
EndFor
Line(12) = {12, 1};
Curve Loop(1) = {1:12};
Plane Surface(1) = {1};
Physical Surface("fluid") = {1};
