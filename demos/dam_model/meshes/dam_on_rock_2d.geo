// A 40 m gravity dam section (heel (0, 0), toe (30, 0), crest (0..6, 40))
// on a rock block 150 m wide and 60 m deep whose outer 20 m along the
// sides and bottom form the cell group "band" (unstructured triangles):
// the band of dam_model's multi-transmitting boundary (supports.
// transmitting = ["boundary"], foundation.band = ["band"]).
//   gmsh -2 dam_on_rock_2d.geo -o dam_on_rock_2d.msh -format msh41
// With -setnumber far 1 the block sits inside rock 2430 m wide and 1200 m
// deep (group "far", its sides and bottom "boundary"): the reference of
// the boundary's check (tests/demo/dam_model_mtf_checks.sh). The dam, the
// rock and the band are meshed alike in both: the same curves with the
// same point sizes, each surface meshed from its own boundary.
//   gmsh -2 -setnumber far 1 dam_on_rock_2d.geo -o dam_on_rock_2d_far.msh -format msh41
SetFactory("OpenCASCADE");
If (!Exists(far))
  far = 0;
EndIf
If (!Exists(margin))
  margin = 60; // the block's outer boundary beyond the dam's base [m]
EndIf
band = 20;     // the band's thickness [m]
a = -margin; b = 30 + margin; d = -margin;       // the block
ai = a + band; bi = b - band; di = d + band;     // inside the band
h_dam = 2.0;  // cell size in the dam [m]
h_rock = 4.0; // in the rock and the band (the formula's dx with P1)
h_far = 40.0; // at the far rock's outer boundary
Mesh.MeshSizeFromPoints = 1;
Mesh.MeshSizeExtendFromBoundary = 1;
Mesh.MeshSizeFromCurvature = 0;
Mesh.Algorithm = 6;

// The dam.
Point(1) = {0, 0, 0, h_dam};
Point(2) = {30, 0, 0, h_dam};
Point(3) = {6, 40, 0, h_dam};
Point(4) = {0, 40, 0, h_dam};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};

// The rock inside the band: x in [-40, 70], y in [-40, 0].
Point(5) = {ai, 0, 0, h_rock};
Point(6) = {ai, di, 0, h_rock};
Point(7) = {bi, di, 0, h_rock};
Point(8) = {bi, 0, 0, h_rock};
Line(5) = {5, 1};
Line(6) = {6, 5};
Line(7) = {7, 6};
Line(8) = {8, 7};
Line(9) = {2, 8};
Curve Loop(2) = {5, 1, 9, 8, 7, 6};
Plane Surface(2) = {2};

// The band: the block x in [-60, 90], y in [-60, 0] outside the rock.
Point(9) = {a, 0, 0, h_rock};
Point(10) = {a, d, 0, h_rock};
Point(11) = {b, d, 0, h_rock};
Point(12) = {b, 0, 0, h_rock};
Line(10) = {9, 5};
Line(11) = {10, 9};
Line(12) = {11, 10};
Line(13) = {12, 11};
Line(14) = {8, 12};
Curve Loop(3) = {10, -6, -7, -8, 14, 13, 12, 11};
Plane Surface(3) = {3};

Physical Surface("dam") = {1};
Physical Surface("rock") = {2};
Physical Surface("band") = {3};
Physical Curve("crest") = {3};
Physical Curve("upstream") = {4};
Physical Curve("downstream") = {2};

If (far == 0)
  Physical Curve("boundary") = {11, 12, 13};
Else
  // The far rock: x in [-1200, 1230], y in [-1200, 0] outside the block.
  Point(13) = {-1200, 0, 0, h_far};
  Point(14) = {-1200, -1200, 0, h_far};
  Point(15) = {1230, -1200, 0, h_far};
  Point(16) = {1230, 0, 0, h_far};
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
