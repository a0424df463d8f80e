// A 1 m concrete cube on a base block (1 x 1 m, 0.5 m deep) across a
// horizontal joint at z = 0 whose faces are meshed alike (duplicated
// nodes), and a spring: a massless bar (0.2 x 0.2 m, 2 m long) from the
// middle of the cube's face at x = 1 to its far end, fixed. The bar meets
// the cube at mid-height, so that the spring's pull and the cube's inertia
// make no moment about the joint. For the Coulomb oscillator check
// (tests/demo/joint_contact_checks.sh).
//   gmsh -3 coulomb_oscillator.geo -o coulomb_oscillator.msh -format msh41
SetFactory("OpenCASCADE");
B = 1; H = 1; D = 0.5; L = 2; a = 0.2; h = 0.34;
Box(1) = {0, 0, -D, B, B, D};
Box(2) = {0, 0, 0, B, B, H};
Box(3) = {B, (B - a) / 2, (H - a) / 2, L, a, a};
// The cube and the bar share their interface; the base stays apart.
BooleanFragments{ Volume{2}; Delete; }{ Volume{3}; Delete; }
Mesh.CharacteristicLengthMax = h;
Mesh.MshFileVersion = 4.1;

eps = 1e-6;
joint() = Surface In BoundingBox{-eps, -eps, -eps, B + eps, B + eps, eps};
// Box 1's top face comes first, the cube's bottom face second.
Periodic Surface{joint(1)} = {joint(0)} Translate{0, 0, 0};

Physical Volume("base") = Volume In BoundingBox{-eps, -eps, -D - eps, B + eps, B + eps, eps};
Physical Volume("block") = Volume In BoundingBox{-eps, -eps, -eps, B + eps, B + eps, H + eps};
Physical Volume("spring") = Volume In BoundingBox{B - eps, -eps, -eps, B + L + eps, B + eps, H + eps};
Physical Surface("joint_base") = {joint(0)};
Physical Surface("joint_block") = {joint(1)};
Physical Surface("bottom") = Surface In BoundingBox{-eps, -eps, -D - eps, B + eps, B + eps, -D + eps};
Physical Surface("spring_end") = Surface In BoundingBox{B + L - eps, -eps, -eps, B + L + eps, B + eps, H + eps};
