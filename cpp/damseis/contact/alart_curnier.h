// The Coulomb contact law of one node pair of a contraction joint, in the
// Cartesian Alart-Curnier form (algorithms.md 2.4), and the damped
// semismooth Newton solution of one pair. Pure C++ on small arrays, like
// material/: unit-tested without a mesh.
//
// Conventions (algorithms.md 2.1): local frame (n, t_a, t_b), n the unit
// normal of side 1 into side 2; relative displacement w = (w_n, w_a, w_b)
// of side 2 from side 1; gap g = g0 + w_n >= 0; slip increment over the
// step ds = w_T - w_T,old; pair force p = (P_n, P_a, P_b) acting on side 2
// as +p (side 1: -p), P_n >= 0 in compression, |P_T| <= mu P_n, and in
// sliding P_T opposite to the slip.
#pragma once

#include <Eigen/Dense>

namespace damseis::contact
{
/// The law of a joint.
struct PairLaw
{
  double mu = 1.0;    ///< friction coefficient (the paper: 1.0)
  bool keyed = false; ///< shear keys: no sliding (mu -> infinity)
  double r_n = 1.0;   ///< scaling of the gap in the normal residual [N/m]
  double r_t = 1.0;   ///< scaling of the slip in the tangential one [N/m]
  /// An intact bond (grouted joint): the tension T it carries (P_n >= -T)
  /// and its cohesion C (|P_T| <= C + mu P_n) [N: strength times the
  /// pair's area]. 0: none (the paper's joints). A bond that fails is
  /// gone for good: the caller sets both to 0 (bond_failed()).
  double tension = 0.0;
  double cohesion = 0.0;
};

enum class PairState
{
  open,  ///< no force (the normal residual's open branch)
  stick, ///< in contact, no slip
  slip   ///< in contact, sliding at |P_T| = mu P_n
};

/// The residual F(p; g, ds) = (F_n, F_T) of a pair, zero exactly at the
/// Coulomb solution, and its generalised Jacobian: B = dF/dp and A =
/// dF/d(g, ds_a, ds_b) (ties take the contact branches).
struct PairResidual
{
  Eigen::Vector3d F;
  Eigen::Matrix3d B, A;
  PairState state = PairState::open;
};

/// F_n = P_n + T - <sigma_n>, sigma_n = P_n + T - r_n g; F_T = P_T -
/// Pi_rho(P_T - r_t ds), rho = <C + mu (sigma_n - T)> while closed, 0 open
/// (keyed: F_T = r_t ds). Without a bond (T = C = 0) the classic form.
PairResidual alart_curnier(const PairLaw& law, const Eigen::Vector3d& p,
                           double g, const Eigen::Vector2d& ds);

/// Whether a bonded pair's bond has failed in the state `s`: it opened
/// (the tension reached T) or slid (the shear reached C + mu P_n).
inline bool bond_failed(const PairLaw& law, PairState s)
{
  return (law.tension > 0.0 || law.cohesion > 0.0) && s != PairState::stick;
}

/// One pair whose relative displacement depends linearly on its force, w =
/// w_free + W p (W: the pair's 3x3 flexibility, symmetric positive
/// definite): the force that satisfies the law.
struct PairSolution
{
  Eigen::Vector3d p = Eigen::Vector3d::Zero();
  Eigen::Vector3d w = Eigen::Vector3d::Zero();
  PairState state = PairState::open;
  int iterations = 0;
  bool converged = false;
};

/// Damped semismooth Newton on F(p) = 0 with w = w_free + W p, g = g0 +
/// w_n, ds = w_T - w_T,old (algorithms.md 2.5: Armijo line search on
/// |F|^2 / 2, gradient fallback), from `p0`. Converged when |F| <= tol
/// times the scale of the forces.
PairSolution solve_pair(const PairLaw& law, const Eigen::Matrix3d& W,
                        const Eigen::Vector3d& w_free,
                        const Eigen::Vector2d& w_T_old, double g0,
                        const Eigen::Vector3d& p0 = Eigen::Vector3d::Zero(),
                        double tol = 1e-12, int max_iterations = 50);
} // namespace damseis::contact
