#include "static_contact.h"
#include <algorithm>
#include <cmath>
#include <damseis/linalg/duplicate_matrix.h>
#include <damseis/linalg/petsc_vectors.h>
#include <sstream>

namespace damseis::joint
{
namespace
{
/// The proximal-point iteration of one load F (static_contact.h), with the
/// pairs' contact (`solve`) or without (`free`); u holds the start and gets
/// the solution. Returns the iterations; throws ContactFailure when the
/// iterates stop converging (a rigid motion nobody holds).
template <typename Solve>
int relax(Mat M, double shift, Vec F, Vec u, const Solve& solve,
          const std::string& what, const std::string& advice)
{
  using dolfinx::la::petsc::Vector;
  Vector rhs = linalg::column_vector(M), u_old = linalg::column_vector(M);
  double change_old = 0.0;
  int slow = 0; // consecutive iterations that did not halve the change
  // The size the round-off of an iterate scales with: the displacements
  // in the solves, the start's among them (rhs = F + s M u_k), even when
  // the load nearly cancels them.
  double size = 0.0;
  VecNorm(u, NORM_INFINITY, &size);
  for (int k = 1; k <= static_max_iterations; ++k)
  {
    VecCopy(u, u_old.vec());
    MatMult(M, u, rhs.vec());
    VecAYPX(rhs.vec(), shift, F); // rhs = F + s M u_k
    try
    {
      solve(rhs.vec(), u);
    }
    catch (const ContactFailure& e)
    {
      throw ContactFailure(what + ": " + e.what() +
                           "; try more joints.static_increments");
    }
    VecAXPY(u_old.vec(), -1.0, u);
    double change = 0.0, size_k = 0.0;
    VecNorm(u_old.vec(), NORM_INFINITY, &change);
    VecNorm(u, NORM_INFINITY, &size_k);
    size = std::max(size, size_k);
    if (!std::isfinite(change))
      break;
    if (change <= static_tolerance * size)
      return k;
    // Elastic errors shrink 1000x per iteration; a rigid motion no joint
    // holds moves by the same amount each time (three iterations in a row:
    // pairs that open or slip between iterations may slow one or two).
    // Round-off stops the first at static_round_off.
    slow = k > 1 && change > 0.5 * change_old ? slow + 1 : 0;
    const bool stalled = slow >= 3;
    if (stalled && change <= static_round_off * size)
      return k;
    if (stalled)
    {
      std::ostringstream msg;
      msg << what << ": no static equilibrium (the displacement still "
          << "changes by " << change << " m per iteration after " << k << ")"
          << advice;
      throw ContactFailure(msg.str());
    }
    change_old = change;
  }
  throw ContactFailure(what + ": no static equilibrium (no convergence in " +
                       std::to_string(static_max_iterations) + " iterations)" +
                       advice);
}
} // namespace

StaticContactResult static_contact(Mat K, Mat M, double omega_1, Vec F_dead,
                                   Vec F_all, const PairSet& pairs,
                                   const StaticContactSettings& settings,
                                   contact::NcpSettings ncp)
{
  using dolfinx::la::petsc::Vector;
  // Under the small shift the free relative displacements of a block held
  // only by its joints are ~1/shift times the true ones, and so is the
  // NCP's force scale: a start within tol may still be off by tol times
  // those displacements, an error that each proximal iteration would
  // carry on. At least one Newton step polishes it to round-off (the
  // residual is piecewise linear in the forces).
  ncp.min_iterations = std::max(ncp.min_iterations, 1);
  StaticContactResult r;
  r.shift = static_shift_factor * omega_1 * omega_1;
  Mat Ks = linalg::duplicate_matrix(K, MAT_COPY_VALUES);
  MatAXPY(Ks, r.shift, M, SUBSET_NONZERO_PATTERN);
  dolfinx::la::petsc::Matrix K_shifted(Ks, false);
  CondensedContact c(pairs, ncp);
  c.factorize(K_shifted.mat());

  const std::size_t n = pairs.size();
  r.u = linalg::column_vector(K);
  Vector F = linalg::column_vector(K), force = linalg::column_vector(K);
  auto with_contact = [&](Vec rhs, Vec u) { c.solve(rhs, u, force.vec()); };

  auto increment = [&](double load_factor, const std::string& what)
  {
    // F = F_dead + factor (F_all - F_dead)
    VecCopy(F_dead, F.vec());
    VecScale(F.vec(), 1.0 - load_factor);
    VecAXPY(F.vec(), load_factor, F_all);
    r.iterations += relax(M, r.shift, F.vec(), r.u.vec(), with_contact, what,
                          "; a block slides or is not held");
  };

  if (settings.cantilever_dead_load)
  {
    // The blocks carry their own weight; the joints are closed (grouted)
    // in that state, with no force, or open by their initial gap: the
    // gaps' reference and the slips are measured from it.
    r.iterations += relax(
        M, r.shift, F_dead, r.u.vec(),
        [&](Vec rhs, Vec u) { c.solve_free(rhs, u); },
        "static stage, dead weight on the cantilevers",
        ": a block has no support but its joints, so it cannot carry its "
        "dead weight alone; use joints.dead_load = \"joints_active\"");
    close_joints_at(c, r.u.vec());
  }
  else
    increment(0.0, "static stage, dead weight");
  const int m = std::max(settings.increments, 1);
  for (int k = 1; k <= m; ++k)
    increment(static_cast<double>(k) / m, "static stage, load increment " +
                                              std::to_string(k) + "/" +
                                              std::to_string(m));
  StaticContactResult state = contact_state(c);
  state.u = std::move(r.u);
  state.shift = r.shift;
  state.iterations = r.iterations;
  return state;
}

StaticContactResult contact_state(const CondensedContact& c)
{
  StaticContactResult r;
  r.g0 = c.g0();
  r.w = c.relative_displacement();
  r.p = c.forces();
  r.states = c.states();
  r.broken = c.broken();
  r.totals = c.totals();
  return r;
}

void close_joints_at(CondensedContact& c, Vec u)
{
  const PairSet& pairs = c.pairs();
  const std::size_t n = pairs.size();
  const Eigen::VectorXd w = c.relative_of(u);
  Eigen::VectorXd g0(n);
  for (std::size_t i = 0; i < n; ++i)
    g0[i] = pairs.joints[pairs.joint[i]].initial_gap - w[3 * i];
  c.set_state(g0, w, Eigen::VectorXd::Zero(3 * n),
              std::vector<contact::PairState>(n, contact::PairState::stick));
}
} // namespace damseis::joint
