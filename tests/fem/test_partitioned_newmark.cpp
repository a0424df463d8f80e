// Verification of the Hughes-Liu implicit-explicit partition
// (damseis/dynamics/partitioned_newmark.h) on a fixed-free bar of linear
// elements (E = rho = A = 1, c = 1, element length h = 1), its first half
// implicit (consistent mass), its second half explicit (lumped mass).
//
// References (none calls the library):
//  * the stability limit of the explicit group: for gamma = 1/2 (beta 0 or
//    1/4) the one-degree-of-freedom predictor-corrector is stable for
//    omega dt <= 2 (Hughes & Liu 1978; Hughes, The Finite Element Method,
//    1987, sec. 9.3 and 8.3); a lumped linear bar element has omega_max =
//    2 c / h, so dt_crit = h / c (Courant number 1);
//  * with no explicit elements the partition is Newmark's average
//    acceleration, which LinearNewmark integrates independently;
//  * the nonlinear integrator's partition (NonlinearNewmark::set_partition)
//    on a linear system is the same algorithm as PartitionedNewmark, which
//    integrates it independently (acceleration form, one solve per step);
//  * without explicit elements that partition takes HHT alpha: the
//    Hilber-Hughes-Taylor equation (Hilber, Hughes & Taylor 1977)
//      M a' + (1 + alpha)(C v' + K u') - alpha (C v + K u)
//        = (1 + alpha) f' - alpha f
//    at the free unknowns, the prescribed one's v and a from Newmark's
//    relations, integrated here on the dense matrices (Eigen).
// The matrices live on PETSC_COMM_SELF: under mpirun every rank runs its
// own serial copy.
#include <damseis/dynamics/newmark.h>
#include <damseis/dynamics/nonlinear_newmark.h>
#include <damseis/dynamics/partitioned_newmark.h>

#include <Eigen/Dense>
#include <cmath>
#include <cstdio>
#include <gtest/gtest.h>
#include <petscmat.h>
#include <random>
#include <vector>

namespace
{
using damseis::dynamics::PartitionedNewmark;
using damseis::dynamics::RayleighDamping;

struct Bar
{
  Mat K = nullptr, K_implicit = nullptr, M = nullptr;
  int n = 0; ///< nodes (node 0 fixed)
  ~Bar()
  {
    MatDestroy(&K);
    MatDestroy(&K_implicit);
    MatDestroy(&M);
  }
};

/// A bar of `elements` elements, the first `implicit` of them implicit.
void make_bar(Bar& bar, int elements, int implicit)
{
  const int n = elements + 1;
  bar.n = n;
  for (Mat* A : {&bar.K, &bar.K_implicit, &bar.M})
  {
    MatCreateSeqAIJ(PETSC_COMM_SELF, n, n, 3, nullptr, A);
    MatSetOption(*A, MAT_NEW_NONZERO_ALLOCATION_ERR, PETSC_FALSE);
  }
  for (int e = 0; e < elements; ++e)
  {
    const PetscInt idx[2] = {e, e + 1};
    const double k[4] = {1, -1, -1, 1};
    const double m_consistent[4] = {1.0 / 3, 1.0 / 6, 1.0 / 6, 1.0 / 3};
    const double m_lumped[4] = {0.5, 0, 0, 0.5};
    MatSetValues(bar.K, 2, idx, 2, idx, k, ADD_VALUES);
    if (e < implicit)
    {
      MatSetValues(bar.K_implicit, 2, idx, 2, idx, k, ADD_VALUES);
      MatSetValues(bar.M, 2, idx, 2, idx, m_consistent, ADD_VALUES);
    }
    else
      MatSetValues(bar.M, 2, idx, 2, idx, m_lumped, ADD_VALUES);
  }
  for (Mat A : {bar.K, bar.K_implicit, bar.M})
  {
    for (PetscInt i = 0; i < n; ++i) // keep every diagonal in the pattern
      MatSetValue(A, i, i, 0.0, ADD_VALUES);
    MatAssemblyBegin(A, MAT_FINAL_ASSEMBLY);
    MatAssemblyEnd(A, MAT_FINAL_ASSEMBLY);
  }
  // Node 0 fixed: identity rows of K, zero rows of M.
  const PetscInt fixed = 0;
  MatZeroRowsColumns(bar.K, 1, &fixed, 1.0, nullptr, nullptr);
  MatZeroRowsColumns(bar.K_implicit, 1, &fixed, 1.0, nullptr, nullptr);
  MatZeroRowsColumns(bar.M, 1, &fixed, 0.0, nullptr, nullptr);
}

/// The largest total energy (kinetic + strain) over the second half of
/// `steps` free-vibration steps from a random displacement, relative to
/// the largest over the first half (infinite if it overflows). The
/// explicit group conserves a nearby energy, not this one, so this one
/// oscillates (by up to 1 / (1 - (omega dt / 2)^2) in the highest modes);
/// a stable run does not grow.
double energy_growth(const Bar& bar, double dt, int steps,
                     RayleighDamping damping = {}, double b_explicit = 0.0)
{
  PartitionedNewmark newmark(bar.M, bar.K, bar.K_implicit, damping, dt,
                             damseis::linalg::Factorization::petsc, nullptr,
                             b_explicit);
  Vec u, zero;
  MatCreateVecs(bar.K, &u, nullptr);
  VecDuplicate(u, &zero);
  VecSet(zero, 0.0);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> r(-1.0, 1.0);
  for (PetscInt i = 1; i < bar.n; ++i)
    VecSetValue(u, i, r(rng), INSERT_VALUES);
  VecSetValue(u, 0, 0.0, INSERT_VALUES);
  VecAssemblyBegin(u);
  VecAssemblyEnd(u);
  // The acceleration of the state: M a = -K u (M singular only at node 0).
  Vec a, Ku;
  VecDuplicate(u, &a);
  VecDuplicate(u, &Ku);
  MatMult(bar.K, u, Ku);
  VecScale(Ku, -1.0);
  VecSetValue(Ku, 0, 0.0, INSERT_VALUES);
  VecAssemblyBegin(Ku);
  VecAssemblyEnd(Ku);
  {
    Mat M1;
    MatDuplicate(bar.M, MAT_COPY_VALUES, &M1);
    MatSetValue(M1, 0, 0, 1.0, INSERT_VALUES);
    MatAssemblyBegin(M1, MAT_FINAL_ASSEMBLY);
    MatAssemblyEnd(M1, MAT_FINAL_ASSEMBLY);
    damseis::linalg::DirectSolver s(PETSC_COMM_SELF,
                                    damseis::linalg::Factorization::petsc);
    s.factorize_lu(M1);
    s.solve(Ku, a);
    MatDestroy(&M1);
  }
  newmark.set_state(u, zero, a, zero, {}, 0);
  const double e0 = newmark.energy().kinetic + newmark.energy().strain;
  double largest[2] = {e0, 0.0};
  for (int k = 0; k < steps; ++k)
  {
    newmark.step(zero);
    const double e = newmark.energy().kinetic + newmark.energy().strain;
    double& l = largest[2 * k < steps ? 0 : 1];
    l = std::max(l, e);
    if (!std::isfinite(e) || e > 1e12 * e0)
      return std::numeric_limits<double>::infinity();
  }
  for (Vec* v : {&u, &zero, &a, &Ku})
    VecDestroy(v);
  return largest[1] / largest[0];
}
/// The lumped mass (h = 1: 1/2 at each end) of the bar's elements first
/// to last - 1 (the explicit ones), zero elsewhere. The caller destroys it.
Vec explicit_lumped_mass(const Bar& bar, int first, int last)
{
  Vec D;
  MatCreateVecs(bar.K, &D, nullptr);
  VecSet(D, 0.0);
  for (int e = first; e < last; ++e)
  {
    VecSetValue(D, e, 0.5, ADD_VALUES);
    VecSetValue(D, e + 1, 0.5, ADD_VALUES);
  }
  VecAssemblyBegin(D);
  VecAssemblyEnd(D);
  return D;
}
} // namespace

TEST(PartitionedNewmark, StableStepIsTwoOverOmegaUndamped)
{
  // Omega_crit = 2 for gamma = 1/2 (Hughes & Liu 1978).
  for (double w : {1.0, 37.0, 2.0e3})
    EXPECT_NEAR(damseis::dynamics::explicit_stable_step(w, {}) * w, 2.0, 1e-9);
  // Mass-proportional damping (implicit) does not lower it; explicit
  // stiffness-proportional damping does, monotonically.
  const double w = 100.0;
  EXPECT_GE(damseis::dynamics::explicit_stable_step(w, {5.0, 0.0}) * w,
            2.0 - 1e-9);
  double last = 2.0;
  for (double xi : {0.05, 0.2, 0.5})
  {
    const double ratio =
        damseis::dynamics::explicit_stable_step(w, {0.0, 2.0 * xi / w}) * w;
    EXPECT_LT(ratio, last);
    last = ratio;
  }
}

TEST(PartitionedNewmark, BarIsStableBelowCourantOneAndUnstableAbove)
{
  // 20 implicit + 20 explicit elements, h = c = 1: dt_crit = 1 (element
  // theory); the assembled explicit group's highest frequency is a little
  // below 2 c / h, so the run is unstable clearly above 1.
  Bar bar;
  make_bar(bar, 40, 20);
  // Below the limit the energy does not grow (the second 10,000 steps'
  // peak within 1 % of the first's).
  for (double dt : {0.5, 0.9, 0.98})
    EXPECT_LT(energy_growth(bar, dt, 20000), 1.01) << "dt = " << dt;
  // Above it the energy grows without bound.
  EXPECT_GT(energy_growth(bar, 1.05, 20000), 1e6);
}

TEST(PartitionedNewmark, ExplicitStiffnessDampingLowersTheStableStep)
{
  // The explicit elements' own damping b_E K_E on the predicted velocity:
  // central differences with stiffness damping xi at omega_max are stable
  // for omega_max dt <= 2 (sqrt(1 + xi^2) - xi) (Belytschko, Liu & Moran,
  // Nonlinear Finite Elements, 2000, eq. 6.3.21). The bar's explicit
  // group, xi = 0.3 at its highest frequency: stable at 0.98 of that step,
  // unstable at 1.05 of it (which is stable without the damping: its
  // undamped limit is 1.35 times higher).
  Bar bar;
  make_bar(bar, 40, 20);
  Vec lumped = explicit_lumped_mass(bar, 20, 40);
  const double w = damseis::dynamics::highest_explicit_frequency(
      bar.K, bar.K_implicit, lumped, {});
  VecDestroy(&lumped);
  const double xi = 0.3, b_e = 2 * xi / w;
  const double limit = 2 * (std::sqrt(1 + xi * xi) - xi) / w;
  EXPECT_NEAR(damseis::dynamics::explicit_stable_step(w, {0.0, b_e}), limit,
              1e-6 * limit);
  EXPECT_LT(energy_growth(bar, 0.98 * limit, 20000, {}, b_e), 1.01);
  EXPECT_GT(energy_growth(bar, 1.05 * limit, 20000, {}, b_e), 1e6);
  EXPECT_LT(energy_growth(bar, 1.05 * limit, 20000), 1.1); // 1.0103
}

TEST(PartitionedNewmark, HighestExplicitFrequencyOfTheBar)
{
  // The explicit half of the bar (20 lumped elements, its inner end tied
  // to the implicit half, its outer end free): the chain's highest
  // frequency lies just below the element's 2 c / h (within 1 %: the
  // free-fixed lumped chain of n elements has 2 sin((2n - 1) pi /
  // (4n)) = 2 - O(1/n^2)).
  Bar bar;
  make_bar(bar, 40, 20);
  Vec D = explicit_lumped_mass(bar, 20, 40);
  const double w = damseis::dynamics::highest_explicit_frequency(
      bar.K, bar.K_implicit, D, {});
  EXPECT_GT(w, 1.98);
  EXPECT_LE(w, 2.0 + 1e-12);
  // The same eigenproblem solved densely (Eigen, all eigenvalues of
  // D^-1/2 K_E D^-1/2 on the unknowns with D > 0): the frequency is
  // converged (1e-9; the power iteration it replaced stopped at a 1e-7
  // change of its Rayleigh quotient, which left it up to 1.9e-5 low and
  // dependent on the dof numbering).
  {
    std::vector<int> rows;
    const double* d = nullptr;
    VecGetArrayRead(D, &d);
    for (int i = 0; i < bar.n; ++i)
      if (d[i] > 0.0)
        rows.push_back(i);
    Eigen::MatrixXd A(rows.size(), rows.size());
    for (std::size_t r = 0; r < rows.size(); ++r)
      for (std::size_t c = 0; c < rows.size(); ++c)
      {
        double k = 0.0, k_implicit = 0.0;
        MatGetValues(bar.K, 1, &rows[r], 1, &rows[c], &k);
        MatGetValues(bar.K_implicit, 1, &rows[r], 1, &rows[c], &k_implicit);
        A(r, c) = (k - k_implicit) / std::sqrt(d[rows[r]] * d[rows[c]]);
      }
    VecRestoreArrayRead(D, &d);
    const double reference =
        std::sqrt(Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(A)
                      .eigenvalues()
                      .maxCoeff());
    EXPECT_NEAR(w, reference, 1e-9 * reference);
  }
  // Without explicit unknowns (no lumped mass): 0, and no step limit.
  VecSet(D, 0.0);
  EXPECT_EQ(damseis::dynamics::highest_explicit_frequency(bar.K, bar.K_implicit,
                                                          D, {}),
            0.0);
  EXPECT_TRUE(std::isinf(damseis::dynamics::explicit_stable_step(0.0, {})));
  VecDestroy(&D);
}

TEST(PartitionedNewmark, WithoutExplicitElementsItIsNewmark)
{
  // All elements implicit: the partition is Newmark's average
  // acceleration with C = a_M M + b_K K, as LinearNewmark (displacement
  // form) integrates it; a load ramp at the free end.
  Bar bar;
  make_bar(bar, 12, 12);
  const RayleighDamping damping{0.3, 0.002};
  const double dt = 0.05;
  PartitionedNewmark p(bar.M, bar.K, bar.K_implicit, damping, dt,
                       damseis::linalg::Factorization::petsc);
  damseis::dynamics::LinearNewmark l(bar.M, bar.K, damping, {dt, 0.0},
                                     damseis::linalg::Factorization::petsc);
  Vec zero, f;
  MatCreateVecs(bar.K, &zero, nullptr);
  VecDuplicate(zero, &f);
  VecSet(zero, 0.0);
  p.set_state(zero, zero, zero, zero, {}, 0);
  l.set_state(zero, zero, zero, zero);
  for (int k = 1; k <= 300; ++k)
  {
    VecSet(f, 0.0);
    VecSetValue(f, bar.n - 1, std::sin(0.1 * k), INSERT_VALUES);
    VecAssemblyBegin(f);
    VecAssemblyEnd(f);
    p.step(f);
    l.step(f);
  }
  double du = 0.0, u = 0.0;
  VecNorm(l.u(), NORM_INFINITY, &u);
  VecWAXPY(f, -1.0, p.u(), l.u());
  VecNorm(f, NORM_INFINITY, &du);
  EXPECT_GT(u, 1e-3);
  EXPECT_LT(du, 1e-10 * u);
  // The energy balance closes for the trapezoidal rule.
  const auto& e = p.energy();
  EXPECT_LT(std::abs(e.error()), 1e-10 * e.external_work);
  VecDestroy(&zero);
  VecDestroy(&f);
}

namespace
{
/// f_int = K u: the bar as a nonlinear system.
class LinearBar : public damseis::dynamics::NonlinearSystem
{
public:
  explicit LinearBar(Mat K) : _K(K) { MatCreateVecs(K, &_u, nullptr); }
  ~LinearBar() override { VecDestroy(&_u); }
  bool trial(Vec u, double) override
  {
    VecCopy(u, _u);
    return true;
  }
  void internal_force(Vec f) override { MatMult(_K, _u, f); }
  void add_tangent_change(Mat A, double) override
  {
    MatAssemblyBegin(A, MAT_FINAL_ASSEMBLY);
    MatAssemblyEnd(A, MAT_FINAL_ASSEMBLY);
  }
  bool accept() override { return true; }
  bool tangent_is_initial() const override { return true; }

private:
  Mat _K;
  Vec _u = nullptr;
};

/// The bar's free end moves as 0.3 sin(0.7 t) (its node explicit alone).
class EndMotion : public damseis::dynamics::PrescribedMotion
{
public:
  EndMotion(PetscInt row, double dt) : _rows{row}, _dt(dt) {}
  const std::vector<PetscInt>& rows() const override { return _rows; }
  void values(int n_next, const damseis::dynamics::Kinematics&,
              const damseis::dynamics::Kinematics&,
              damseis::dynamics::PrescribedValues& out) override
  {
    const double t = n_next * _dt;
    out.u[0] = 0.3 * std::sin(0.7 * t);
    out.v[0] = 0.3 * 0.7 * std::cos(0.7 * t);
    out.a[0] = -0.3 * 0.49 * std::sin(0.7 * t);
  }

private:
  std::vector<PetscInt> _rows;
  double _dt;
};
} // namespace

TEST(PartitionedNewmark, NonlinearIntegratorsPartitionIsTheSame)
{
  // 10 implicit + 10 explicit elements, Rayleigh damping (its stiffness
  // part on the implicit elements) and the explicit elements' own
  // stiffness damping, a load at mid-length and the free end
  // prescribed: NonlinearNewmark with the partition (Newton on u, the
  // explicit force at the predictor) against PartitionedNewmark.
  Bar bar;
  make_bar(bar, 20, 10);
  const RayleighDamping damping{0.4, 0.003};
  const double dt = 0.5; // below the explicit limit dt = h / c = 1
  Mat K_E;
  MatDuplicate(bar.K, MAT_COPY_VALUES, &K_E);
  MatAXPY(K_E, -1.0, bar.K_implicit, DIFFERENT_NONZERO_PATTERN);
  const PetscInt end = bar.n - 1;
  auto motion = std::make_shared<EndMotion>(end, dt);
  // The explicit elements damped too: 5 % at the highest frequency (2).
  const double b_e = 0.05;
  PartitionedNewmark p(bar.M, bar.K, bar.K_implicit, damping, dt,
                       damseis::linalg::Factorization::petsc, motion, b_e);
  LinearBar system(bar.K);
  damseis::dynamics::NonlinearNewmark n(bar.M, bar.K, damping, {dt, 0.0},
                                        system, {},
                                        damseis::linalg::Factorization::petsc);
  n.set_partition({bar.K_implicit, K_E, motion, b_e});
  Vec zero, f;
  MatCreateVecs(bar.K, &zero, nullptr);
  VecDuplicate(zero, &f);
  VecSet(zero, 0.0);
  p.set_state(zero, zero, zero, zero, {}, 0);
  n.set_state(zero, zero, zero, zero, zero);
  double u_max = 0.0, du_max = 0.0, dv_max = 0.0;
  for (int k = 1; k <= 200; ++k)
  {
    VecSet(f, 0.0);
    VecSetValue(f, 5, 0.2 * std::cos(0.3 * k * dt), INSERT_VALUES);
    VecAssemblyBegin(f);
    VecAssemblyEnd(f);
    p.step(f);
    n.step(f);
    double x = 0.0;
    VecNorm(p.u(), NORM_INFINITY, &x);
    u_max = std::max(u_max, x);
    VecWAXPY(zero, -1.0, p.u(), n.u());
    VecNorm(zero, NORM_INFINITY, &x);
    du_max = std::max(du_max, x);
    VecWAXPY(zero, -1.0, p.v(), n.v());
    VecNorm(zero, NORM_INFINITY, &x);
    dv_max = std::max(dv_max, x);
  }
  // The end follows its motion; both integrators agree to the Newton
  // tolerance (||R|| <= 1e-6 ||F||, linear here: one direction is exact,
  // so round-off).
  double u_end = 0.0;
  VecGetValues(n.u(), 1, &end, &u_end);
  EXPECT_NEAR(u_end, 0.3 * std::sin(0.7 * 200 * dt), 1e-14);
  EXPECT_GT(u_max, 0.1);
  EXPECT_LT(du_max, 1e-9 * u_max);
  EXPECT_LT(dv_max, 1e-9 * u_max);
  VecDestroy(&zero);
  VecDestroy(&f);
  MatDestroy(&K_E);
}

namespace
{
/// The dense copy of a small sequential matrix.
Eigen::MatrixXd dense(Mat A)
{
  PetscInt n = 0;
  MatGetSize(A, &n, nullptr);
  Eigen::MatrixXd D = Eigen::MatrixXd::Zero(n, n);
  for (PetscInt i = 0; i < n; ++i)
    for (PetscInt j = 0; j < n; ++j)
      MatGetValues(A, 1, &i, 1, &j, &D(i, j));
  return D;
}
} // namespace

namespace
{
/// All 20 elements implicit (consistent mass: the prescribed end couples
/// to its neighbour through M, C and K), Rayleigh damping, a load at
/// mid-length, the free end prescribed (its motion starts with a
/// velocity: Newmark's relations on its displacement alone would start
/// the alternating mode), HHT alpha: NonlinearNewmark with the partition
/// (K_explicit null), and at alpha = 0 PartitionedNewmark, against the
/// HHT equation on the dense matrices (the end's u, v and a from the
/// motion, the other unknowns solved).
void implicit_band_against_dense(double alpha)
{
  Bar bar;
  make_bar(bar, 20, 20);
  const RayleighDamping damping{0.4, 0.003};
  const double dt = 0.5;
  const damseis::dynamics::TimeScheme scheme{dt, alpha};
  const double beta = scheme.beta(), gamma = scheme.gamma();
  const PetscInt end = bar.n - 1;
  auto motion = std::make_shared<EndMotion>(end, dt);
  LinearBar system(bar.K);
  int iterations = 0;
  damseis::dynamics::NewtonSettings settings;
  settings.monitor = [&](int it, double)
  { iterations = std::max(iterations, it); };
  damseis::dynamics::NonlinearNewmark n(bar.M, bar.K, damping, scheme, system,
                                        settings,
                                        damseis::linalg::Factorization::petsc);
  n.set_partition({bar.K_implicit, nullptr, motion, 0.0});
  Vec zero, f;
  MatCreateVecs(bar.K, &zero, nullptr);
  VecDuplicate(zero, &f);
  VecSet(zero, 0.0);
  n.set_state(zero, zero, zero, zero, zero);
  std::unique_ptr<PartitionedNewmark> p;
  if (alpha == 0.0)
  {
    p = std::make_unique<PartitionedNewmark>(
        bar.M, bar.K, bar.K_implicit, damping, dt,
        damseis::linalg::Factorization::petsc, motion);
    p->set_state(zero, zero, zero, zero, {}, 0);
  }

  // The reference: free unknowns 1 .. n - 2 (node 0 fixed, the end
  // prescribed).
  const Eigen::MatrixXd M = dense(bar.M), K = dense(bar.K);
  const Eigen::MatrixXd C = damping.a_mass * M + damping.b_stiffness * K;
  const int N = bar.n;
  Eigen::VectorXd u = Eigen::VectorXd::Zero(N), v = u, a = u, fo = u;
  const double a0 = 1.0 / (beta * dt * dt), a1 = gamma / (beta * dt);
  std::vector<int> free;
  for (int i = 1; i < N - 1; ++i)
    free.push_back(i);
  Eigen::MatrixXd A(free.size(), free.size());
  for (std::size_t i = 0; i < free.size(); ++i)
    for (std::size_t j = 0; j < free.size(); ++j)
      A(i, j) = a0 * M(free[i], free[j]) +
                (1 + alpha) * (a1 * C(free[i], free[j]) + K(free[i], free[j]));
  const Eigen::PartialPivLU<Eigen::MatrixXd> lu(A);

  double u_max = 0.0, du_max = 0.0, dv_max = 0.0;
  for (int k = 1; k <= 200; ++k)
  {
    const double load = 0.2 * std::cos(0.3 * k * dt);
    VecSet(f, 0.0);
    VecSetValue(f, 5, load, INSERT_VALUES);
    VecAssemblyBegin(f);
    VecAssemblyEnd(f);
    iterations = 0;
    n.step(f);
    if (p)
      p->step(f);
    EXPECT_LE(iterations, 1) << "step " << k; // J0 is the exact Jacobian

    // u' = u~ + beta dt^2 a', v' = v + dt ((1 - gamma) a + gamma a'):
    // the HHT residual is linear in u'; with u' = 0 at the free unknowns
    // it is r0, and A is its Jacobian there.
    Eigen::VectorXd fn = Eigen::VectorXd::Zero(N);
    fn(5) = load;
    auto state =
        [&](const Eigen::VectorXd& un, Eigen::VectorXd& vn, Eigen::VectorXd& an)
    {
      an = a0 * (un - u) - v / (beta * dt) - (0.5 / beta - 1.0) * a;
      vn = v + dt * ((1 - gamma) * a + gamma * an);
      vn(N - 1) = 0.3 * 0.7 * std::cos(0.7 * k * dt);
      an(N - 1) = -0.3 * 0.49 * std::sin(0.7 * k * dt);
    };
    Eigen::VectorXd un = Eigen::VectorXd::Zero(N), vn, an;
    un(N - 1) = 0.3 * std::sin(0.7 * k * dt);
    state(un, vn, an);
    const Eigen::VectorXd r0 = M * an + (1 + alpha) * (C * vn + K * un) -
                               alpha * (C * v + K * u) - (1 + alpha) * fn +
                               alpha * fo;
    Eigen::VectorXd rf(free.size());
    for (std::size_t i = 0; i < free.size(); ++i)
      rf(i) = r0(free[i]);
    const Eigen::VectorXd x = lu.solve(-rf);
    for (std::size_t i = 0; i < free.size(); ++i)
      un(free[i]) = x(i);
    state(un, vn, an);
    u = un;
    v = vn;
    a = an;
    fo = fn;

    std::vector<double> nu(N), nv(N);
    std::vector<PetscInt> rows(N);
    for (int i = 0; i < N; ++i)
      rows[i] = i;
    for (auto [x, y] : {std::pair{n.u(), n.v()},
                        std::pair{p ? p->u() : n.u(), p ? p->v() : n.v()}})
    {
      VecGetValues(x, N, rows.data(), nu.data());
      VecGetValues(y, N, rows.data(), nv.data());
      for (int i = 0; i < N; ++i)
      {
        u_max = std::max(u_max, std::abs(u(i)));
        du_max = std::max(du_max, std::abs(nu[i] - u(i)));
        dv_max = std::max(dv_max, std::abs(nv[i] - v(i)));
      }
    }
  }
  // Linear: one exact direction per step, so the two agree to round-off
  // (1e-9 of the peak as the test above).
  std::printf("HHT %g, band implicit: u %.2e, v %.2e of the peak %.3f\n", alpha,
              du_max / u_max, dv_max / u_max, u_max);
  EXPECT_GT(u_max, 0.1);
  EXPECT_LT(du_max, 1e-9 * u_max);
  EXPECT_LT(dv_max, 1e-9 * u_max);
  VecDestroy(&zero);
  VecDestroy(&f);
}
} // namespace

TEST(PartitionedNewmark, NonlinearIntegratorsImplicitBandTakesHhtAlpha)
{
  implicit_band_against_dense(-0.1);
}

TEST(PartitionedNewmark, ImplicitBandAverageAccelerationBothIntegrators)
{
  implicit_band_against_dense(0.0);
}
