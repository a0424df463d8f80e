// A 1 m concrete cube on a base block (1 x 1 m, 0.5 m deep), the two
// separated by a horizontal joint at z = 0 whose faces are meshed alike
// (duplicated nodes). The base's bottom is fixed. For the contact checks
// (tests/demo/joint_contact_checks.sh): Newmark's sliding block and the
// keyed joint against the tied model.
//   gmsh -3 sliding_block.geo -o sliding_block.msh -format msh41
SetFactory("OpenCASCADE");
B = 1; H = 1; D = 0.5; h = 0.34;
Box(1) = {0, 0, -D, B, B, D};
Box(2) = {0, 0, 0, B, B, H};
Mesh.CharacteristicLengthMax = h;
Mesh.MshFileVersion = 4.1;

eps = 1e-6;
joint() = Surface In BoundingBox{-eps, -eps, -eps, B + eps, B + eps, eps};
// Box 1's top face comes first, box 2's bottom face second.
Periodic Surface{joint(1)} = {joint(0)} Translate{0, 0, 0};

Physical Volume("base") = {1};
Physical Volume("block") = {2};
Physical Surface("joint_base") = {joint(0)};
Physical Surface("joint_block") = {joint(1)};
Physical Surface("bottom") = Surface In BoundingBox{-eps, -eps, -D - eps, B + eps, B + eps, -D + eps};
Physical Surface("top") = Surface In BoundingBox{-eps, -eps, H - eps, B + eps, B + eps, H + eps};
