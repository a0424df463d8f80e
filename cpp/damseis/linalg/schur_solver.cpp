#include "schur_solver.h"
#include <chrono>
#include <cmath>
#include <dmumps_c.h>
#include <limits>
#include <petscvec.h>
#include <stdexcept>
#include <string>
#include <vector>

namespace damseis::linalg
{
namespace
{
// MUMPS' control arrays are documented 1-based.
MUMPS_INT& icntl(DMUMPS_STRUC_C& id, int i)
{
  return id.icntl[i - 1];
}
int infog(const DMUMPS_STRUC_C& id, int i)
{
  return id.infog[i - 1];
}
} // namespace

struct SchurSolver::Mumps
{
  DMUMPS_STRUC_C id{};
  std::vector<MUMPS_INT> irn, jcn, listvar, perm;
  std::vector<double> a, schur, redrhs;
  std::vector<PetscInt> unknowns;
  VecScatter to_root = nullptr; ///< the distributed vector to b_seq on rank 0
  Vec b_seq = nullptr;          ///< the whole vector on rank 0, empty elsewhere
  int rank = 0;

  void call(int job, const char* what)
  {
    id.job = job;
    dmumps_c(&id);
    if (infog(id, 1) < 0)
    {
      throw std::runtime_error(
          std::string("MUMPS ") + what +
          " failed: INFOG(1) = " + std::to_string(infog(id, 1)) +
          ", INFOG(2) = " + std::to_string(infog(id, 2)));
    }
  }
  ~Mumps()
  {
    if (id.job != 0) // initialised
    {
      id.job = -2;
      dmumps_c(&id);
    }
    VecScatterDestroy(&to_root);
    VecDestroy(&b_seq);
  }
};

namespace
{
/// The upper triangle of the owned rows of A as 1-based triplets.
void upper_triplets(Mat A, std::vector<MUMPS_INT>& irn,
                    std::vector<MUMPS_INT>& jcn, std::vector<double>& a)
{
  PetscInt r0 = 0, r1 = 0;
  MatGetOwnershipRange(A, &r0, &r1);
  for (PetscInt i = r0; i < r1; ++i)
  {
    PetscInt ncols = 0;
    const PetscInt* cols = nullptr;
    const PetscScalar* vals = nullptr;
    MatGetRow(A, i, &ncols, &cols, &vals);
    for (PetscInt k = 0; k < ncols; ++k)
    {
      if (cols[k] < i)
        continue;
      irn.push_back(static_cast<MUMPS_INT>(i + 1));
      jcn.push_back(static_cast<MUMPS_INT>(cols[k] + 1));
      a.push_back(vals[k]);
    }
    MatRestoreRow(A, i, &ncols, &cols, &vals);
  }
}

/// The full symmetric matrix from MUMPS' array, one triangle of which is
/// filled (the other was set to NaN before).
Eigen::MatrixXd symmetric_from_triangle(const std::vector<double>& s, int n)
{
  Eigen::MatrixXd S(n, n);
  for (int i = 0; i < n; ++i)
  {
    for (int j = 0; j <= i; ++j)
    {
      const double lower = s[static_cast<std::size_t>(i) * n + j];
      const double upper = s[static_cast<std::size_t>(j) * n + i];
      const double v = std::isnan(lower) ? upper : lower;
      if (std::isnan(v))
        throw std::runtime_error(
            "MUMPS returned an incomplete Schur complement");
      S(i, j) = S(j, i) = v;
    }
  }
  return S;
}
} // namespace

SchurSolver::SchurSolver(Mat A, std::span<const PetscInt> schur)
    : _mumps(std::make_unique<Mumps>())
{
  const auto t0 = std::chrono::steady_clock::now();
  MPI_Comm comm = PetscObjectComm(reinterpret_cast<PetscObject>(A));
  Mumps& m = *_mumps;
  MPI_Comm_rank(comm, &m.rank);
  m.unknowns.assign(schur.begin(), schur.end());
  PetscInt N = 0;
  MatGetSize(A, &N, nullptr);
  for (PetscInt s : m.unknowns)
  {
    if (s < 0 || s >= N)
      throw std::invalid_argument("Schur unknown out of range");
  }

  DMUMPS_STRUC_C& id = m.id;
  id.comm_fortran = static_cast<MUMPS_INT>(MPI_Comm_c2f(comm));
  id.par = 1; // rank 0 works too
  id.sym = 1; // symmetric positive definite
  m.call(-1, "initialisation");
  for (int i : {1, 2, 3})
    icntl(id, i) = -1; // no output
  icntl(id, 4) = 0;
  icntl(id, 14) = 40; // workspace relaxation [%]
  icntl(id, 18) = 3;  // distributed assembled matrix
  icntl(id, 19) = 1;  // Schur complement centralised on rank 0

  upper_triplets(A, m.irn, m.jcn, m.a);
  id.n = static_cast<MUMPS_INT>(N);
  id.nnz_loc = static_cast<MUMPS_INT8>(m.a.size());
  id.irn_loc = m.irn.data();
  id.jcn_loc = m.jcn.data();
  id.a_loc = m.a.data();
  const int ns = static_cast<int>(m.unknowns.size());
  // The pivot order. With a Schur complement this MUMPS orders by AMD only
  // (PORD requests are replaced), which on the 3D arch dam gives 1.7x the
  // factor entries and 3x the flops; so the order comes from an analysis
  // without the Schur complement (PORD), the Schur unknowns moved last.
  m.call(1, "analysis for the pivot order");
  if (m.rank == 0)
  {
    std::vector<char> in_schur(static_cast<std::size_t>(N), 0);
    for (PetscInt s : m.unknowns)
      in_schur[s] = 1;
    std::vector<PetscInt> order(static_cast<std::size_t>(N));
    for (PetscInt i = 0; i < N; ++i)
      order[id.sym_perm[i] - 1] = i;
    m.perm.assign(static_cast<std::size_t>(N), 0);
    MUMPS_INT next = 1;
    for (PetscInt i : order)
      if (!in_schur[i])
        m.perm[i] = next++;
    for (PetscInt s : m.unknowns)
      m.perm[s] = next++;
    id.perm_in = m.perm.data();
  }
  icntl(id, 7) = 1;
  id.size_schur = ns;
  if (m.rank == 0)
  {
    for (PetscInt s : m.unknowns)
      m.listvar.push_back(static_cast<MUMPS_INT>(s + 1));
    m.schur.assign(static_cast<std::size_t>(ns) * ns,
                   std::numeric_limits<double>::quiet_NaN());
    m.redrhs.assign(ns, 0.0);
    id.listvar_schur = m.listvar.data();
    id.schur = m.schur.data();
    id.schur_lld = ns;
  }
  m.call(4, "analysis and factorisation");
  if (m.rank == 0)
    _S = symmetric_from_triangle(m.schur, ns);
  m.schur = std::vector<double>(); // the copy in _S is kept

  Vec b;
  MatCreateVecs(A, nullptr, &b);
  VecScatterCreateToZero(b, &m.to_root, &m.b_seq);
  VecDestroy(&b);
  _factor_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0)
          .count();
}

SchurSolver::~SchurSolver() = default;

std::span<const PetscInt> SchurSolver::unknowns() const
{
  return _mumps->unknowns;
}

void SchurSolver::condense(Vec b, Eigen::VectorXd& y)
{
  Mumps& m = *_mumps;
  VecScatterBegin(m.to_root, b, m.b_seq, INSERT_VALUES, SCATTER_FORWARD);
  VecScatterEnd(m.to_root, b, m.b_seq, INSERT_VALUES, SCATTER_FORWARD);
  double* rhs = nullptr;
  VecGetArray(m.b_seq, &rhs);
  m.id.rhs = rhs;
  m.id.nrhs = 1;
  m.id.lrhs = m.id.n;
  m.id.redrhs = m.redrhs.data();
  m.id.lredrhs = m.id.size_schur;
  icntl(m.id, 20) = 0; // dense right-hand side on rank 0
  icntl(m.id, 21) = 0; // solution on rank 0
  icntl(m.id, 26) = 1; // condensation
  m.call(3, "condensation");
  VecRestoreArray(m.b_seq, &rhs);
  if (m.rank == 0)
    y = Eigen::Map<const Eigen::VectorXd>(m.redrhs.data(), m.id.size_schur);
  else
    y.resize(0);
}

void SchurSolver::expand(const Eigen::VectorXd& x_s, Vec x)
{
  Mumps& m = *_mumps;
  if (m.rank == 0)
  {
    if (x_s.size() != m.id.size_schur)
      throw std::invalid_argument("expand: x_s has the wrong size");
    Eigen::Map<Eigen::VectorXd>(m.redrhs.data(), m.id.size_schur) = x_s;
  }
  double* rhs = nullptr;
  VecGetArray(m.b_seq, &rhs);
  m.id.rhs = rhs;
  m.id.redrhs = m.redrhs.data();
  icntl(m.id, 26) = 2; // expansion
  m.call(3, "expansion");
  VecRestoreArray(m.b_seq, &rhs);
  VecScatterBegin(m.to_root, m.b_seq, x, INSERT_VALUES, SCATTER_REVERSE);
  VecScatterEnd(m.to_root, m.b_seq, x, INSERT_VALUES, SCATTER_REVERSE);
}
} // namespace damseis::linalg
