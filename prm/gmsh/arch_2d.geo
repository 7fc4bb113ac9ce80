// A semicircular arch (inner radius 1, outer radius 1.5, centre at the
// origin) standing on the line y = 0: its left foot is anchored (clamped),
// its right foot rests on the foundation (contact), the outer arc carries
// the load. A structured quadrilateral mesh (Recombine + Transfinite).
//
// Regenerate the committed mesh (Gmsh 4.8, Debian package 'gmsh'; MSH 4.1):
//   gmsh -2 prm/gmsh/arch_2d.geo -o prm/gmsh/arch_2d.msh
// (tests/io/meshes/ holds the same mesh as MSH 2.2, '-format msh22', and
// as binary MSH 4.1, '-bin', for tests/io/gmsh_formats.sh.)
//
// Physical tags (the groups are named) become deal.II boundary ids:
//   1 left foot (x in [-1.5,-1], y = 0)   -> clamped boundary ids
//   2 right foot (x in [1,1.5], y = 0)    -> contact boundary ids
//   3 outer arc (radius 1.5)              -> traction boundary ids
//   4 inner arc (radius 1)                -> free (no condition)
ri = 1.0;
ro = 1.5;
n_radial = 4;          // cells across the thickness
n_around = 24;         // cells along each quarter of the arch

Point(1) = {0, 0, 0};
Point(2) = {ri, 0, 0};
Point(3) = {ro, 0, 0};
Point(4) = {0, ri, 0};
Point(5) = {0, ro, 0};
Point(6) = {-ri, 0, 0};
Point(7) = {-ro, 0, 0};

Line(1) = {2, 3};             // right foot
Circle(2) = {3, 1, 5};        // outer arc, right quarter
Circle(3) = {5, 1, 7};        // outer arc, left quarter
Line(4) = {7, 6};             // left foot
Circle(5) = {6, 1, 4};        // inner arc, left quarter
Circle(6) = {4, 1, 2};        // inner arc, right quarter
Line(7) = {4, 5};             // crown (interior line between the two halves)

Curve Loop(1) = {1, 2, -7, 6};
Plane Surface(1) = {1};
Curve Loop(2) = {7, 3, 4, 5};
Plane Surface(2) = {2};

Transfinite Curve{1, 4, 7} = n_radial + 1;
Transfinite Curve{2, 3, 5, 6} = n_around + 1;
Transfinite Surface{1};
Transfinite Surface{2};
Recombine Surface{1, 2};

Physical Curve("clamped", 1) = {4};
Physical Curve("contact", 2) = {1};
Physical Curve("load", 3) = {2, 3};
Physical Curve("free", 4) = {5, 6};
Physical Surface("arch", 10) = {1, 2};
