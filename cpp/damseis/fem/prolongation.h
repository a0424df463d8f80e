// Linear multipoint constraints between the nodes (dof blocks) of a vector
// space, u_s = sum_j w_j u_mj per component, eliminated by a prolongation
// P (all dofs x the unconstrained ones): u = P u_r. Tied joints are the
// case of one master of weight 1; the midside nodes of P2 contact joints
// follow the relative motion of their edge's vertex pairs.
#pragma once

#include <cstdint>
#include <dolfinx/fem/FunctionSpace.h>
#include <petscmat.h>
#include <span>
#include <utility>
#include <vector>

namespace damseis::fem
{
/// A constrained node: an owned block (local index) and its masters
/// (global block indices, none of them constrained) with weights.
struct BlockConstraint
{
  std::int32_t slave = 0;
  std::vector<std::pair<std::int64_t, double>> masters;
};

/// P for the constraints of the owned blocks of V (each slave once).
/// Collective; the caller owns P. The reduced numbering keeps the owned
/// unconstrained blocks in order, with the block structure.
Mat constraint_prolongation(const dolfinx::fem::FunctionSpace& V,
                            const std::vector<BlockConstraint>& constraints);

/// The reduced block each global block takes its dofs from (its own, or
/// the master of a tie: a single master of weight 1), -1 where it combines
/// several; on every rank (collective; `blocks` the same on every rank).
std::vector<std::int64_t> reduced_blocks(Mat P, int bs,
                                         std::span<const std::int64_t> blocks);
} // namespace damseis::fem
