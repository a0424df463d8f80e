// The static stage of a jointed dam with contact at the joints
// (algorithms.md 2.8): the dead weight either with the joints active from
// the start, or carried by the cantilevers alone (joints disconnected, as
// they are grouted after the blocks carry their own weight: the gaps and
// slips are then measured from the dead-load state), then the rest of the
// static load (water, silt, ...) in increments with contact active.
#pragma once

#include "condensed_contact.h"
#include <dolfinx/la/petsc.h>

namespace damseis::joint
{
struct StaticContactSettings
{
  bool cantilever_dead_load = false; ///< joints disconnected under gravity
  int increments = 5; ///< for the load beyond the dead weight (>= 1)
};

/// A block held only by its joints (no support of its own) makes K
/// singular: the static stage then solves with K + shift M, shift = 1e-6
/// omega_1^2 (omega_1 the lowest circular frequency of the bonded model):
/// the inertia-like term changes the elastic response by about 1e-6.
constexpr double static_shift_factor = 1e-6;

struct StaticContactResult
{
  dolfinx::la::petsc::Vector u{nullptr, false}; ///< the static displacement
  Eigen::VectorXd g0, w, p; ///< the pairs' gap reference, w and forces
  std::vector<contact::PairState> states;
  ContactTotals totals; ///< the static solves' work
  double shift = 0.0;   ///< the mass shift used (0: none; K was regular)
};

/// K u = F + G p with the contact of `pairs`: F_dead first (one increment),
/// then F_dead + k/n (F_all - F_dead), k = 1..n. With blocks held by their
/// joints alone, K + shift M with shift = static_shift_factor omega_1^2.
/// Collective. Throws ContactFailure naming the increment if contact does
/// not converge, or if the dead load is carried by the cantilevers alone
/// while a block has no support of its own.
StaticContactResult static_contact(Mat K, Mat M, double omega_1, Vec F_dead,
                                   Vec F_all, const PairSet& pairs,
                                   const StaticContactSettings& settings,
                                   contact::NcpSettings ncp = {});
} // namespace damseis::joint
