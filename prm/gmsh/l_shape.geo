// An L-shaped body: [0, 2] x [0, 2] without (1, 2] x (1, 2], its
// re-entrant corner at (1, 1). Three unit squares, one quadrilateral each
// (the runs refine them).
//
// Regenerate the committed mesh (Gmsh 4.8, Debian package 'gmsh'; MSH 4.1):
//   gmsh -2 prm/gmsh/l_shape.geo -o prm/gmsh/l_shape.msh
//
// Physical tags (the groups are named) become deal.II boundary ids:
//   1 the left side x = 0                    -> clamped boundary ids
//   2 the bottom y = 0                       -> contact boundary ids
//   3 the top of the left arm, y = 2         -> traction boundary ids
//   4 every other edge                       -> free (no condition)
Point(1) = {0, 0, 0};
Point(2) = {1, 0, 0};
Point(3) = {2, 0, 0};
Point(4) = {2, 1, 0};
Point(5) = {1, 1, 0};
Point(6) = {1, 2, 0};
Point(7) = {0, 2, 0};
Point(8) = {0, 1, 0};

Line(1) = {1, 2};   // bottom, left half
Line(2) = {2, 3};   // bottom, right half
Line(3) = {3, 4};   // right side
Line(4) = {4, 5};   // top of the right arm
Line(5) = {5, 6};   // inner side of the left arm
Line(6) = {6, 7};   // top of the left arm
Line(7) = {7, 8};   // left side, upper half
Line(8) = {8, 1};   // left side, lower half
Line(9) = {2, 5};   // interior
Line(10) = {5, 8};  // interior

Curve Loop(1) = {1, 9, 10, 8};
Plane Surface(1) = {1};
Curve Loop(2) = {2, 3, 4, -9};
Plane Surface(2) = {2};
Curve Loop(3) = {-10, 5, 6, 7};
Plane Surface(3) = {3};
Transfinite Curve{1:10} = 2;
Transfinite Surface{1, 2, 3};
Recombine Surface{1, 2, 3};

Physical Curve("clamped", 1) = {7, 8};
Physical Curve("contact", 2) = {1, 2};
Physical Curve("load", 3) = {6};
Physical Curve("free", 4) = {3, 4, 5};
Physical Surface("body", 10) = {1, 2, 3};
