// Two unit cubes side by side whose faces at x = 1 carry the same nodes but
// different triangles (structured, diagonals the other way): a
// non-conforming joint that dam_model must refuse.
//   gmsh -3 joint_nonconforming.geo -o joint_nonconforming.msh -format msh41
SetFactory("OpenCASCADE");
Box(1) = {0, 0, 0, 1, 1, 1};
Box(2) = {1, 0, 0, 1, 1, 1};
eps = 1e-6;
s() = Surface In BoundingBox{1 - eps, -eps, -eps, 1 + eps, 1 + eps, 1 + eps};
Transfinite Curve{:} = 3;
Transfinite Surface{s(0)} Left;
Transfinite Surface{s(1)} Right;
Physical Volume("left") = {1};
Physical Volume("right") = {2};
Physical Surface("side1") = {s(0)};
Physical Surface("side2") = {s(1)};
Physical Surface("base") = Surface In BoundingBox{-eps, -eps, -eps, 2 + eps, 1 + eps, eps};
