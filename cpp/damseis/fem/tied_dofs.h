// Tying coincident degrees of freedom (bonded contraction joints): the
// prolongation P from the tied (reduced) unknowns to all dofs, u = P u_r.
#pragma once

#include <dolfinx/fem/FunctionSpace.h>
#include <dolfinx/mesh/MeshTags.h>
#include <petscmat.h>
#include <utility>
#include <vector>

namespace damseis::fem
{
/// Builds P (all dofs x reduced dofs, one 1 per row) such that every dof of
/// V on the facets tagged `second` equals the coincident dof (within `tol`)
/// on the facets tagged `first`, for each (first, second) pair of tags.
/// Dofs of a block (all components of a node) are tied together; the
/// reduced numbering keeps the block structure. Collective. Throws
/// std::runtime_error if a dof on a `second` facet has no coincident
/// partner. The caller owns P.
Mat tie_prolongation(const dolfinx::fem::FunctionSpace& V,
                     const dolfinx::mesh::MeshTags<std::int32_t>& facet_tags,
                     const std::vector<std::pair<int, int>>& tag_pairs,
                     double tol = 1e-8);

/// The operator on the tied unknowns, P^T A P (AIJ; any storage of A).
/// The caller owns the result.
Mat reduce_to_tied(Mat A, Mat P);

/// The restriction of a vector x that P reproduces exactly (x = P x_r):
/// the least-squares x_r = (P^T P)^-1 P^T x (with ties: the mean of the
/// tied values). Any prolongation (prolongation.h). The caller owns the
/// result.
Vec restrict_to_tied(Mat P, Vec x);
} // namespace damseis::fem
