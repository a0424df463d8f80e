/// @file dual.h
/// Forward-mode automatic differentiation with a fixed number of directions.
///
/// The local return map writes its residual once, as a template on the scalar
/// type; evaluating it with Dual<N> gives the exact Jacobian (used by the
/// local Newton and, at convergence, by the consistent tangent). The exact
/// Jacobian is what makes the algorithmic tangent agree with finite
/// differences of the return map to round-off (no neglected d(r)/d(sigma),
/// d(g)/d(sigma) or d(coefficients)/d(kappa) terms).
#pragma once

#include <array>
#include <cmath>

namespace damseis::material
{

/// A value and its derivatives with respect to N independent variables.
template <int N>
struct Dual
{
  double v = 0.0;
  std::array<double, N> d{};

  Dual() = default;
  Dual(double x) : v(x) {} // NOLINT: implicit on purpose (constants)
  /// The independent variable number i with value x.
  static Dual variable(double x, int i)
  {
    Dual r(x);
    r.d[i] = 1.0;
    return r;
  }
};

inline double value(double x)
{
  return x;
}
template <int N>
double value(const Dual<N>& x)
{
  return x.v;
}

template <int N>
Dual<N> operator-(const Dual<N>& a)
{
  Dual<N> r;
  r.v = -a.v;
  for (int i = 0; i < N; ++i)
    r.d[i] = -a.d[i];
  return r;
}
template <int N>
Dual<N> operator+(const Dual<N>& a, const Dual<N>& b)
{
  Dual<N> r;
  r.v = a.v + b.v;
  for (int i = 0; i < N; ++i)
    r.d[i] = a.d[i] + b.d[i];
  return r;
}
template <int N>
Dual<N> operator-(const Dual<N>& a, const Dual<N>& b)
{
  Dual<N> r;
  r.v = a.v - b.v;
  for (int i = 0; i < N; ++i)
    r.d[i] = a.d[i] - b.d[i];
  return r;
}
template <int N>
Dual<N> operator*(const Dual<N>& a, const Dual<N>& b)
{
  Dual<N> r;
  r.v = a.v * b.v;
  for (int i = 0; i < N; ++i)
    r.d[i] = a.d[i] * b.v + a.v * b.d[i];
  return r;
}
template <int N>
Dual<N> operator/(const Dual<N>& a, const Dual<N>& b)
{
  Dual<N> r;
  r.v = a.v / b.v;
  const double ib = 1.0 / b.v;
  for (int i = 0; i < N; ++i)
    r.d[i] = (a.d[i] - r.v * b.d[i]) * ib;
  return r;
}
template <int N>
Dual<N> operator+(const Dual<N>& a, double b)
{
  Dual<N> r = a;
  r.v += b;
  return r;
}
template <int N>
Dual<N> operator+(double a, const Dual<N>& b)
{
  return b + a;
}
template <int N>
Dual<N> operator-(const Dual<N>& a, double b)
{
  Dual<N> r = a;
  r.v -= b;
  return r;
}
template <int N>
Dual<N> operator-(double a, const Dual<N>& b)
{
  Dual<N> r = -b;
  r.v += a;
  return r;
}
template <int N>
Dual<N> operator*(const Dual<N>& a, double b)
{
  Dual<N> r;
  r.v = a.v * b;
  for (int i = 0; i < N; ++i)
    r.d[i] = a.d[i] * b;
  return r;
}
template <int N>
Dual<N> operator*(double a, const Dual<N>& b)
{
  return b * a;
}
template <int N>
Dual<N> operator/(const Dual<N>& a, double b)
{
  return a * (1.0 / b);
}
template <int N>
Dual<N> operator/(double a, const Dual<N>& b)
{
  Dual<N> r;
  r.v = a / b.v;
  const double f = -r.v / b.v;
  for (int i = 0; i < N; ++i)
    r.d[i] = f * b.d[i];
  return r;
}
template <int N, class U>
Dual<N>& operator+=(Dual<N>& a, const U& b)
{
  return a = a + b;
}
template <int N, class U>
Dual<N>& operator-=(Dual<N>& a, const U& b)
{
  return a = a - b;
}
template <int N, class U>
Dual<N>& operator*=(Dual<N>& a, const U& b)
{
  return a = a * b;
}

/// Applies a scalar function with value fx and derivative dfx (chain rule).
template <int N>
Dual<N> chain(const Dual<N>& a, double fx, double dfx)
{
  Dual<N> r;
  r.v = fx;
  for (int i = 0; i < N; ++i)
    r.d[i] = dfx * a.d[i];
  return r;
}
template <int N>
Dual<N> sqrt(const Dual<N>& a)
{
  const double s = std::sqrt(a.v);
  return chain(a, s, s > 0.0 ? 0.5 / s : 0.0);
}
template <int N>
Dual<N> exp(const Dual<N>& a)
{
  const double e = std::exp(a.v);
  return chain(a, e, e);
}
template <int N>
Dual<N> log(const Dual<N>& a)
{
  return chain(a, std::log(a.v), 1.0 / a.v);
}
template <int N>
Dual<N> pow(const Dual<N>& a, double p)
{
  const double y = std::pow(a.v, p);
  return chain(a, y, p * y / a.v);
}
template <int N>
Dual<N> abs(const Dual<N>& a)
{
  return a.v < 0.0 ? -a : a;
}

/// max/min for double and Dual alike (the derivative of the selected branch).
template <class T>
T vmax(const T& a, const T& b)
{
  return value(a) >= value(b) ? a : b;
}
template <class T>
T vmin(const T& a, const T& b)
{
  return value(a) <= value(b) ? a : b;
}

} // namespace damseis::material
