// The contact problem of all pairs of the active joints, condensed onto
// the pair forces (algorithms.md 2.2): w = w_free + W p, W the pairs'
// dense flexibility. Solved as a nonlinear complementarity problem in the
// Alart-Curnier form (alart_curnier.h) by a damped semismooth Newton method
// (algorithms.md 2.5).
#pragma once

#include "alart_curnier.h"
#include <functional>
#include <string>
#include <vector>

namespace damseis::contact
{
struct ContactProblem
{
  std::vector<PairLaw> laws; ///< one per pair
  Eigen::MatrixXd W;         ///< 3n x 3n, symmetric positive definite
  /// W^-1, optional (empty: not used). With it the Newton direction d is
  /// found through z = W d: the rows of sticking pairs give their z at
  /// once, and the dense system couples only the rows of open and sliding
  /// pairs (small when most pairs stick); the line search moves w along z.
  Eigen::MatrixXd W_inv;
  Eigen::VectorXd w_free; ///< 3n: (w_n, w_a, w_b) per pair without force
  Eigen::VectorXd wT_old; ///< 2n: the tangential w of the last step
  Eigen::VectorXd g0;     ///< n: initial gaps (0: closed joints)
};

/// The NCP's unknowns and residual: the Cartesian Alart-Curnier form
/// (alart_curnier.h) or the paper's polar form (paper_ncp.h).
enum class Formulation
{
  alart_curnier,
  paper
};

struct NcpSettings
{
  double tol = 1e-10;      ///< |F| <= tol * force scale
  int max_iterations = 50; ///< Newton iterations
  /// Newton iterations taken even when the start meets tol (a start
  /// within tol is then polished to round-off): where the force scale
  /// overstates the forces, tol alone leaves displacement errors that
  /// accumulate (the static stage's proximal iteration).
  int min_iterations = 0;
  Formulation formulation = Formulation::alart_curnier;
};

struct NcpReport
{
  Eigen::VectorXd p, w; ///< pair forces and relative displacements (3n)
  std::vector<PairState> states;
  int iterations = 0;        ///< Newton iterations
  int line_search_steps = 0; ///< step halvings
  int gradient_steps = 0;    ///< fallbacks to the gradient direction
  int reduced_rows = 0;      ///< size of the last reduced system (W_inv)
  bool converged = false;
  double residual = 0.0; ///< |F| / force scale at the end
};

/// The residual of all pairs at the forces p (3n), with the relative
/// displacement w = w_free + W p, and the generalised Jacobian J = B + A W
/// (dense) if `J` is not null.
Eigen::VectorXd contact_residual(const ContactProblem& c,
                                 const Eigen::VectorXd& p, Eigen::VectorXd& w,
                                 std::vector<PairState>& states,
                                 Eigen::MatrixXd* J = nullptr);

/// Writes the problem and a starting point to a binary file, and reads it
/// back (for studying the solver on the problems of a real run:
/// DAMSEIS_DUMP_NCP=<prefix> in the joint contact; bench/ncp_replay).
void write_problem(const ContactProblem& c, const Eigen::VectorXd& p0,
                   const std::string& file);
ContactProblem read_problem(const std::string& file, Eigen::VectorXd& p0);

/// The force scale of the convergence test: the largest force that closes
/// a free gap or stops a free slip (r_n |g0 + w_free,n|, r_t |ds_free|),
/// a bond's strength, or the largest of p0; at least 1e-3 of r_n and r_t
/// times the total relative displacements (a round-off floor).
double force_scale(const ContactProblem& c, const Eigen::VectorXd& p0);

/// The forces with every pair closed and stuck (F = 0 on the stick branch:
/// the bonded joints' forces).
Eigen::VectorXd stuck_forces(const ContactProblem& c);

/// The two-start strategy of both formulations: `newton(true)` from the
/// warm start or `newton(false)` from the stuck forces, `warm_first`
/// deciding which first, the other only if the first fails; the report of
/// the converged run (or of the smaller residual) with the work of both.
NcpReport from_two_starts(bool warm_first,
                          const std::function<NcpReport(bool warm)>& newton);

/// Solves the contact problem from p0 (warm start: the last step's forces)
/// or from stuck_forces(), whichever has the smaller residual, then from
/// the other if Newton fails; the report counts both attempts. In the
/// formulation of `s` (the paper's: solve_ncp_paper of paper_ncp.h).
NcpReport solve_ncp(const ContactProblem& c, const Eigen::VectorXd& p0,
                    const NcpSettings& s = {});
} // namespace damseis::contact
