// The structured band of a transmitting boundary in the arch dam's
// foundation block (geometry/arch_mesh): the rock within a band's width of
// the block's bottom, sides, upstream and downstream faces, cut into
// topological hexahedra and meshed as transfinite (structured)
// tetrahedra, so that every boundary node has the nodes of Liao's formula
// at uniform spacing along its normal (fem/MtfBoundary). Vertical planes
// at the rims and the canyon floor's edges cut the band where it crosses
// the valley into columns under the floor, the walls and the plateau.
// Beside a straight wall (a V canyon) the column is a hexahedron with the
// wall as its top; beside a wall of several segments (a U canyon's
// fillets) it is meshed unstructured and the stencil points in it are
// interpolated. gmsh (OCC) on rank 0.
#pragma once

#include "arch_dam.h"
#include <gmsh.h>
#include <vector>

namespace damseis::geometry
{
/// The rock block `rock` cut into its core (inside the band) and the
/// band's pieces: the band (the rock within `w` of the block's bottom,
/// sides, upstream and downstream faces) fragmented by the planes of the
/// band's inner faces and by vertical planes at the rims and the floor's
/// edges.
/// Returns the core first, then the pieces (OCC, synchronised).
gmsh::vectorpair split_band(const ArchDamGeometry& g, const ModelBox& e,
                            const gmsh::vectorpair& rock, double w);

/// Sets the band's hexahedral volumes (after the model's last boolean) to
/// be meshed as structured tetrahedra of about `h`: the node count of each
/// curve by its interval, opposite edges of every piece equal; the other
/// pieces (beside a wall of several segments) are left unstructured.
void structure_band(const ArchDamGeometry& g, const ModelBox& e, double w,
                    double h, const std::vector<int>& band_volumes);
/// The (volume, surface) pairs of the meshed band whose surface triangles
/// are not faces of the volume's tetrahedra (a non-conforming mesh).
std::vector<std::pair<int, int>>
band_mismatches(const std::vector<int>& band_volumes);
} // namespace damseis::geometry
