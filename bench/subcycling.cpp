// Would subcycling the explicit band keep the implicit-explicit partition
// stable? (algorithms.md 6.4 item 6 proposes it as an extension.) A bar
// of 10 implicit consistent-mass elements and 10 explicit lumped ones
// (h = c = 1, fixed at the implicit end, free at the other), one implicit
// step dt = m h' with m explicit substeps h' inside it, three couplings of
// the two groups at their interface node:
//   a: the band first, the interface extrapolated from step n
//      (d + tau v + tau^2 a / 4), then the implicit solve with the band's
//      new displacement known;
//   b: the implicit solve first with the band at its predictor (the
//      partition's own coupling, dynamics/PartitionedNewmark), then the
//      substeps with the interface interpolated linearly;
//   c: both at once: the implicit solve with the substeps' mean interface
//      force, the interface interpolated (solved exactly).
// The step's amplification matrix is built column by column and its
// spectral radius printed (above 1: the scheme grows). At m = 1 each is
// the partition as built. Prints a Markdown table.
//   bench_subcycling [beta of the band: 0.25 (the partition's
//   predictor-corrector, default) or 0 (central differences)]
#include <Eigen/Dense>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <utility>

namespace
{
using Eigen::MatrixXd;
using Eigen::VectorXd;

constexpr int n_implicit = 10, n_explicit = 10;
constexpr int n = n_implicit + n_explicit; // free nodes; node 0 is fixed
constexpr double beta = 0.25, gamma_ = 0.5;

/// The bar's matrices over the free nodes 1..n (index i = node i + 1),
/// split into the implicit nodes (0..n_implicit-1, the last the
/// interface) and the band's own nodes.
struct Bar
{
  MatrixXd K, K_elements_implicit, M;
  Bar() : K(MatrixXd::Zero(n + 1, n + 1)), M(MatrixXd::Zero(n + 1, n + 1))
  {
    MatrixXd K_band = MatrixXd::Zero(n + 1, n + 1);
    for (int e = 0; e < n; ++e)
    {
      const Eigen::Matrix2d k{{1.0, -1.0}, {-1.0, 1.0}};
      K.block<2, 2>(e, e) += k;
      if (e < n_implicit)
        M.block<2, 2>(e, e) += Eigen::Matrix2d{{2.0, 1.0}, {1.0, 2.0}} / 6.0;
      else
      {
        M(e, e) += 0.5;
        M(e + 1, e + 1) += 0.5;
        K_band.block<2, 2>(e, e) += k;
      }
    }
    K = K.bottomRightCorner(n, n).eval();
    M = M.bottomRightCorner(n, n).eval();
    K_elements_implicit = K - K_band.bottomRightCorner(n, n);
  }
};

struct State
{
  VectorXd d, v, a;
};

enum class Coupling
{
  band_first,
  implicit_first,
  mean_force
};

class Step
{
public:
  Step(const Bar& bar, double dt, int m, double beta_band, Coupling c)
      : _bar(bar), _dt(dt), _m(m), _beta_band(beta_band), _coupling(c)
  {
  }

  /// The state after one implicit step.
  State operator()(const State& s) const
  {
    if (_coupling == Coupling::band_first)
      return band_first(s);
    // The implicit group's new acceleration a' (affine in a'): the
    // residual of its equation is linear, solved from unit responses.
    const VectorXd r0 = residual(s, VectorXd::Zero(n_implicit));
    MatrixXd J(n_implicit, n_implicit);
    const State zero{VectorXd::Zero(n), VectorXd::Zero(n), VectorXd::Zero(n)};
    for (int i = 0; i < n_implicit; ++i)
      J.col(i) = residual(zero, VectorXd::Unit(n_implicit, i));
    return advance(s, J.partialPivLu().solve(-r0)).first;
  }

private:
  auto I() const { return Eigen::seqN(0, n_implicit); }
  auto E() const { return Eigen::seqN(n_implicit, n_explicit); }

  /// The band's substeps with the interface displacement d_I(tau) given.
  VectorXd substeps(State& band, const std::function<VectorXd(double)>& d_I,
                    VectorXd* mean_force) const
  {
    const double h = _dt / _m;
    const VectorXd D = _bar.M.diagonal()(E());
    for (int k = 1; k <= _m; ++k)
    {
      const VectorXd dI = d_I(k * h);
      const VectorXd d_p =
          band.d + h * band.v + (0.5 - _beta_band) * h * h * band.a;
      const VectorXd v_p = band.v + 0.5 * h * band.a;
      if (mean_force)
        *mean_force +=
            (_bar.K(I(), I()) - _bar.K_elements_implicit(I(), I())) * dI / _m +
            _bar.K(I(), E()) * d_p / _m;
      band.a =
          -(_bar.K(E(), E()) * d_p + _bar.K(E(), I()) * dI).cwiseQuotient(D);
      band.d = d_p + _beta_band * h * h * band.a;
      band.v = v_p + 0.5 * h * band.a;
    }
    return band.d;
  }

  State band_first(const State& s) const
  {
    State band{s.d(E()), s.v(E()), s.a(E())};
    const VectorXd dI = s.d(I()), vI = s.v(I()), aI = s.a(I());
    substeps(
        band,
        [&](double tau) -> VectorXd
        { return dI + tau * vI + 0.25 * tau * tau * aI; },
        nullptr);
    const VectorXd d_p = dI + _dt * vI + 0.25 * _dt * _dt * aI;
    const MatrixXd A = _bar.M(I(), I()) + beta * _dt * _dt * _bar.K(I(), I());
    const VectorXd a_new =
        A.ldlt().solve(-_bar.K(I(), I()) * d_p - _bar.K(I(), E()) * band.d);
    return assemble(d_p + beta * _dt * _dt * a_new,
                    s.v(I()) + 0.5 * _dt * aI + gamma_ * _dt * a_new, a_new,
                    band);
  }

  /// The new state for the implicit group's acceleration a_new, and the
  /// residual of its equation.
  std::pair<State, VectorXd> advance(const State& s,
                                     const VectorXd& a_new) const
  {
    const VectorXd dI = s.d(I()), vI = s.v(I()), aI = s.a(I());
    const VectorXd d_p = dI + _dt * vI + 0.25 * _dt * _dt * aI;
    const VectorXd d_new = d_p + beta * _dt * _dt * a_new;
    const VectorXd v_new = vI + 0.5 * _dt * aI + gamma_ * _dt * a_new;
    State band{s.d(E()), s.v(E()), s.a(E())};
    VectorXd r = _bar.M(I(), I()) * a_new;
    if (_coupling == Coupling::implicit_first)
    {
      // The band at its predictor over the whole step.
      const VectorXd band_p = band.d + _dt * band.v + 0.25 * _dt * _dt * band.a;
      r += _bar.K(I(), I()) * d_new + _bar.K(I(), E()) * band_p;
      substeps(
          band,
          [&](double tau) -> VectorXd { return dI + (d_new - dI) * tau / _dt; },
          nullptr);
    }
    else
    {
      VectorXd mean = VectorXd::Zero(n_implicit);
      substeps(
          band,
          [&](double tau) -> VectorXd { return dI + (d_new - dI) * tau / _dt; },
          &mean);
      r += _bar.K_elements_implicit(I(), I()) * d_new + mean;
    }
    return {assemble(d_new, v_new, a_new, band), r};
  }

  VectorXd residual(const State& s, const VectorXd& a_new) const
  {
    return advance(s, a_new).second;
  }

  State assemble(const VectorXd& d, const VectorXd& v, const VectorXd& a,
                 const State& band) const
  {
    State out{VectorXd(n), VectorXd(n), VectorXd(n)};
    out.d << d, band.d;
    out.v << v, band.v;
    out.a << a, band.a;
    return out;
  }

  const Bar& _bar;
  double _dt;
  int _m;
  double _beta_band;
  Coupling _coupling;
};

double spectral_radius(const Step& step)
{
  MatrixXd G(3 * n, 3 * n);
  for (int j = 0; j < 3 * n; ++j)
  {
    const VectorXd x = VectorXd::Unit(3 * n, j);
    const State y = step({x.head(n), x.segment(n, n), x.tail(n)});
    G.col(j) << y.d, y.v, y.a;
  }
  return G.eigenvalues().cwiseAbs().maxCoeff();
}
} // namespace

int main(int argc, char** argv)
{
  const double beta_band = argc > 1 ? std::atof(argv[1]) : 0.25;
  const Bar bar;
  std::printf("Spectral radius of one implicit step, band beta = %g; each "
              "cell: substep h' = 0.5 and 0.95 of the band's h / c\n\n",
              beta_band);
  std::printf("| m | (a) band first | (b) implicit first | (c) mean force |\n"
              "|---|---|---|---|\n");
  for (int m : {1, 2, 3, 4, 8})
  {
    std::printf("| %d |", m);
    for (Coupling c :
         {Coupling::band_first, Coupling::implicit_first, Coupling::mean_force})
    {
      const double r1 = spectral_radius(Step(bar, 0.5 * m, m, beta_band, c));
      const double r2 = spectral_radius(Step(bar, 0.95 * m, m, beta_band, c));
      std::printf(" %.6f, %.6f |", r1, r2);
    }
    std::printf("\n");
  }
  return 0;
}
