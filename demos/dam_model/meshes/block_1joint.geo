// A 3D block of a dam, 20 m long (x), 8 m thick (y) and 24 m high (z), on a
// rigid base, split by one contraction joint at x = 10 m into two
// monoliths. The two faces of the joint are two surfaces meshed alike
// (the right one a periodic copy of the left): duplicated nodes, node for
// node. Upstream face y = 0.
//   gmsh -3 block_1joint.geo -o block_1joint.msh -format msh41
// block_jointless.geo merges the duplicated nodes of the same mesh.
SetFactory("OpenCASCADE");
L = 20; T = 8; H = 24; h = 3;
Box(1) = {0, 0, 0, L / 2, T, H};
Box(2) = {L / 2, 0, 0, L / 2, T, H};
Mesh.CharacteristicLengthMax = h;
Mesh.MshFileVersion = 4.1;

eps = 1e-6;
left_joint() = Surface In BoundingBox{L/2 - eps, -eps, -eps, L/2 + eps, T + eps, H + eps};
// Box 1's face at x = L/2 comes first, box 2's second.
Periodic Surface{left_joint(1)} = {left_joint(0)} Translate{0, 0, 0};

Physical Volume("block_left") = {1};
Physical Volume("block_right") = {2};
Physical Surface("joint_left") = {left_joint(0)};
Physical Surface("joint_right") = {left_joint(1)};
Physical Surface("base") = Surface In BoundingBox{-eps, -eps, -eps, L + eps, T + eps, eps};
Physical Surface("upstream") = Surface In BoundingBox{-eps, -eps, -eps, L + eps, eps, H + eps};
Physical Surface("downstream") = Surface In BoundingBox{-eps, T - eps, -eps, L + eps, T + eps, H + eps};
Physical Surface("crest") = Surface In BoundingBox{-eps, -eps, H - eps, L + eps, T + eps, H + eps};
Physical Surface("ends") = Surface In BoundingBox{-eps, -eps, -eps, eps, T + eps, H + eps};
Physical Surface("ends") += Surface In BoundingBox{L - eps, -eps, -eps, L + eps, T + eps, H + eps};
