// Example B (Bartman-Szwarc, Ochal, Sofonea & Tarzia): the polygon with
// vertices (0,0.2), (0.2,0.4), (0.6,0.4), (0.8,0.2), (0.8,0), (1.2,0),
// (1.2,1.2), (0.8,1.2), (0.8,1), (0.6,0.8), (0.2,0.8), (0,1). An
// unstructured quadrilateral mesh of size h = 1/16 (Delaunay triangles
// recombined by Blossom); 'geometry/global refinements = 1' in
// prm/example_b_penalised.prm halves it to the paper's 1/32.
//
// Regenerate the committed mesh (Gmsh 4.8, Debian package 'gmsh'; MSH 4.1):
//   gmsh -2 prm/gmsh/example_b_polygon.geo -o prm/gmsh/example_b_polygon.msh
//
// Physical tags (the groups are named) become deal.II boundary ids:
//   1 x = 0, y in [0.2, 1]                -> clamped boundary ids
//   2 y = 0, x in [0.8, 1.2]              -> contact boundary ids
//   3 the other ten edges                 -> traction free (no condition)
h = 1/16;
Mesh.MeshSizeMax = h;
Mesh.MeshSizeMin = h;
Mesh.Algorithm = 6;               // Frontal-Delaunay triangles ...
Mesh.RecombinationAlgorithm = 2;  // ... recombined into quadrilaterals
Mesh.RecombineAll = 1;

// the vertices, counterclockwise
Point(1) = {0, 0.2, 0, h};
Point(2) = {0.2, 0.4, 0, h};
Point(3) = {0.6, 0.4, 0, h};
Point(4) = {0.8, 0.2, 0, h};
Point(5) = {0.8, 0, 0, h};
Point(6) = {1.2, 0, 0, h};
Point(7) = {1.2, 1.2, 0, h};
Point(8) = {0.8, 1.2, 0, h};
Point(9) = {0.8, 1, 0, h};
Point(10) = {0.6, 0.8, 0, h};
Point(11) = {0.2, 0.8, 0, h};
Point(12) = {0, 1, 0, h};

// edge i joins vertices i and i + 1; edge 5 is the contact segment, 12 the
// clamped side x = 0
For i In {1:11}
  Line(i) = {i, i + 1};
EndFor
Line(12) = {12, 1};
Curve Loop(1) = {1:12};
Plane Surface(1) = {1};

Physical Curve("clamped", 1) = {12};
Physical Curve("contact", 2) = {5};
Physical Curve("free", 3) = {1, 2, 3, 4, 6, 7, 8, 9, 10, 11};
Physical Surface("body", 10) = {1};
