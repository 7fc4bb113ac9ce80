// Example C (Jureczka, Ochal & Bartman 2023): the plate [0,1.2] x [0,0.6]
// minus the half disk of radius 0.3 centred at (0.6, 0) and minus four
// screw holes of radius 0.05 at (0.15, 0.15), (1.05, 0.15), (0.15, 0.45),
// (1.05, 0.45). An unstructured triangle mesh of size h = 1/64 (Gmsh's
// default Delaunay front), for 'geometry/cell type = simplex'.
//
// Regenerate the committed mesh (Gmsh 4.8, Debian package 'gmsh'; MSH 4.1):
//   gmsh -2 prm/gmsh/plate_half_disk.geo -o prm/gmsh/plate_half_disk.msh
//
// Physical tags (the groups are named) become deal.II boundary ids:
//   1 the four holes' circles             -> clamped boundary ids (screws)
//   2 y = 0, x in [0,0.3] and [0.9,1.2]   -> contact boundary ids
//   3 y = 0.6 and x = 1.2                 -> traction boundary ids
//   4 x = 0 and the half-disk arc         -> free (no condition)
h = 1/64;
rh = 0.05;             // radius of the screw holes
Mesh.MeshSizeMax = h;
Mesh.MeshSizeMin = h;
Mesh.MeshSizeFromCurvature = 0;
Mesh.MeshSizeExtendFromBoundary = 1;

// outer boundary, counterclockwise
Point(1) = {0, 0, 0, h};
Point(2) = {0.3, 0, 0, h};
Point(3) = {0.6, 0, 0, h};       // centre of the half disk
Point(4) = {0.6, 0.3, 0, h};     // top of the half disk
Point(5) = {0.9, 0, 0, h};
Point(6) = {1.2, 0, 0, h};
Point(7) = {1.2, 0.6, 0, h};
Point(8) = {0, 0.6, 0, h};

Line(1) = {1, 2};                // contact, left
Circle(2) = {2, 3, 4};           // half-disk arc, left quarter
Circle(3) = {4, 3, 5};           // half-disk arc, right quarter
Line(4) = {5, 6};                // contact, right
Line(5) = {6, 7};                // x = 1.2, loaded
Line(6) = {7, 8};                // y = 0.6, loaded
Line(7) = {8, 1};                // x = 0, free
Curve Loop(1) = {1, 2, 3, 4, 5, 6, 7};

// four holes, each four quarter arcs
cx[] = {0.15, 1.05, 0.15, 1.05};
cy[] = {0.15, 0.15, 0.45, 0.45};
holes[] = {};
For i In {0:3}
  c = newp; Point(c) = {cx[i], cy[i], 0, h};
  p1 = newp; Point(p1) = {cx[i] + rh, cy[i], 0, h};
  p2 = newp; Point(p2) = {cx[i], cy[i] + rh, 0, h};
  p3 = newp; Point(p3) = {cx[i] - rh, cy[i], 0, h};
  p4 = newp; Point(p4) = {cx[i], cy[i] - rh, 0, h};
  a1 = newc; Circle(a1) = {p1, c, p2};
  a2 = newc; Circle(a2) = {p2, c, p3};
  a3 = newc; Circle(a3) = {p3, c, p4};
  a4 = newc; Circle(a4) = {p4, c, p1};
  loop = newll; Curve Loop(loop) = {a1, a2, a3, a4};
  holes[] += {loop};
  screw~{i}[] = {a1, a2, a3, a4};
EndFor

Plane Surface(1) = {1, holes[]};

Physical Curve("screws", 1) = {screw_0[], screw_1[], screw_2[], screw_3[]};
Physical Curve("contact", 2) = {1, 4};
Physical Curve("load", 3) = {5, 6};
Physical Curve("free", 4) = {2, 3, 7};
Physical Surface("plate", 10) = {1};
