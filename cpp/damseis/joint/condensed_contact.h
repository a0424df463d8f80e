// The contact of joint pairs on a linear bulk, condensed onto the pairs
// (algorithms.md 2.2): the effective matrix is factorised with the pairs'
// unknowns s kept as a dense Schur complement S (rank 0), so that
//   w = w_free + W p,   W = G^T S^-1 G   (3 NC x 3 NC, once per factorisation)
// and a step costs one ordinary solve (condense, the pair problem, expand)
// plus dense work on rank 0: the NCP of contact/ncp.h (Alart-Curnier,
// damped semismooth Newton) and two products with S^-1 (symmetric, half of it
// read).
//   G: the pair operator, w_i = Q_i^T (u_b - u_a), forces G p (+Q_i p_i on
//   side 2, -Q_i p_i on side 1).
// The unknowns s: a pair whose two nodes are free and in no other pair is
// condensed on its relative displacement alone. The change of variables
// u = T u', u_b = u_a + r (T = I but for the identity blocks (b, a); K' =
// T^T K T) makes r = u'_b, so s holds 3 unknowns per pair instead of 6: S
// is 4 times smaller, its inverse is W itself but for the pair frames, and
// W^-1 needs no inversion. Other pairs (a node shared with another pair, or
// with a fixed component) keep both nodes' unknowns.
#pragma once

#include "pairs.h"
#include <algorithm>
#include <damseis/contact/ncp.h>
#include <damseis/dynamics/newmark.h>
#include <damseis/dynamics/nonlinear_newmark.h>
#include <damseis/linalg/schur_solver.h>
#include <functional>
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
  long bonds_broken = 0;        ///< bonded pairs whose bond failed
  double seconds_bulk = 0.0;    ///< condense + expand (the sparse solve)
  double seconds_contact = 0.0; ///< the dense pair problem on rank 0
  double seconds_impact = 0.0;
  double seconds_setup = 0.0; ///< S^-1, W (per factorisation)
};

class CondensedContact : public dynamics::ConstrainedSolve
{
public:
  /// `pairs` (with their laws); each pair's gap reference g0 is its
  /// joint's initial gap (g = g0 + w_n). The reference of the tangential
  /// slip is w_T = 0 until set_state().
  explicit CondensedContact(PairSet pairs, contact::NcpSettings ncp = {});
  ~CondensedContact();
  CondensedContact(const CondensedContact&) = delete;
  CondensedContact& operator=(const CondensedContact&) = delete;

  void factorize(Mat K_eff) override;
  /// Throws dynamics::StepFailure (on every rank) if the pair problem does
  /// not converge. The outcome is committed: the next solve measures the
  /// slip from it (a time step).
  void solve(Vec rhs, Vec u, Vec r) override;
  /// The solve without committing its outcome (an iterate of a step: the
  /// slip is measured from the committed state, and commit() or rollback()
  /// ends the step; collective).
  void solve_trial(Vec rhs, Vec u, Vec r);
  /// The last trial becomes the committed state (the slip's reference;
  /// the counts of state changes and broken bonds).
  void commit();
  /// Back to the committed forces, relative displacements, states and
  /// bonds.
  void rollback();
  /// Back to the committed bonds only (the bonds a trial broke are intact
  /// again: each iterate of a step decides anew which fail).
  void reset_bonds();
  /// Sets the trial forces and relative displacements (a line search
  /// between two trials; the states are those of the last solve).
  void set_trial(const Eigen::VectorXd& p, const Eigen::VectorXd& w);
  /// r = G p of the trial forces (collective).
  void force_vector(Vec r) const;
  /// The solve with the pairs disconnected (no pair forces; collective);
  /// the pair state is left as it was.
  void solve_free(Vec rhs, Vec u);
  std::string name() const override { return "mumps-cholesky-schur"; }
  /// The settings of the pair problem from the next solve on.
  void set_ncp(const contact::NcpSettings& ncp) { _ncp = ncp; }
  const contact::NcpSettings& ncp() const { return _ncp; }
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
  /// the forces (warm start) and the pairs whose bond has failed (empty:
  /// none). Same on every rank.
  void set_state(const Eigen::VectorXd& g0, const Eigen::VectorXd& w,
                 const Eigen::VectorXd& p,
                 const std::vector<contact::PairState>& states,
                 const std::vector<char>& broken = {});
  /// Per pair: 1 if its bond has failed (a bonded joint: it carries no
  /// tension and no cohesion since), else 0. Same on every rank.
  const std::vector<char>& broken() const { return _broken; }
  const Eigen::VectorXd& g0() const { return _g0; }
  /// The relative displacements w = G^T u of a displacement u, on every
  /// rank (collective).
  Eigen::VectorXd relative_of(Vec u) const;
  const ContactTotals& totals() const { return _totals; }
  ContactTotals& totals() { return _totals; }

  /// The global indices of the pair nodes' unknowns (3 per node, nodes in
  /// first-seen order of side 1, side 2 over the pairs).
  const std::vector<PetscInt>& unknowns() const { return _unknowns; }
  /// For pair i, the positions in unknowns() of its side-1 and side-2
  /// nodes' first component.
  int position1(std::size_t i) const { return _pos1[i]; }
  int position2(std::size_t i) const { return _pos2[i]; }
  /// The pairs condensed on their relative displacement alone (3 Schur
  /// unknowns instead of 6; after the first factorisation).
  std::size_t relative_pairs() const
  {
    return static_cast<std::size_t>(
        std::count(_slot1.begin(), _slot1.end(), -1));
  }

private:
  /// The Schur unknowns s and, if some pairs are condensed on their
  /// relative displacement, T (collective; at the first factorisation:
  /// fixed components are read from K's rows).
  void choose_schur_unknowns(Mat K);
  /// W = G^T S^-1 G (S^-1 in _S_inv), W^-1 (from S if every pair is
  /// relative, else by inversion) and the laws' scalings (rank 0).
  void set_up_flexibility(const Eigen::MatrixXd& S);
  /// w = G^T x_s, x_s on the Schur unknowns (rank 0).
  Eigen::VectorXd relative(const Eigen::VectorXd& x_s) const;
  /// G p on the Schur unknowns (rank 0).
  Eigen::VectorXd schur_forces(const Eigen::VectorXd& p) const;
  /// G p on unknowns() (rank 0).
  Eigen::VectorXd pair_forces(const Eigen::VectorXd& p) const;
  /// The solve of K' x' = T^T b, x = T x' (T = I: none), x' from
  /// `middle` (y on the Schur unknowns -> x_s).
  void transformed_solve(Vec b, Vec x,
                         const std::function<void(const Eigen::VectorXd&,
                                                  Eigen::VectorXd&)>& middle);
  /// The pair problem on rank 0: p from y; returns the NCP's report.
  /// Bonds that fail are broken and the problem solved again without them
  /// until none fails.
  contact::NcpReport solve_pairs(const Eigen::VectorXd& y,
                                 Eigen::VectorXd& x_s);
  /// Breaks the bonds that failed in `states` (rank 0); whether one did.
  bool break_failed_bonds(const std::vector<contact::PairState>& states);

  PairSet _pairs;
  contact::NcpSettings _ncp;
  std::vector<PetscInt> _unknowns;
  std::vector<int> _pos1, _pos2;
  /// The Schur unknowns, and pair i's positions in them: its relative
  /// displacement (relative pairs: _slot1 = -1) or its side-2 and side-1
  /// nodes.
  std::vector<PetscInt> _schur_unknowns;
  std::vector<int> _slot1, _slot2;
  bool _all_relative = false;
  Mat _T = nullptr;       ///< the change of variables (null: none)
  Mat _K_prime = nullptr; ///< T^T K T of the last factorisation
  Vec _b_prime = nullptr, _x_prime = nullptr;
  std::unique_ptr<linalg::SchurSolver> _schur;
  Eigen::MatrixXd _S_inv;           ///< S^-1, both triangles (rank 0)
  contact::ContactProblem _problem; ///< W, laws (rank 0)
  Eigen::VectorXd _p, _w, _g0, _wT_ref;
  std::vector<contact::PairState> _states;
  std::vector<char> _broken;
  /// The committed state (solve_trial's iterates start from it).
  struct Committed
  {
    Eigen::VectorXd p, w;
    std::vector<contact::PairState> states;
    std::vector<char> broken;
  } _committed;
  ContactTotals _totals;
  double _factor_seconds = 0.0;
  MPI_Comm _comm = MPI_COMM_NULL;
  int _rank = 0;
};
} // namespace damseis::joint
