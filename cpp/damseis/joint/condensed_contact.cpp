#include "condensed_contact.h"
#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <damseis/dynamics/nonlinear_newmark.h>
#include <damseis/fem/tied_dofs.h>
#include <map>
#include <petscblaslapack.h>
#include <sstream>
#include <stdexcept>

namespace damseis::joint
{
namespace
{
double seconds_since(std::chrono::steady_clock::time_point t0)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0)
      .count();
}

extern "C" void dpocon_(const char* uplo, const int* n, const double* a,
                        const int* lda, const double* anorm, double* rcond,
                        double* work, int* iwork, int* info);

/// Below this reciprocal condition number (1-norm, LAPACK's estimate) a
/// Schur complement of the pairs (or W) is taken as singular: a block
/// whose rigid motions only its joints hold gives the S of K an eigenvalue
/// at round-off level, and potrf may or may not notice, depending on the
/// rounding of the parallel factorisation (measured: 1 run in 12 on 2
/// ranks did not). The matrices factorised are regular (K_eff, and K +
/// s M in the static stage): measured rcond 5e-7 (S) and 1e-6 (W) for the
/// sliding block's static stage, 2e-8 and 2e-10 for the bar test's,
/// 1e-3 and more in time stepping.
constexpr double singular_rcond = 1e-13;

/// Cholesky factorisation of the symmetric positive definite A in place
/// (lower triangle; LAPACK); throws NotPositiveDefinite if A is not
/// positive definite or is singular to round-off.
void cholesky(Eigen::MatrixXd& A)
{
  const PetscBLASInt n = static_cast<PetscBLASInt>(A.rows());
  const double norm_1 = A.cwiseAbs().colwise().sum().maxCoeff();
  PetscBLASInt info = 0;
  LAPACKpotrf_("L", &n, A.data(), &n, &info);
  if (info != 0)
  {
    throw NotPositiveDefinite(
        "the Schur complement of the joint pairs is not positive definite "
        "(LAPACK potrf info " +
        std::to_string(info) + ")");
  }
  double rcond = 0.0;
  std::vector<double> work(3 * static_cast<std::size_t>(n));
  std::vector<int> iwork(static_cast<std::size_t>(n));
  int m = n;
  dpocon_("L", &m, A.data(), &m, &norm_1, &rcond, work.data(), iwork.data(),
          &info);
  if (!(rcond > singular_rcond))
  {
    std::ostringstream msg;
    msg << "the Schur complement of the joint pairs is singular (reciprocal "
           "condition number "
        << rcond << ")";
    throw NotPositiveDefinite(msg.str());
  }
}

/// The symmetric positive definite A replaced by its inverse, both
/// triangles (LAPACK potrf with the singularity test of cholesky(), then
/// potri).
void invert_spd(Eigen::MatrixXd& A)
{
  cholesky(A);
  const PetscBLASInt n = static_cast<PetscBLASInt>(A.rows());
  PetscBLASInt info = 0;
  LAPACKpotri_("L", &n, A.data(), &n, &info);
  A.triangularView<Eigen::StrictlyUpper>() = A.transpose();
}

Eigen::MatrixXd spd_inverse(Eigen::MatrixXd A)
{
  invert_spd(A);
  return A;
}

extern "C" void dsymv_(const char* uplo, const int* n, const double* alpha,
                       const double* a, const int* lda, const double* x,
                       const int* incx, const double* beta, double* y,
                       const int* incy);

/// A x for the symmetric A (its lower triangle read: half the memory
/// traffic of a general product; BLAS).
Eigen::VectorXd symmetric_product(const Eigen::MatrixXd& A,
                                  const Eigen::VectorXd& x)
{
  Eigen::VectorXd y(x.size());
  const int n = static_cast<int>(A.rows()), one = 1;
  const double alpha = 1.0, beta = 0.0;
  dsymv_("L", &n, &alpha, A.data(), &n, x.data(), &one, &beta, y.data(), &one);
  return y;
}
/// The position of node `block`'s first unknown in `unknowns`, where its
/// 3 unknowns are appended when first seen (`position` remembers them).
int place(std::int64_t block, std::map<std::int64_t, int>& position,
          std::vector<PetscInt>& unknowns)
{
  auto [it, fresh] =
      position.try_emplace(block, static_cast<int>(unknowns.size()));
  if (fresh)
  {
    for (int k = 0; k < 3; ++k)
      unknowns.push_back(static_cast<PetscInt>(3 * block + k));
  }
  return it->second;
}
} // namespace

CondensedContact::CondensedContact(PairSet pairs, contact::NcpSettings ncp)
    : _pairs(std::move(pairs)), _ncp(ncp)
{
  const std::size_t n = _pairs.size();
  std::map<std::int64_t, int> position;
  for (std::size_t i = 0; i < n; ++i)
  {
    _pos1.push_back(place(_pairs.block1[i], position, _unknowns));
    _pos2.push_back(place(_pairs.block2[i], position, _unknowns));
  }
  _p = _w = Eigen::VectorXd::Zero(3 * n);
  _g0 = Eigen::VectorXd::Zero(n);
  for (std::size_t i = 0; i < n; ++i)
    _g0[i] = _pairs.joints[_pairs.joint[i]].initial_gap;
  _wT_ref = Eigen::VectorXd::Zero(2 * n);
  _states.assign(n, contact::PairState::stick);
  _broken.assign(n, 0);
  _committed = {_p, _w, _states, _broken};
}

CondensedContact::~CondensedContact()
{
  MatDestroy(&_T);
  MatDestroy(&_K_prime);
  VecDestroy(&_b_prime);
  VecDestroy(&_x_prime);
}

namespace
{
/// Whether a component of node `block` is fixed: a row of K with no
/// nonzero off the diagonal (the Dirichlet rows of the assembly). 0 for
/// rows this rank does not own.
int has_fixed_component(Mat K, std::int64_t block)
{
  PetscInt r0 = 0, r1 = 0;
  MatGetOwnershipRange(K, &r0, &r1);
  int fixed = 0;
  for (PetscInt row = 3 * block; row < 3 * block + 3; ++row)
  {
    if (row < r0 || row >= r1)
      continue;
    PetscInt ncols = 0;
    const PetscInt* cols = nullptr;
    const PetscScalar* vals = nullptr;
    MatGetRow(K, row, &ncols, &cols, &vals);
    bool coupled = false;
    for (PetscInt k = 0; k < ncols; ++k)
      coupled = coupled || (cols[k] != row && vals[k] != 0.0);
    MatRestoreRow(K, row, &ncols, &cols, &vals);
    fixed = fixed || !coupled;
  }
  return fixed;
}
} // namespace

void CondensedContact::choose_schur_unknowns(Mat K)
{
  const std::size_t n = _pairs.size();
  std::map<std::int64_t, int> uses;
  for (std::size_t i = 0; i < n; ++i)
  {
    ++uses[_pairs.block1[i]];
    ++uses[_pairs.block2[i]];
  }
  std::vector<int> fixed(2 * n);
  for (std::size_t i = 0; i < n; ++i)
  {
    fixed[2 * i] = has_fixed_component(K, _pairs.block1[i]);
    fixed[2 * i + 1] = has_fixed_component(K, _pairs.block2[i]);
  }
  MPI_Allreduce(MPI_IN_PLACE, fixed.data(), static_cast<int>(fixed.size()),
                MPI_INT, MPI_MAX, _comm);

  // The Schur unknowns: the relative displacement of a relative pair (in
  // its side-2 node's unknowns), both nodes of the others.
  std::vector<char> relative(n);
  std::map<std::int64_t, int> position;
  _all_relative = n > 0;
  for (std::size_t i = 0; i < n; ++i)
  {
    relative[i] = uses[_pairs.block1[i]] == 1 && uses[_pairs.block2[i]] == 1 &&
                  !fixed[2 * i] && !fixed[2 * i + 1];
    _all_relative = _all_relative && relative[i];
    _slot1.push_back(
        relative[i] ? -1 : place(_pairs.block1[i], position, _schur_unknowns));
    _slot2.push_back(place(_pairs.block2[i], position, _schur_unknowns));
  }
  if (std::none_of(relative.begin(), relative.end(),
                   [](char r) { return r != 0; }))
    return;

  // T: the identity, and u_b = u_a + r for the relative pairs (rows of b).
  PetscInt m = 0, N = 0, r0 = 0, r1 = 0;
  MatGetLocalSize(K, &m, nullptr);
  MatGetSize(K, &N, nullptr);
  MatGetOwnershipRange(K, &r0, &r1);
  MatCreateAIJ(_comm, m, m, N, N, 2, nullptr, 1, nullptr, &_T);
  for (PetscInt row = r0; row < r1; ++row)
    MatSetValue(_T, row, row, 1.0, INSERT_VALUES);
  for (std::size_t i = 0; i < n; ++i)
  {
    for (PetscInt k = 0; k < 3 && relative[i]; ++k)
    {
      const PetscInt row = static_cast<PetscInt>(3 * _pairs.block2[i] + k);
      if (row >= r0 && row < r1)
        MatSetValue(_T, row, static_cast<PetscInt>(3 * _pairs.block1[i] + k),
                    1.0, INSERT_VALUES);
    }
  }
  MatAssemblyBegin(_T, MAT_FINAL_ASSEMBLY);
  MatAssemblyEnd(_T, MAT_FINAL_ASSEMBLY);
  MatCreateVecs(K, &_x_prime, &_b_prime);
}

Eigen::VectorXd CondensedContact::relative(const Eigen::VectorXd& x_s) const
{
  const std::size_t n = _pairs.size();
  Eigen::VectorXd w(3 * n);
  for (std::size_t i = 0; i < n; ++i)
  {
    Eigen::Vector3d d = x_s.segment<3>(_slot2[i]);
    if (_slot1[i] >= 0)
      d -= x_s.segment<3>(_slot1[i]);
    w.segment<3>(3 * i) = _pairs.frame[i].transpose() * d;
  }
  return w;
}

Eigen::VectorXd CondensedContact::schur_forces(const Eigen::VectorXd& p) const
{
  Eigen::VectorXd f = Eigen::VectorXd::Zero(_schur_unknowns.size());
  for (std::size_t i = 0; i < _pairs.size(); ++i)
  {
    const Eigen::Vector3d fi = _pairs.frame[i] * p.segment<3>(3 * i);
    f.segment<3>(_slot2[i]) += fi;
    if (_slot1[i] >= 0)
      f.segment<3>(_slot1[i]) -= fi;
  }
  return f;
}

Eigen::VectorXd CondensedContact::pair_forces(const Eigen::VectorXd& p) const
{
  Eigen::VectorXd f = Eigen::VectorXd::Zero(_unknowns.size());
  for (std::size_t i = 0; i < _pairs.size(); ++i)
  {
    const Eigen::Vector3d fi = _pairs.frame[i] * p.segment<3>(3 * i);
    f.segment<3>(_pos2[i]) += fi;
    f.segment<3>(_pos1[i]) -= fi;
  }
  return f;
}

void CondensedContact::factorize(Mat K_eff)
{
  const auto t0 = std::chrono::steady_clock::now();
  _comm = PetscObjectComm(reinterpret_cast<PetscObject>(K_eff));
  MPI_Comm_rank(_comm, &_rank);
  if (_slot2.empty())
    choose_schur_unknowns(K_eff);
  Mat A = K_eff;
  if (_T)
  {
    MatDestroy(&_K_prime);
    _K_prime = fem::reduce_to_tied(K_eff, _T); // T^T K T
    A = _K_prime;
  }
  _schur.reset();
  _schur = std::make_unique<linalg::SchurSolver>(A, _schur_unknowns);
  const auto t1 = std::chrono::steady_clock::now();
  // S^-1 (Cholesky, then the inverse: a step then reads half of it twice,
  // less memory traffic than two triangular solves with the factor and a
  // product with S^-1 G); W = G^T S^-1 G pair by pair (rank 0; the outcome
  // to every rank).
  std::string failure;
  if (_rank == 0)
  {
    try
    {
      Eigen::MatrixXd S = _schur->take_schur_complement();
      _S_inv = _all_relative ? S : std::move(S);
      invert_spd(_S_inv);
      set_up_flexibility(S);
    }
    catch (const NotPositiveDefinite& e)
    {
      failure = e.what();
    }
  }
  int failed = failure.empty() ? 0 : 1;
  MPI_Bcast(&failed, 1, MPI_INT, 0, _comm);
  if (failed)
    throw NotPositiveDefinite(_rank == 0 ? failure
                                         : "the Schur complement of the joint "
                                           "pairs is not positive definite");
  _totals.seconds_setup += seconds_since(t1);
  _factor_seconds += seconds_since(t0);
}

void CondensedContact::set_up_flexibility(const Eigen::MatrixXd& S)
{
  const std::size_t n = _pairs.size();
  // W_ij = Q_i^T (S^-1[2i, 2j] - S^-1[2i, 1j] - S^-1[1i, 2j] + S^-1[1i, 1j])
  // Q_j, [a b] the 3 x 3 block of the unknowns a (of pair i) and b (of
  // pair j): 2 the side-2 node or the relative displacement, 1 the side-1
  // node (none for a relative pair).
  auto block = [&](int a, int b) -> Eigen::Matrix3d
  {
    if (a < 0 || b < 0)
      return Eigen::Matrix3d::Zero();
    return _S_inv.block<3, 3>(a, b);
  };
  Eigen::MatrixXd W(3 * n, 3 * n);
  for (std::size_t j = 0; j < n; ++j)
  {
    for (std::size_t i = j; i < n; ++i)
    {
      const Eigen::Matrix3d B =
          block(_slot2[i], _slot2[j]) - block(_slot2[i], _slot1[j]) -
          block(_slot1[i], _slot2[j]) + block(_slot1[i], _slot1[j]);
      const Eigen::Matrix3d Wij =
          _pairs.frame[i].transpose() * B * _pairs.frame[j];
      W.block<3, 3>(3 * i, 3 * j) = Wij;
      W.block<3, 3>(3 * j, 3 * i) = Wij.transpose();
    }
  }
  _problem.W = 0.5 * (W + W.transpose());
  // W^-1: Newton directions through z = W d, the dense system on the open
  // and sliding pairs' rows only (contact/ncp.h). With every pair relative,
  // W = Q^T S^-1 Q, so W^-1 = Q^T S Q (Q the pairs' frames).
  if (_all_relative)
  {
    Eigen::MatrixXd& Wi = _problem.W_inv;
    Wi.resize(3 * n, 3 * n);
    for (std::size_t j = 0; j < n; ++j)
    {
      for (std::size_t i = j; i < n; ++i)
      {
        const Eigen::Matrix3d Vij = _pairs.frame[i].transpose() *
                                    S.block<3, 3>(_slot2[i], _slot2[j]) *
                                    _pairs.frame[j];
        Wi.block<3, 3>(3 * i, 3 * j) = Vij;
        Wi.block<3, 3>(3 * j, 3 * i) = Vij.transpose();
      }
    }
  }
  else
    _problem.W_inv = spd_inverse(_problem.W);
  _problem.laws.clear();
  for (std::size_t i = 0; i < n; ++i)
  {
    contact::PairLaw law = _pairs.law(i);
    if (_broken[i])
      law.tension = law.cohesion = 0.0;
    law.r_n = 1.0 / _problem.W(3 * i, 3 * i);
    law.r_t = 2.0 / (_problem.W(3 * i + 1, 3 * i + 1) +
                     _problem.W(3 * i + 2, 3 * i + 2));
    _problem.laws.push_back(law);
  }
}

contact::NcpReport CondensedContact::solve_pairs(const Eigen::VectorXd& y,
                                                 Eigen::VectorXd& x_s)
{
  const Eigen::VectorXd x0 = symmetric_product(_S_inv, y);
  _problem.w_free = relative(x0);
  _problem.wT_old = _wT_ref;
  _problem.g0 = _g0;
  if (const char* dump = std::getenv("DAMSEIS_DUMP_NCP"))
  {
    // Every solve of the run in order, or every k-th with
    // DAMSEIS_DUMP_NCP_EVERY=k (a paper-scale problem takes ~300 MB).
    static int solves = 0;
    const char* every = std::getenv("DAMSEIS_DUMP_NCP_EVERY");
    const int k = every ? std::max(1, std::atoi(every)) : 1;
    if (solves % k == 0)
      contact::write_problem(_problem, _p,
                             std::string(dump) + "_" + std::to_string(solves) +
                                 ".bin");
    ++solves;
  }
  contact::NcpReport rep = contact::solve_ncp(_problem, _p, _ncp);
  while (rep.converged && break_failed_bonds(rep.states))
  {
    contact::NcpReport again = contact::solve_ncp(_problem, rep.p, _ncp);
    again.iterations += rep.iterations;
    again.line_search_steps += rep.line_search_steps;
    again.gradient_steps += rep.gradient_steps;
    rep = std::move(again);
  }
  // x0 + S^-1 G p: the pair displacements of x_s are then those of the
  // NCP's w = w_free + W p (W from the same S^-1) to round-off.
  x_s = x0 + symmetric_product(_S_inv, schur_forces(rep.p));
  return rep;
}

void CondensedContact::transformed_solve(
    Vec b, Vec x,
    const std::function<void(const Eigen::VectorXd&, Eigen::VectorXd&)>& middle)
{
  Vec b_solved = b, x_solved = x;
  if (_T)
  {
    MatMultTranspose(_T, b, _b_prime);
    b_solved = _b_prime;
    x_solved = _x_prime;
  }
  Eigen::VectorXd y, x_s;
  _schur->condense(b_solved, y);
  middle(y, x_s);
  _schur->expand(x_s, x_solved);
  if (_T)
    MatMult(_T, _x_prime, x);
}

bool CondensedContact::break_failed_bonds(
    const std::vector<contact::PairState>& states)
{
  bool any = false;
  for (std::size_t i = 0; i < states.size(); ++i)
  {
    contact::PairLaw& law = _problem.laws[i];
    if (contact::bond_failed(law, states[i]))
    {
      law.tension = law.cohesion = 0.0;
      _broken[i] = 1;
      any = true;
    }
  }
  return any;
}

void CondensedContact::solve(Vec rhs, Vec u, Vec r)
{
  solve_trial(rhs, u, r);
  commit();
}

void CondensedContact::commit()
{
  for (std::size_t i = 0; i < _states.size(); ++i)
  {
    _totals.state_changes += _states[i] != _committed.states[i];
    _totals.bonds_broken += _broken[i] && !_committed.broken[i];
    _wT_ref.segment<2>(2 * i) = _w.segment<2>(3 * i + 1);
  }
  _committed = {_p, _w, _states, _broken};
}

void CondensedContact::rollback()
{
  _p = _committed.p;
  _w = _committed.w;
  _states = _committed.states;
  reset_bonds();
}

void CondensedContact::reset_bonds()
{
  // Every pair intact in the committed state gets its law back, also one
  // whose bond a failed solve broke on rank 0 before it threw (_broken
  // not yet updated then).
  for (std::size_t i = 0; i < _broken.size(); ++i)
  {
    if (!_committed.broken[i] && i < _problem.laws.size())
    {
      const contact::PairLaw law = _pairs.law(i);
      _problem.laws[i].tension = law.tension;
      _problem.laws[i].cohesion = law.cohesion;
    }
  }
  _broken = _committed.broken;
}

void CondensedContact::force_vector(Vec r) const
{
  int rank = 0; // (the communicator's, also before factorize())
  MPI_Comm_rank(PetscObjectComm(reinterpret_cast<PetscObject>(r)), &rank);
  VecSet(r, 0.0);
  if (rank == 0)
  {
    const Eigen::VectorXd f = pair_forces(_p);
    VecSetValues(r, static_cast<PetscInt>(_unknowns.size()), _unknowns.data(),
                 f.data(), ADD_VALUES);
  }
  VecAssemblyBegin(r);
  VecAssemblyEnd(r);
}

void CondensedContact::set_trial(const Eigen::VectorXd& p,
                                 const Eigen::VectorXd& w)
{
  _p = p;
  _w = w;
}

void CondensedContact::solve_trial(Vec rhs, Vec u, Vec r)
{
  if (!_schur)
    throw std::logic_error("CondensedContact::solve before factorize");
  const std::size_t n = _pairs.size();
  const auto t0 = std::chrono::steady_clock::now();
  double seconds_contact = 0.0;
  auto pair_problem = [&](const Eigen::VectorXd& y, Eigen::VectorXd& x_s)
  {
    const auto t1 = std::chrono::steady_clock::now();
    // The pair problem on rank 0; its outcome to every rank.
    std::vector<double> outcome(3 * n * 2 + 2 * n + 6, 0.0);
    if (_rank == 0)
    {
      const contact::NcpReport rep = solve_pairs(y, x_s);
      Eigen::Map<Eigen::VectorXd>(outcome.data(), 3 * n) = rep.p;
      Eigen::Map<Eigen::VectorXd>(outcome.data() + 3 * n, 3 * n) = rep.w;
      for (std::size_t i = 0; i < n; ++i)
      {
        outcome[6 * n + i] = static_cast<double>(rep.states[i]);
        outcome[7 * n + i] = _broken[i];
      }
      double* tail = outcome.data() + 8 * n;
      tail[0] = rep.converged ? 1.0 : 0.0;
      tail[1] = rep.iterations;
      tail[2] = rep.line_search_steps;
      tail[3] = rep.gradient_steps;
      tail[4] = rep.residual;
    }
    MPI_Bcast(outcome.data(), static_cast<int>(outcome.size()), MPI_DOUBLE, 0,
              _comm);
    const double* tail = outcome.data() + 8 * n;
    _totals.ncp_iterations += static_cast<long>(tail[1]);
    _totals.line_search_steps += static_cast<long>(tail[2]);
    _totals.gradient_steps += static_cast<long>(tail[3]);
    if (tail[0] != 1.0)
    {
      std::ostringstream msg;
      msg << "the joint contact problem did not converge (" << n
          << " pairs, residual " << tail[4] << " after "
          << static_cast<int>(tail[1]) << " Newton iterations)";
      throw ContactFailure(msg.str());
    }
    _p = Eigen::Map<const Eigen::VectorXd>(outcome.data(), 3 * n);
    _w = Eigen::Map<const Eigen::VectorXd>(outcome.data() + 3 * n, 3 * n);
    for (std::size_t i = 0; i < n; ++i)
    {
      _states[i] = static_cast<contact::PairState>(outcome[6 * n + i]);
      _broken[i] = outcome[7 * n + i] != 0.0;
    }
    seconds_contact = seconds_since(t1);
  };
  transformed_solve(rhs, u, pair_problem);
  force_vector(r); // r = G p on the pair nodes' unknowns
  _totals.seconds_contact += seconds_contact;
  _totals.seconds_bulk += seconds_since(t0) - seconds_contact;
  ++_totals.solves;
}

void CondensedContact::solve_free(Vec rhs, Vec u)
{
  if (!_schur)
    throw std::logic_error("CondensedContact::solve_free before factorize");
  transformed_solve(rhs, u,
                    [&](const Eigen::VectorXd& y, Eigen::VectorXd& x_s)
                    {
                      if (_rank == 0)
                        x_s = symmetric_product(_S_inv, y);
                    });
}

Eigen::VectorXd CondensedContact::relative_of(Vec u) const
{
  // Not on the hot path: the pair unknowns gathered by value.
  std::vector<double> local(_unknowns.size(), 0.0);
  PetscInt lo = 0, hi = 0;
  VecGetOwnershipRange(u, &lo, &hi);
  const double* a = nullptr;
  VecGetArrayRead(u, &a);
  for (std::size_t k = 0; k < _unknowns.size(); ++k)
    if (_unknowns[k] >= lo && _unknowns[k] < hi)
      local[k] = a[_unknowns[k] - lo];
  VecRestoreArrayRead(u, &a);
  Eigen::VectorXd x_s(static_cast<Eigen::Index>(_unknowns.size()));
  MPI_Allreduce(local.data(), x_s.data(), static_cast<int>(local.size()),
                MPI_DOUBLE, MPI_SUM,
                PetscObjectComm(reinterpret_cast<PetscObject>(u)));
  // In the order of unknowns() (both nodes of every pair), not of S's.
  const std::size_t n = _pairs.size();
  Eigen::VectorXd w(3 * n);
  for (std::size_t i = 0; i < n; ++i)
  {
    w.segment<3>(3 * i) = _pairs.frame[i].transpose() *
                          (x_s.segment<3>(_pos2[i]) - x_s.segment<3>(_pos1[i]));
  }
  return w;
}

void CondensedContact::set_state(const Eigen::VectorXd& g0,
                                 const Eigen::VectorXd& w,
                                 const Eigen::VectorXd& p,
                                 const std::vector<contact::PairState>& states,
                                 const std::vector<char>& broken)
{
  const std::size_t n = _pairs.size();
  if (g0.size() != static_cast<Eigen::Index>(n) ||
      w.size() != static_cast<Eigen::Index>(3 * n) ||
      p.size() != static_cast<Eigen::Index>(3 * n) || states.size() != n ||
      (!broken.empty() && broken.size() != n))
    throw std::invalid_argument("CondensedContact::set_state: sizes");
  _g0 = g0;
  _w = w;
  _p = p;
  _states = states;
  _broken = broken.empty() ? std::vector<char>(n, 0) : broken;
  for (std::size_t i = 0; i < n; ++i)
  {
    _wT_ref.segment<2>(2 * i) = w.segment<2>(3 * i + 1);
    if (_broken[i] && i < _problem.laws.size()) // factorised already
      _problem.laws[i].tension = _problem.laws[i].cohesion = 0.0;
  }
  _committed = {_p, _w, _states, _broken};
}
} // namespace damseis::joint
