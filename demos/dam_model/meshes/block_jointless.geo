// The mesh of block_1joint.geo with its duplicated joint nodes merged: the
// same nodes and cells, the two monoliths bonded (a reference for the tied
// joint).
//   gmsh -3 block_jointless.geo -o block_jointless.msh -format msh41
Merge "block_1joint.msh";
Coherence Mesh;
Mesh.MshFileVersion = 4.1;
