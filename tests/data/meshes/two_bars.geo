// Two bars of one material meeting at a joint: a 1 m bar (x = 0 ... 1)
// and a 3 m bar (x = 1 ... 4) fixed on its far face, 0.2 x 0.2 m, the
// joint's faces meshed alike (duplicated nodes). For the impact of two
// massive bodies (tests/demo/joint_patch_impact_checks.sh): the short bar
// moving at v0 stops after 2 L1 / c and its momentum passes to the long one.
//   gmsh -3 two_bars.geo -o two_bars.msh -format msh41
SetFactory("OpenCASCADE");
L1 = 1; L2 = 3; a = 0.2; h = 0.1;
Box(1) = {0, 0, 0, L1, a, a};
Box(2) = {L1, 0, 0, L2, a, a};
Mesh.CharacteristicLengthMax = h;
Mesh.MshFileVersion = 4.1;

eps = 1e-6;
joint() = Surface In BoundingBox{L1 - eps, -eps, -eps, L1 + eps, a + eps, a + eps};
// Box 1's face at x = L1 comes first, box 2's second.
Periodic Surface{joint(1)} = {joint(0)} Translate{0, 0, 0};

Physical Volume("short_bar") = {1};
Physical Volume("long_bar") = {2};
Physical Surface("joint_short") = {joint(0)};
Physical Surface("joint_long") = {joint(1)};
Physical Surface("support") = Surface In BoundingBox{L1 + L2 - eps, -eps, -eps, L1 + L2 + eps, a + eps, a + eps};
