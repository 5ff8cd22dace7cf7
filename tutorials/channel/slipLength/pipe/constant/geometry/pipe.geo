// A pipe of radius 4 along y (gmsh's x-y plane is the box's x-z plane; extrudeAxis y in
// constant/dpdProperties): the fluid is the disc, the solid the rest of the 10 x 10 box. A fine
// characteristic length makes the polygon of the disc's edge a circle to 1e-4.
R = 4;
lc = 0.05;
Point(1) = {0, 0, 0, lc};
Point(2) = {R, 0, 0, lc};  Point(3) = {0, R, 0, lc};  Point(4) = {-R, 0, 0, lc};  Point(5) = {0, -R, 0, lc};
Circle(1) = {2, 1, 3};  Circle(2) = {3, 1, 4};  Circle(3) = {4, 1, 5};  Circle(4) = {5, 1, 2};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Physical Surface("fluid") = {1};
