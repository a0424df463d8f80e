// The patch test across a closed contact joint: two unit cubes, one on the
// other, separated by a joint at z' = 0 whose faces are meshed alike
// (duplicated nodes), the whole turned by 30 degrees about the y axis so
// the joint is inclined (its frame is neither the global one nor aligned
// with it). The lower cube's bottom is fixed; tractions on the top and the
// four sides make a uniform stress state
// (tests/demo/joint_patch_impact_checks.sh).
//   gmsh -3 patch_joint.geo -o patch_joint.msh -format msh41
SetFactory("OpenCASCADE");
h = 0.3;
Box(1) = {0, 0, -1, 1, 1, 1};
Box(2) = {0, 0, 0, 1, 1, 1};
Mesh.CharacteristicLengthMax = h;
Mesh.MshFileVersion = 4.1;

Rotate {{0, 1, 0}, {0, 0, 0}, Pi / 6} { Volume{1, 2}; }
// A box's faces in OpenCASCADE's order: x' = 0, x' = 1, y' = 0, y' = 1,
// z' = min, z' = max (the turn keeps the order, not the tags).
lo() = Boundary{ Volume{1}; };
up() = Boundary{ Volume{2}; };
// The lower cube's top face first, the upper cube's bottom face second.
Periodic Surface{up(4)} = {lo(5)} Translate{0, 0, 0};

Physical Volume("lower") = {1};
Physical Volume("upper") = {2};
Physical Surface("joint_lower") = {lo(5)};
Physical Surface("joint_upper") = {up(4)};
Physical Surface("bottom") = {lo(4)};
Physical Surface("top") = {up(5)};
Physical Surface("x0") = {lo(0), up(0)};
Physical Surface("x1") = {lo(1), up(1)};
Physical Surface("y0") = {lo(2), up(2)};
Physical Surface("y1") = {lo(3), up(3)};
