// Lamb's problem in 2D (issue 20's scattering check): rock x in [-L, L],
// y in [-L, 0] (plane strain), a strip |x| <= 4 m of the free surface
// loaded by a vertical traction (facet group "load"), the block's outer
// 16 m along the sides and bottom the cell group "band" (unstructured
// triangles), its outer boundary "boundary". The cells under the strip
// (x in [-4, 4], y in [-8, 0]) are the group "source" (dam_model's
// regions.dam; the same rock). The surface points x = 4, 8, ... are mesh
// nodes, so the receivers tests/demo/lamb_checks.sh reads are nodes.
//   gmsh -2 -setnumber L 120 lamb_half_space_2d.geo -o lamb.msh -format msh41
// With -setnumber far 1 the block sits inside rock reaching 1600 m
// (group "far", coarse at its boundary): a reference whose boundary is
// too far for a reflection to return within the checked window.
SetFactory("OpenCASCADE");
If (!Exists(L))
  L = 120;
EndIf
If (!Exists(far))
  far = 0;
EndIf
If (!Exists(h))
  h = 8.0; // cell size (P2: node spacing h / 2)
EndIf
band = 16;
Mesh.MeshSizeFromPoints = 1;
Mesh.MeshSizeExtendFromBoundary = 1;
Mesh.MeshSizeFromCurvature = 0;
Mesh.Algorithm = 6;

// The source cells.
Point(1) = {-4, 0, 0, h / 2};
Point(2) = {4, 0, 0, h / 2};
Point(3) = {4, -8, 0, h / 2};
Point(4) = {-4, -8, 0, h / 2};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};

// The rock inside the band.
a = L - band;
Point(5) = {-a, 0, 0, h};
Point(6) = {-a, -a, 0, h};
Point(7) = {a, -a, 0, h};
Point(8) = {a, 0, 0, h};
Line(5) = {5, 1};
Line(6) = {6, 5};
Line(7) = {7, 6};
Line(8) = {8, 7};
Line(9) = {2, 8};
Curve Loop(2) = {5, -4, -3, -2, 9, 8, 7, 6};
Plane Surface(2) = {2};

// The band.
Point(9) = {-L, 0, 0, h};
Point(10) = {-L, -L, 0, h};
Point(11) = {L, -L, 0, h};
Point(12) = {L, 0, 0, h};
Line(10) = {9, 5};
Line(11) = {10, 9};
Line(12) = {11, 10};
Line(13) = {12, 11};
Line(14) = {8, 12};
Curve Loop(3) = {10, -6, -7, -8, 14, 13, 12, 11};
Plane Surface(3) = {3};

// Surface nodes every h / 2 (receivers on nodes).
Transfinite Curve{9} = (a - 4) / (h / 2) + 1;
Transfinite Curve{5} = (a - 4) / (h / 2) + 1;
Transfinite Curve{1} = 8 / (h / 2) + 1;

Physical Surface("source") = {1};
Physical Surface("rock") = {2};
Physical Surface("band") = {3};
Physical Curve("load") = {1};
Physical Curve("surface") = {5, 9};

If (far == 0)
  Physical Curve("boundary") = {11, 12, 13};
Else
  F = 1600;
  Point(13) = {-F, 0, 0, 20 * h};
  Point(14) = {-F, -F, 0, 20 * h};
  Point(15) = {F, -F, 0, 20 * h};
  Point(16) = {F, 0, 0, 20 * h};
  Line(15) = {13, 9};
  Line(16) = {14, 13};
  Line(17) = {15, 14};
  Line(18) = {16, 15};
  Line(19) = {12, 16};
  Curve Loop(4) = {15, -11, -12, -13, 19, 18, 17, 16};
  Plane Surface(4) = {4};
  Physical Surface("far") = {4};
  Physical Curve("boundary") = {16, 17, 18};
EndIf
