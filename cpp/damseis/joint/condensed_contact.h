// The contact of joint pairs on a linear bulk, condensed onto the pairs
// (algorithms.md 2.2): the effective matrix is factorised with the pair
// nodes' unknowns s kept as a dense Schur complement S (rank 0), so that
//   w = w_free + W p,   W = G^T S^-1 G   (3 NC x 3 NC, once per factorisation)
// and a step costs one ordinary solve (condense, the pair problem, expand)
// plus dense work on rank 0: the NCP of contact/ncp.h (Alart-Curnier,
// damped semismooth Newton) and two products with S^-1 (symmetric, half of it
// read).
//   G: the pair operator, w_i = Q_i^T (u_b - u_a), forces G p (+Q_i p_i on
//   side 2, -Q_i p_i on side 1).
#pragma once

#include "pairs.h"
#include <damseis/contact/ncp.h>
#include <damseis/dynamics/newmark.h>
#include <damseis/dynamics/nonlinear_newmark.h>
#include <damseis/linalg/schur_solver.h>
#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace damseis::joint
{
/// The Schur complement of the pairs is singular: a block has no support
/// but its joints (thrown by factorize()).
struct NotPositiveDefinite : std::runtime_error
{
  using std::runtime_error::runtime_error;
};

/// The joint contact problem of a step did not converge (a StepFailure:
/// the run stops rather than accept it); the message says what to try.
struct ContactFailure : dynamics::StepFailure
{
  using dynamics::StepFailure::StepFailure;
};

/// Work and events over the solves so far.
struct ContactTotals
{
  long solves = 0;
  long ncp_iterations = 0;
  long line_search_steps = 0;
  long gradient_steps = 0;
  long state_changes = 0;       ///< pairs whose state (open/stick/slip) changed
  long impacts = 0;             ///< pairs closing (impact corrections)
  double seconds_bulk = 0.0;    ///< condense + expand (the sparse solve)
  double seconds_contact = 0.0; ///< the dense pair problem on rank 0
  double seconds_impact = 0.0;
  double seconds_setup = 0.0; ///< S^-1, W (per factorisation)
};

class CondensedContact : public dynamics::ConstrainedSolve
{
public:
  /// `pairs` (with their laws); `g0`: initial gap of each pair (empty: 0,
  /// closed joints). The reference of the tangential slip is w_T = 0 until
  /// set_reference().
  explicit CondensedContact(PairSet pairs, contact::NcpSettings ncp = {});

  void factorize(Mat K_eff) override;
  /// Throws dynamics::StepFailure (on every rank) if the pair problem does
  /// not converge.
  void solve(Vec rhs, Vec u, Vec r) override;
  /// The solve with the pairs disconnected (no pair forces; collective);
  /// the pair state is left as it was.
  void solve_free(Vec rhs, Vec u);
  std::string name() const override { return "mumps-cholesky-schur"; }
  double factor_seconds() const override { return _factor_seconds; }

  const PairSet& pairs() const { return _pairs; }
  /// Pair forces p and relative displacements w (3 per pair: n, t_a, t_b)
  /// of the last solve, and the pair states; the same on every rank.
  const Eigen::VectorXd& forces() const { return _p; }
  const Eigen::VectorXd& relative_displacement() const { return _w; }
  const std::vector<contact::PairState>& states() const { return _states; }
  /// Gap g = g0 + w_n of pair i.
  double gap(std::size_t i) const { return _g0[i] + _w[3 * i]; }
  /// Sets the state the next solve starts from: the gaps' reference g0
  /// (g = g0 + w_n), the tangential displacement the slip is measured from,
  /// and the forces (warm start). Same on every rank.
  void set_state(const Eigen::VectorXd& g0, const Eigen::VectorXd& w,
                 const Eigen::VectorXd& p,
                 const std::vector<contact::PairState>& states);
  const Eigen::VectorXd& g0() const { return _g0; }
  /// The relative displacements w = G^T u of a displacement u, on every
  /// rank (collective).
  Eigen::VectorXd relative_of(Vec u) const;
  const ContactTotals& totals() const { return _totals; }
  ContactTotals& totals() { return _totals; }

  /// The global indices of the pair nodes' unknowns (3 per node, nodes in
  /// first-seen order of side 1, side 2 over the pairs): S's rows.
  const std::vector<PetscInt>& unknowns() const { return _unknowns; }
  /// For pair i, the positions in unknowns() of its side-1 and side-2
  /// nodes' first component.
  int position1(std::size_t i) const { return _pos1[i]; }
  int position2(std::size_t i) const { return _pos2[i]; }

private:
  /// W = G^T S^-1 G and the laws' scalings (rank 0).
  void set_up_flexibility();
  /// w = G^T x_s (rank 0).
  Eigen::VectorXd relative(const Eigen::VectorXd& x_s) const;
  /// G p on the Schur unknowns (rank 0).
  Eigen::VectorXd pair_forces(const Eigen::VectorXd& p) const;
  /// The pair problem on rank 0: p from y; returns the NCP's report.
  contact::NcpReport solve_pairs(const Eigen::VectorXd& y,
                                 Eigen::VectorXd& x_s);

  PairSet _pairs;
  contact::NcpSettings _ncp;
  std::vector<PetscInt> _unknowns;
  std::vector<int> _pos1, _pos2;
  std::unique_ptr<linalg::SchurSolver> _schur;
  Eigen::MatrixXd _S_inv;           ///< S^-1, both triangles (rank 0)
  contact::ContactProblem _problem; ///< W, laws (rank 0)
  Eigen::VectorXd _p, _w, _g0, _wT_ref;
  std::vector<contact::PairState> _states;
  ContactTotals _totals;
  double _factor_seconds = 0.0;
  MPI_Comm _comm = MPI_COMM_NULL;
  int _rank = 0;
};
} // namespace damseis::joint
