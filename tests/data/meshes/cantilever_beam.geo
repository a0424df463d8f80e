// A cantilever beam, 10 m long (x), 1 m wide (y), 1 m deep (z), fixed at
// x = 0 and bending under its own weight. For the arch and cantilever
// stresses of a face (tests/demo/dam_model_checks.sh): on the side face y
// = 0 the face's horizontal is x, so the "arch" stress is the bending
// stress sigma_xx = 3 rho g (L - x)^2 / h at the top fibre, and the
// "cantilever" stress (vertical in the face) is small.
//   gmsh -3 cantilever_beam.geo -o cantilever_beam.msh -format msh41
SetFactory("OpenCASCADE");
L = 10; b = 1; h = 1;
Box(1) = {0, 0, 0, L, b, h};
Mesh.CharacteristicLengthMax = 0.34;
Mesh.MshFileVersion = 4.1;
eps = 1e-6;
Physical Volume("beam") = {1};
Physical Surface("root") = Surface In BoundingBox{-eps, -eps, -eps, eps, b + eps, h + eps};
Physical Surface("side") = Surface In BoundingBox{-eps, -eps, -eps, L + eps, eps, h + eps};
