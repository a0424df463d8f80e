// The structured band of a transmitting boundary in the arch dam's
// foundation block (geometry/arch_mesh): the rock within a band's width of
// the block's bottom, sides, upstream and downstream faces, cut into
// topological hexahedra and meshed as transfinite (structured)
// tetrahedra, so that every boundary node has the nodes of Liao's formula
// at uniform spacing along its normal (fem/MtfBoundary). Vertical planes
// at the canyon's corners (the floor's edges, where a wall changes slope,
// the rims) cut the band into columns, each under one face of the ground:
// the floor, one wall segment or the plateau. gmsh (OCC) on rank 0.
#pragma once

#include "arch_dam.h"
#include <gmsh.h>
#include <vector>

namespace damseis::geometry
{
/// The x of the band's vertical cuts, ascending: the block's faces, the
/// band's inner faces, the rims, the floor's edges and the walls' corners.
std::vector<double> band_x_cuts(const ArchDamGeometry& g, const ModelBox& e,
                                double w);

/// The rock block `rock` cut into its core (inside the band) and the
/// band's pieces: the band (the rock within `w` of the block's bottom,
/// sides, upstream and downstream faces) fragmented by the planes of the
/// band's inner faces and by vertical planes at band_x_cuts.
/// Returns the core first, then the pieces (OCC, synchronised).
gmsh::vectorpair split_band(const ArchDamGeometry& g, const ModelBox& e,
                            const gmsh::vectorpair& rock, double w);

/// Sets the band's volumes (after the model's last boolean) to be meshed as
/// structured tetrahedra of about `h`: the node count of each curve by its
/// interval, opposite edges of every piece equal. Throws
/// std::runtime_error if a piece is not a hexahedron.
void structure_band(const ArchDamGeometry& g, const ModelBox& e, double w,
                    double h, const std::vector<int>& band_volumes);
/// The (volume, surface) pairs of the meshed band whose surface triangles
/// are not faces of the volume's tetrahedra (a non-conforming mesh).
std::vector<std::pair<int, int>>
band_mismatches(const std::vector<int>& band_volumes);
} // namespace damseis::geometry
