/// @file rate.h
/// Strain-rate effects: the CEB-FIP Model Code 1990 dynamic increase factors
/// (the reference) and the model's rate functions R(kappa_dot).
///
/// CEB-FIP MC90 (CEB Bulletin 213/214, 1993; restated by Malvar & Crawford
/// 1998, "Dynamic increase factors for concrete", and in algorithms.md 1.3),
/// with fcm the static compressive strength and fcmo = 10 MPa:
///   compression, rate <= 30/s: (rate/30e-6)^(1.026 alpha_s),
///                alpha_s = 1/(5 + 9 fcm/fcmo);
///               rate > 30/s: gamma_s rate^(1/3),
///                log10(gamma_s) = 6.156 alpha_s - 2;
///   tension,     rate <= 30/s: (rate/3e-6)^(1.016 delta_s),
///                delta_s = 1/(10 + 6 fcm/fcmo);
///               rate > 30/s: beta_s (rate/3e-6)^(1/3),
///                log10(beta_s) = 7.11 delta_s - 2.33.
/// The model uses form (R1) of algorithms.md 1.3, shifted so that R(0) = 1
/// and R'(0) is finite (needed by the Newton solve):
///   R(kdot) = (1 + kdot/kdot0)^delta,
/// with delta the CEB exponent and kdot0 the CEB reference rate converted
/// from total axial strain rate to the rate of the internal variable at the
/// peak of a uniaxial test (see concrete.h).
#pragma once

#include "dual.h"

#include <cmath>

namespace damseis::material
{

/// CEB-FIP MC90 dynamic increase factor in compression at strain rate
/// `rate` [1/s] for static strength fcm [Pa].
double ceb_dif_compression(double rate, double fcm);
/// CEB-FIP MC90 dynamic increase factor in tension.
double ceb_dif_tension(double rate, double fcm);
/// The MC90 exponents and reference rates (rate <= 30/s branch).
double ceb_exponent_compression(double fcm); ///< 1.026 alpha_s
double ceb_exponent_tension(double fcm);     ///< 1.016 delta_s
inline constexpr double ceb_reference_rate_compression = 30e-6;
inline constexpr double ceb_reference_rate_tension = 3e-6;

/// Kinds of rate function.
enum class RateLaw
{
  none,    ///< R = 1 (s = 0): rate-independent even in viscoplastic mode
  ceb_fip, ///< R = (1 + kdot/kdot0)^delta, fitted to the CEB-FIP DIF
  linear   ///< R = 1 + eta kdot (Wang-type linear viscosity)
};

/// One rate function R(kdot) (power or linear).
struct RateFunction
{
  RateLaw law = RateLaw::none;
  double delta = 0.0; ///< power-law exponent
  double kdot0 = 1.0; ///< power-law reference rate [1/s]
  double eta = 0.0;   ///< linear-law viscosity [s]

  template <class T>
  T operator()(const T& kdot) const
  {
    using std::pow;
    switch (law)
    {
    case RateLaw::ceb_fip:
      return pow(1.0 + kdot / kdot0, delta);
    case RateLaw::linear:
      return 1.0 + eta * kdot;
    default:
      return T(1.0);
    }
  }
};

} // namespace damseis::material
