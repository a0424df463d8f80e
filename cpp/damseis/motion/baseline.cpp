#include "baseline.h"
#include "message.h"
#include "spectrum.h"
#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <complex>
#include <fftw3.h>
#include <memory>
#include <stdexcept>

namespace damseis::motion
{
std::size_t fast_fft_size(std::size_t n)
{
  for (std::size_t m = std::max<std::size_t>(n, 1);; ++m)
  {
    std::size_t r = m;
    for (std::size_t p : {2, 3, 5})
      while (r % p == 0)
        r /= p;
    if (r == 1)
      return m;
  }
}

void remove_displacement_trend(std::vector<double>& a, double dt, int degree)
{
  if (degree < 3 || degree > 8)
    throw std::invalid_argument("baseline polynomial degree " +
                                std::to_string(degree) + "; expected 3 to 8");
  if (!(dt > 0))
    throw std::invalid_argument("time step " + number_text(dt) +
                                " s; expected > 0");
  const std::size_t n = a.size();
  const int m = degree - 1; // terms x^2 .. x^degree, x = t / t_end
  if (n < static_cast<std::size_t>(m) + 2)
    return;
  std::vector<double> v, d;
  integrate(a, dt, v, d);
  const double tend = dt * static_cast<double>(n - 1);
  Eigen::MatrixXd basis(n, m);
  Eigen::VectorXd rhs(n);
  for (std::size_t k = 0; k < n; ++k)
  {
    const double x = static_cast<double>(k) / static_cast<double>(n - 1);
    double p = x * x;
    for (int j = 0; j < m; ++j, p *= x)
      basis(static_cast<Eigen::Index>(k), j) = p;
    rhs(static_cast<Eigen::Index>(k)) = d[k];
  }
  // Constraints: the fit ends with the record's displacement and velocity
  // (so the corrected ones end at zero): p(1) = d_end, p'(1) = v_end tend.
  Eigen::MatrixXd constraints(2, m);
  for (int j = 0; j < m; ++j)
  {
    constraints(0, j) = 1.0;
    constraints(1, j) = j + 2;
  }
  const Eigen::Vector2d ends(d.back(), v.back() * tend);
  // Null-space method: c = c_p + Z z, C Z = 0, z by least squares.
  const Eigen::HouseholderQR<Eigen::MatrixXd> qr(constraints.transpose());
  const Eigen::MatrixXd q = qr.householderQ();
  const Eigen::MatrixXd r =
      qr.matrixQR().topRows(2).triangularView<Eigen::Upper>();
  const Eigen::VectorXd c_p =
      q.leftCols(2) * r.transpose().triangularView<Eigen::Lower>().solve(ends);
  Eigen::VectorXd c = c_p;
  if (m > 2) // degree 3: the constraints fix both terms
  {
    const Eigen::MatrixXd z_basis = q.rightCols(m - 2);
    c += z_basis *
         (basis * z_basis).colPivHouseholderQr().solve(rhs - basis * c_p);
  }
  // Second derivative in t: sum_j c_j j (j-1) x^(j-2) / tend^2.
  for (std::size_t k = 0; k < n; ++k)
  {
    const double x = static_cast<double>(k) / static_cast<double>(n - 1);
    double p = 1.0, second = 0.0;
    for (int j = 0; j < m; ++j, p *= x)
    {
      const int power = j + 2;
      second += c(j) * power * (power - 1) * p;
    }
    a[k] -= second / (tend * tend);
  }
}

void end_at_rest(std::vector<double>& a, double dt,
                 const std::vector<double>& shape)
{
  const std::size_t n = a.size();
  if (shape.size() != n)
    throw std::invalid_argument(
        "end_at_rest: shape of " + std::to_string(shape.size()) +
        " samples for a record of " + std::to_string(n));
  if (n < 3)
    return;
  // End velocity and displacement are linear in the record: those of a,
  // of shape and of shape * t / t_end (g1).
  const double tend = dt * static_cast<double>(n - 1);
  std::vector<double> g1(n);
  for (std::size_t k = 0; k < n; ++k)
    g1[k] = shape[k] * dt * static_cast<double>(k) / tend;
  auto ends = [&](const std::vector<double>& x)
  {
    std::vector<double> v, d;
    integrate(x, dt, v, d);
    return Eigen::Vector2d(v.back(), d.back());
  };
  Eigen::Matrix2d m;
  m.col(0) = ends(shape);
  m.col(1) = ends(g1);
  const Eigen::FullPivLU<Eigen::Matrix2d> lu(m);
  if (!lu.isInvertible())
    throw std::invalid_argument("end_at_rest: the shape cannot bring the "
                                "motion to rest");
  const Eigen::Vector2d c = lu.solve(ends(a));
  for (std::size_t k = 0; k < n; ++k)
    a[k] -= c(0) * shape[k] + c(1) * g1[k];
}

void butterworth_bandpass(std::vector<double>& a, double dt, double f_low,
                          double f_high, int order)
{
  if (!(dt > 0))
    throw std::invalid_argument("time step " + number_text(dt) +
                                " s; expected > 0");
  const double nyquist = 0.5 / dt;
  if (!(f_low >= 0) || !(f_high > f_low) || !std::isfinite(f_low))
    throw std::invalid_argument("band-pass " + number_text(f_low) + " - " +
                                number_text(f_high) +
                                " Hz; expected 0 <= f_low < f_high");
  if (f_low > 0 && f_low < 1e-3)
    throw std::invalid_argument("band-pass low corner " + number_text(f_low) +
                                " Hz; expected 0 (none) or at least 0.001");
  if (order < 1 || order > 16)
    throw std::invalid_argument("Butterworth order " + std::to_string(order) +
                                "; expected 1 to 16");
  const std::size_t n = a.size();
  if (n < 2)
    return;
  // Zero padding against wrap-around: the filter's impulse response lasts
  // about order / f_low (both directions).
  const double ring = f_low > 0 ? 2.0 * order / f_low : 0.0;
  const std::size_t size =
      fast_fft_size(2 * n + static_cast<std::size_t>(std::ceil(ring / dt)));
  std::vector<double> x(size, 0.0);
  std::copy(a.begin(), a.end(), x.begin());
  const std::size_t bins = size / 2 + 1;
  auto spectrum = std::unique_ptr<fftw_complex[], decltype(&fftw_free)>(
      static_cast<fftw_complex*>(fftw_malloc(sizeof(fftw_complex) * bins)),
      &fftw_free);
  fftw_plan forward = fftw_plan_dft_r2c_1d(static_cast<int>(size), x.data(),
                                           spectrum.get(), FFTW_ESTIMATE);
  fftw_execute(forward);
  fftw_destroy_plan(forward);
  const double two_n = 2.0 * order;
  for (std::size_t k = 0; k < bins; ++k)
  {
    const double f = static_cast<double>(k) / (static_cast<double>(size) * dt);
    double gain = 1.0;
    if (f_low > 0)
      gain *= f > 0 ? 1.0 / (1.0 + std::pow(f_low / f, two_n)) : 0.0;
    if (f_high < nyquist)
      gain *= 1.0 / (1.0 + std::pow(f / f_high, two_n));
    // FFTW's transforms are unnormalised: divide by the size here.
    gain /= static_cast<double>(size);
    spectrum[k][0] *= gain;
    spectrum[k][1] *= gain;
  }
  fftw_plan backward = fftw_plan_dft_c2r_1d(
      static_cast<int>(size), spectrum.get(), x.data(), FFTW_ESTIMATE);
  fftw_execute(backward);
  fftw_destroy_plan(backward);
  std::copy(x.begin(), x.begin() + static_cast<std::ptrdiff_t>(n), a.begin());
}
} // namespace damseis::motion
