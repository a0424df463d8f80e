// The static stage of a jointed dam with contact at the joints
// (algorithms.md 2.8): the dead weight either with the joints active from
// the start, or carried by the cantilevers alone (joints disconnected, as
// they are grouted after the blocks carry their own weight: the gaps and
// slips are then measured from the dead-load state), then the rest of the
// static load (water, silt, ...) in increments with contact active.
//
// A block may be held by its joints alone (no support of its own): K is
// then singular, and whether a factorisation of it notices depends on its
// rounding. So the static stage never factorises K: it solves K u = F + G p
// by the proximal-point iteration
//   (K + s M) u_k+1 = F + G p_k+1 + s M u_k,   s = static_shift_factor
//   omega_1^2 (omega_1: the lowest circular frequency of the bonded model),
// with the contact of each iterate. Its fixed point is the static solution;
// the error of each elastic mode j shrinks by s / (s + omega_j^2) <= 1/1000
// per iteration (a few iterations), and a rigid motion that no joint holds
// does not shrink at all: no static equilibrium, reported as such.
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

/// s = static_shift_factor omega_1^2 (see above).
constexpr double static_shift_factor = 1e-3;
/// The iteration has converged when no unknown changes by more than this
/// times the largest displacement.
constexpr double static_tolerance = 1e-10;
/// When the changes stop shrinking below this times the largest
/// displacement, round-off has been reached (the conditioning of a block
/// held by its joints alone: measured 1e-9 on tests/data's sliding block).
constexpr double static_round_off = 1e-7;
/// Iterations per load increment before giving up.
constexpr int static_max_iterations = 40;

struct StaticContactResult
{
  dolfinx::la::petsc::Vector u{nullptr, false}; ///< the static displacement
  Eigen::VectorXd g0, w, p; ///< the pairs' gap reference, w and forces
  std::vector<contact::PairState> states;
  std::vector<char> broken; ///< per pair: its bond failed (bonded joints)
  ContactTotals totals;     ///< the static solves' work
  double shift = 0.0;       ///< s [1/s^2]
  int iterations = 0;       ///< proximal-point iterations over all increments
};

/// The pairs' state after a static stage (the u, shift and iterations
/// left to the caller).
StaticContactResult contact_state(const CondensedContact& c);

/// The joints closed (grouted) at the displacement u of the cantilevers'
/// dead load, with no force, or open by their initial gap: the gaps'
/// reference and the slips measured from u (collective).
void close_joints_at(CondensedContact& c, Vec u);

/// K u = F + G p with the contact of `pairs`: F_dead first (one increment),
/// then F_dead + k/n (F_all - F_dead), k = 1..n. Collective. Throws
/// ContactFailure naming the increment if contact does not converge, if
/// there is no static equilibrium (a block slides or is not held), or if
/// the dead load is carried by the cantilevers alone while a block has no
/// support of its own.
StaticContactResult static_contact(Mat K, Mat M, double omega_1, Vec F_dead,
                                   Vec F_all, const PairSet& pairs,
                                   const StaticContactSettings& settings,
                                   contact::NcpSettings ncp = {});
} // namespace damseis::joint
