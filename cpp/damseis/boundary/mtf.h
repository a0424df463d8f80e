// Liao's multi-transmitting formula (MTF; Liao & Wong 1984), the discrete
// transmitting boundary of a node x_0 on an artificial boundary
// (algorithms.md 3.1). With the nodes x_k = x_0 - k dx inward along the
// normal, u_k^p = u(x_k, t_p), the artificial speed c_a and s = c_a dt / dx
// in (0, 1], the operator S ("one step back, c_a dt inward") takes the
// quadratic interpolation t = (t_1, t_2, t_3):
//   t_1 = (1 - s)(2 - s)/2,  t_2 = s (2 - s),  t_3 = s (s - 1)/2,
// S^j the 2j + 1 coefficients T^(j) of (t_1 + t_2 z + t_3 z^2)^j, and the
// N-th order formula (I - b S)^N u_0^(p+1) = 0 with the drift factor
// b = 1 / (1 + gamma_d):
//   u_0^(p+1) = sum_j (-1)^(j+1) C(N, j) b^j sum_k T^(j)_k u_k^(p+1-j).
// Applied to each Cartesian component of the scattered field.
#pragma once

#include <array>
#include <complex>
#include <vector>

namespace damseis::boundary
{
class MultiTransmittingFormula
{
public:
  /// order N >= 1, s in (0, 1], drift gamma_d >= 0.
  MultiTransmittingFormula(int order, double s, double drift = 0.0);

  int order() const { return _order; }
  /// The nodes along the normal the formula reads: 2 N + 1 (k = 0..2N).
  int stencil() const { return 2 * _order + 1; }
  /// The weight of u_k^(p+1-j) (j = 1..N, k = 0..2j): the sign, binomial
  /// and drift factors included.
  double weight(int j, int k) const { return _w[j - 1][k]; }

  /// u_0^(p+1) from the history u(j, k) = u_k^(p+1-j).
  template <typename History>
  double extrapolate(const History& u) const
  {
    double sum = 0.0;
    for (int j = 1; j <= _order; ++j)
      for (int k = 0; k <= 2 * j; ++k)
        sum += _w[j - 1][k] * u(j, k);
    return sum;
  }

  /// The reflection coefficient of this boundary for a plane wave of
  /// frequency omega and wave number kappa (outgoing e^(i(omega t - kappa
  /// x)), x along the outward normal) in a discretisation with steps dt,
  /// dx: R = -((1 - b sigma_out) / (1 - b sigma_in))^N, sigma the factor
  /// S applies to the outgoing and to the reflected wave.
  std::complex<double> reflection(double omega_dt, double kappa_dx) const;

private:
  int _order;
  double _s, _b;
  std::array<double, 3> _t{};
  std::vector<std::vector<double>> _w;
};
} // namespace damseis::boundary
