// A column 1 m wide and 10 m high (2D), for closed-form checks of
// dam_model's loads: self weight, a traction on the top, an initial
// velocity (plane stress, nu = 0: a 1D bar).
//   gmsh -2 column_2d.geo -o column_2d.msh -format msh41
SetFactory("OpenCASCADE");
Rectangle(1) = {0, 0, 0, 1, 10};
Mesh.CharacteristicLengthMax = 0.5;
eps = 1e-6;
Physical Surface("column") = {1};
Physical Curve("base") = Curve In BoundingBox{-eps, -eps, -eps, 1 + eps, eps, eps};
Physical Curve("top") = Curve In BoundingBox{-eps, 10 - eps, -eps, 1 + eps, 10 + eps, eps};
Physical Curve("sides") = Curve In BoundingBox{-eps, -eps, -eps, eps, 10 + eps, eps};
Physical Curve("sides") += Curve In BoundingBox{1 - eps, -eps, -eps, 1 + eps, 10 + eps, eps};
