/// @file htc.h
/// The Hsieh-Ting-Chen (HTC) four-parameter failure surface.
///
/// Classic form (Hsieh, Ting & Chen 1982), dimensionless coefficients:
///   F = A J2/fc^2 + B sqrt(J2)/fc + C sigma1/fc + D I1/fc - 1
/// Paper form (Lin et al., eq. 4), same surface once sigma1 is written with
/// the Lode angle:
///   f = a J2 + (d cos(theta) + c) sqrt(J2) + b I1 - 1,
///   a = A/fc^2, c = B/fc, d = 2C/(sqrt(3) fc), b = (D + C/3)/fc.
/// Calibration (algorithms.md 1.2): the surface passes through uniaxial
/// compression fc, uniaxial tension ft, equibiaxial compression fbc and one
/// point of the compressive meridian (sigma_oct, tau_oct) = (-xi0 fc, rho0 fc)
/// -> a 4x4 linear system. Stress is tension-positive, Voigt order
/// (11, 22, 33, 12, 23, 13).
#pragma once

#include "dual.h"

#include <array>
#include <cmath>

namespace damseis::material
{

using Vector6 = std::array<double, 6>;

/// Dimensionless HTC coefficients (A, B, C, D), relative to a strength fc.
struct HtcCoefficients
{
  double A = 0, B = 0, C = 0, D = 0;
};

/// The paper's coefficients (eq. 4) for a given fc: a [1/Pa^2], b, c, d [1/Pa].
struct HtcPaperForm
{
  double a = 0, b = 0, c = 0, d = 0;
};

/// The four calibration strengths, as ratios to fc.
struct HtcCalibration
{
  double ft_ratio = 0.1;   ///< ft / fc (uniaxial tension)
  double fbc_ratio = 1.15; ///< fbc / fc (equibiaxial compression)
  double xi0 = 1.95;       ///< -sigma_oct / fc of the triaxial point
  double rho0 = 1.61;      ///< tau_oct / fc of the triaxial point
};

/// Solves the 4x4 calibration system. Works in absolute units: the returned
/// coefficients are relative to fc. Throws std::invalid_argument if the
/// system is singular.
HtcCoefficients calibrate_htc(double fc, double ft, double fbc, double xi0,
                              double rho0);

/// The commonly quoted set A = 2.0108, B = 0.9714, C = 9.1412, D = 0.2312.
HtcCoefficients classic_htc();

/// The calibration points the classic set passes through: ft/fc and
/// fbc/fc from the surface itself, rho0 on the meridian at xi0 = 1.95.
HtcCalibration classic_calibration();

/// The paper's form for strength fc.
HtcPaperForm paper_form(const HtcCoefficients& k, double fc);

/// F(sigma) in the classic form (sigma1 from the eigenvalues).
double htc_value(const HtcCoefficients& k, double fc, const Vector6& sigma);

/// f(sigma) in the paper's form (Lode angle from cos(3 theta)).
double htc_paper_value(const HtcPaperForm& p, const Vector6& sigma);

/// Strength along the ray sigma = t * direction (principal stresses,
/// direction any nonzero vector): the t > 0 where F = 0 (inf if none).
double htc_strength_along(const HtcCoefficients& k, double fc,
                          const std::array<double, 3>& direction);

/// Principal stresses in descending order.
std::array<double, 3> principal_stresses(const Vector6& sigma);

/// The one-parameter family used by the model (option O1 of algorithms.md
/// 1.4): compression, equibiaxial and triaxial points fixed relative to fc,
/// tension point at rho * fc. Rows 1, 3, 4 of the 4x4 system do not depend on
/// rho, so its solution is X(rho) = Xp + t(rho) v, v spanning the kernel of
/// those rows: cheap and exactly differentiable (also in Dual numbers).
class HtcFamily
{
public:
  HtcFamily() = default;
  HtcFamily(double fbc_ratio, double xi0, double rho0);

  /// (A, B, C, D) for ft/fc = rho.
  template <class T>
  std::array<T, 4> coefficients(const T& rho) const
  {
    const T q0 = rho * rho / 3.0, q1 = rho / std::sqrt(3.0);
    const T qp = q0 * xp_[0] + q1 * xp_[1] + rho * (xp_[2] + xp_[3]);
    const T qv = q0 * v_[0] + q1 * v_[1] + rho * (v_[2] + v_[3]);
    const T t = (1.0 - qp) / qv;
    return {xp_[0] + t * v_[0], xp_[1] + t * v_[1], xp_[2] + t * v_[2],
            xp_[3] + t * v_[3]};
  }
  HtcCoefficients at(double rho) const
  {
    const auto x = coefficients(rho);
    return {x[0], x[1], x[2], x[3]};
  }

private:
  std::array<double, 4> xp_{}, v_{};
};

} // namespace damseis::material
