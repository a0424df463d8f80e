#include "mtf.h"
#include <cmath>
#include <stdexcept>

namespace damseis::boundary
{
MultiTransmittingFormula::MultiTransmittingFormula(int order, double s,
                                                   double drift)
    : _order(order), _s(s), _b(1.0 / (1.0 + drift))
{
  if (order < 1 || order > 8)
    throw std::invalid_argument("MTF: order between 1 and 8");
  if (!(s > 0.0 && s <= 1.0))
    throw std::invalid_argument("MTF: s = c_a dt / dx must be in (0, 1]");
  if (!(drift >= 0.0))
    throw std::invalid_argument("MTF: the drift factor must be >= 0");
  _t = {0.5 * (1 - s) * (2 - s), s * (2 - s), 0.5 * s * (s - 1)};
  // T^(j) = T^(j-1) convolved with t; the weights with their factors.
  std::vector<double> T = {1.0};
  double binomial = 1.0;
  for (int j = 1; j <= order; ++j)
  {
    std::vector<double> next(T.size() + 2, 0.0);
    for (std::size_t a = 0; a < T.size(); ++a)
      for (int c = 0; c < 3; ++c)
        next[a + c] += T[a] * _t[c];
    T = std::move(next);
    binomial = binomial * (order - j + 1) / j;
    const double factor =
        (j % 2 == 1 ? 1.0 : -1.0) * binomial * std::pow(_b, j);
    std::vector<double> w(T.size());
    for (std::size_t k = 0; k < T.size(); ++k)
      w[k] = factor * T[k];
    _w.push_back(std::move(w));
  }
}

std::complex<double> MultiTransmittingFormula::reflection(double omega_dt,
                                                          double kappa_dx) const
{
  using C = std::complex<double>;
  const C i(0.0, 1.0);
  // u_k^p = e^(i (omega p dt + kappa k dx)) for the outgoing wave (x_k =
  // -k dx), e^(i (omega p dt - kappa k dx)) for the reflected one; S takes
  // u_0^(p+1) to sum_c t_c u_c^p.
  auto sigma = [&](double sign)
  {
    C sum = 0.0;
    for (int c = 0; c < 3; ++c)
      sum += _t[c] * std::exp(sign * i * kappa_dx * double(c));
    return std::exp(-i * omega_dt) * sum;
  };
  return -std::pow((1.0 - _b * sigma(1.0)) / (1.0 - _b * sigma(-1.0)), _order);
}
} // namespace damseis::boundary
