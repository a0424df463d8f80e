// The normal of a triangular facet of a tetrahedral mesh, out of one of its
// cells, scaled by the facet's area (sums of them over the facets at a node
// give area-weighted node normals).
#pragma once

#include <Eigen/Dense>
#include <cstdint>
#include <dolfinx/mesh/Mesh.h>

namespace damseis::geometry
{
/// The area-weighted normal of facet `facet` pointing out of `cell` (one of
/// the facet's cells), from the geometry's vertices.
Eigen::Vector3d outward_facet_normal(const dolfinx::mesh::Mesh& mesh,
                                     std::int32_t facet, std::int32_t cell);
} // namespace damseis::geometry
