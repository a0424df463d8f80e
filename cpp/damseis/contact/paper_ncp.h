// Formulation A (algorithms.md 2.3): the paper's NCP (eq. 13) in the
// unknowns q = (P_n, P_tau, theta) of each pair, the tangential force in
// polar form: P_a = P_tau cos(theta), P_b = P_tau sin(theta), P_tau signed
// and theta in (-pi/2, pi/2]. With x = ds . e_theta the slip along the
// force line and y = ds_a sin(theta) - ds_b cos(theta) across it, and
// rho = mu <P_n - r_n g>,
//   h1 = min(P_n, r_n g)
//   h2 = P_tau - clamp(P_tau - r_t x, -rho, rho)
//   h3 = r_t y
// (the paper's h2 = r_t x + min(0, rho + P_tau - r_t x) + max(0, -rho +
// P_tau - r_t x), the same function; r_n, r_t the scalings of
// alart_curnier.h). h2 is a 1-D complementarity along the force line, h3
// keeps the slip on that line. Where the slip direction is void (open or
// frictionless pairs: P_T = 0) h3 is replaced by theta - theta_k = 0
// (theta frozen at the iterate). Keyed: h2 = r_t x, h3 = r_t y (ds = 0).
// Solved by the damped semismooth Newton method of ncp.h (Armijo search on
// |h|^2 / 2, gradient fallback, the same two starts), with the dense
// Jacobian J = B + A W D, D = dp/dq per pair.
#pragma once

#include "ncp.h"

namespace damseis::contact
{
struct PaperResidual
{
  Eigen::Vector3d h;
  /// dh/dq at fixed (g, ds), and dh/d(g, ds_a, ds_b) at fixed q.
  Eigen::Matrix3d B, A;
  PairState state = PairState::open;
};

/// The residual of one pair at q (theta_k: the angle h3 freezes where the
/// slip direction is void).
PaperResidual paper_residual(const PairLaw& law, const Eigen::Vector3d& q,
                             double g, const Eigen::Vector2d& ds,
                             double theta_k);

/// p = (P_n, P_tau cos(theta), P_tau sin(theta)) and dp/dq.
Eigen::Vector3d paper_forces(const Eigen::Vector3d& q);
Eigen::Matrix3d paper_forces_jacobian(const Eigen::Vector3d& q);
/// q of the forces p (theta in (-pi/2, pi/2]).
Eigen::Vector3d paper_unknowns(const Eigen::Vector3d& p);

/// The contact problem solved in formulation A from p0 or the stuck
/// forces (as solve_ncp); the report's p, w and states are those of the
/// Cartesian forces, its residual |h| / force scale.
NcpReport solve_ncp_paper(const ContactProblem& c, const Eigen::VectorXd& p0,
                          const NcpSettings& s = {});
} // namespace damseis::contact
