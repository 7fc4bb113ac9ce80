// Example D (doc/examples.md): an arch on two pillars, 2D. The upper half
// (y >= 2) of the annulus centred at (2.5, 2) with radii 1.5 and 2.5,
// standing on the pillars [0, 1] x [0, 2] and [4, 5] x [0, 2]; nothing
// under the arch. Triangles of size 0.05 at the base, growing by 0.05 per
// unit of height (h = 0.05 + 0.05 y).
//
// Regenerate the committed mesh (Gmsh 4.8, Debian package 'gmsh'; MSH 4.1):
//   gmsh -2 prm/gmsh/example_d_arch_pillars.geo -o prm/gmsh/example_d_arch_pillars.msh
//
// Physical tags (the groups are named) become deal.II boundary ids:
//   1 the left pillar's base [0, 1] x {0}    -> clamped boundary ids
//   2 the right pillar's base [4, 5] x {0}   -> contact boundary ids
//   3 the outer arc (radius 2.5)             -> traction boundary ids
//   4 every other edge                       -> free (no condition)
h = 0.05;

Point(1) = {0, 0, 0, h};
Point(2) = {1, 0, 0, h};
Point(3) = {1, 2, 0, h};
Point(4) = {2.5, 3.5, 0, h};   // top of the inner arc
Point(5) = {4, 2, 0, h};
Point(6) = {4, 0, 0, h};
Point(7) = {5, 0, 0, h};
Point(8) = {5, 2, 0, h};
Point(9) = {2.5, 4.5, 0, h};   // top of the outer arc
Point(10) = {0, 2, 0, h};
Point(11) = {2.5, 2, 0, h};    // centre of the arcs

Line(1) = {1, 2};          // left base
Line(2) = {2, 3};          // left pillar, inner side
Circle(3) = {3, 11, 4};    // inner arc, left half
Circle(4) = {4, 11, 5};    // inner arc, right half
Line(5) = {5, 6};          // right pillar, inner side
Line(6) = {6, 7};          // right base
Line(7) = {7, 8};          // right pillar, outer side
Circle(8) = {8, 11, 9};    // outer arc, right half
Circle(9) = {9, 11, 10};   // outer arc, left half
Line(10) = {10, 1};        // left pillar, outer side

Curve Loop(1) = {1, 2, 3, 4, 5, 6, 7, 8, 9, 10};
Plane Surface(1) = {1};

Field[1] = MathEval;
Field[1].F = "0.05 + 0.05*y";
Background Field = 1;
Mesh.MeshSizeExtendFromBoundary = 0;
Mesh.MeshSizeFromPoints = 0;
Mesh.MeshSizeFromCurvature = 0;

Physical Curve("clamped", 1) = {1};
Physical Curve("contact", 2) = {6};
Physical Curve("load", 3) = {8, 9};
Physical Curve("free", 4) = {2, 3, 4, 5, 7, 10};
Physical Surface("arch", 10) = {1};
