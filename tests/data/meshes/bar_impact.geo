// A 2 m bar (0.2 x 0.2 m section) against a 5 cm wall fixed on its far
// face, the two separated by a joint at x = 2 m whose faces are meshed alike
// (duplicated nodes). For the impact check of contact joints
// (tests/demo/joint_contact_checks.sh): the bar moving at v0 towards the
// wall rebounds after 2L/c with -v0, the interface stress rho c v0.
//   gmsh -3 bar_impact.geo -o bar_impact.msh -format msh41
SetFactory("OpenCASCADE");
L = 2; a = 0.2; t = 0.05; h = 0.1;
Box(1) = {0, 0, 0, L, a, a};
Box(2) = {L, 0, 0, t, a, a};
Mesh.CharacteristicLengthMax = h;
Mesh.MshFileVersion = 4.1;

eps = 1e-6;
joint() = Surface In BoundingBox{L - eps, -eps, -eps, L + eps, a + eps, a + eps};
// Box 1's face at x = L comes first, box 2's second.
Periodic Surface{joint(1)} = {joint(0)} Translate{0, 0, 0};

Physical Volume("bar") = {1};
Physical Volume("wall") = {2};
Physical Surface("joint_bar") = {joint(0)};
Physical Surface("joint_wall") = {joint(1)};
Physical Surface("support") = Surface In BoundingBox{L + t - eps, -eps, -eps, L + t + eps, a + eps, a + eps};
