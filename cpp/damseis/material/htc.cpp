#include "htc.h"

#include <Eigen/Dense>
#include <algorithm>
#include <limits>
#include <numbers>
#include <stdexcept>

namespace damseis::material
{

namespace
{
/// Row q_k = [J2, sqrt(J2), sigma1, I1] of the calibration system for
/// principal stresses s (any order).
Eigen::RowVector4d row(std::array<double, 3> s)
{
  std::sort(s.begin(), s.end(), std::greater<>());
  const double I1 = s[0] + s[1] + s[2];
  const double p = I1 / 3.0;
  const double J2 = 0.5 * ((s[0] - p) * (s[0] - p) + (s[1] - p) * (s[1] - p) +
                           (s[2] - p) * (s[2] - p));
  return {J2, std::sqrt(J2), s[0], I1};
}

std::array<double, 3> triaxial_point(double fc, double xi0, double rho0)
{
  const double so = -xi0 * fc, to = rho0 * fc;
  const double s12 = so + to / std::sqrt(2.0), s3 = so - std::sqrt(2.0) * to;
  return {s12, s12, s3};
}
} // namespace

HtcCoefficients calibrate_htc(double fc, double ft, double fbc, double xi0,
                              double rho0)
{
  Eigen::Matrix4d M;
  M.row(0) = row({0.0, 0.0, -fc});
  M.row(1) = row({ft, 0.0, 0.0});
  M.row(2) = row({0.0, -fbc, -fbc});
  M.row(3) = row(triaxial_point(fc, xi0, rho0));
  Eigen::FullPivLU<Eigen::Matrix4d> lu(M);
  if (!lu.isInvertible())
    throw std::invalid_argument("calibrate_htc: singular calibration system");
  const Eigen::Vector4d x = lu.solve(Eigen::Vector4d::Ones());
  // x = (A/fc^2, B/fc, C/fc, D/fc)
  return {x[0] * fc * fc, x[1] * fc, x[2] * fc, x[3] * fc};
}

HtcCoefficients classic_htc()
{
  return {2.0108, 0.9714, 9.1412, 0.2312};
}

HtcCalibration classic_calibration()
{
  const HtcCoefficients k = classic_htc();
  HtcCalibration c;
  c.ft_ratio = htc_strength_along(k, 1.0, {1.0, 0.0, 0.0});
  c.fbc_ratio = htc_strength_along(k, 1.0, {0.0, -1.0, -1.0});
  c.xi0 = 1.95;
  // On the compressive meridian at sigma_oct = -xi0: J2 = 1.5 tau^2,
  // sigma1 = sigma_oct + tau/sqrt(2), I1 = 3 sigma_oct: a quadratic in tau.
  const double so = -c.xi0;
  const double qa = 1.5 * k.A;
  const double qb = k.B * std::sqrt(1.5) + k.C / std::sqrt(2.0);
  const double qc = k.C * so + 3.0 * k.D * so - 1.0;
  c.rho0 = (-qb + std::sqrt(qb * qb - 4.0 * qa * qc)) / (2.0 * qa);
  return c;
}

HtcPaperForm paper_form(const HtcCoefficients& k, double fc)
{
  return {k.A / (fc * fc), (k.D + k.C / 3.0) / fc, k.B / fc,
          2.0 * k.C / (std::sqrt(3.0) * fc)};
}

std::array<double, 3> principal_stresses(const Vector6& s)
{
  Eigen::Matrix3d m;
  m << s[0], s[3], s[5], s[3], s[1], s[4], s[5], s[4], s[2];
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es(m, Eigen::EigenvaluesOnly);
  const auto& e = es.eigenvalues();
  return {e[2], e[1], e[0]};
}

double htc_value(const HtcCoefficients& k, double fc, const Vector6& sigma)
{
  const auto q = row(principal_stresses(sigma));
  return k.A * q[0] / (fc * fc) + k.B * q[1] / fc + k.C * q[2] / fc +
         k.D * q[3] / fc - 1.0;
}

double htc_paper_value(const HtcPaperForm& p, const Vector6& s)
{
  const double I1 = s[0] + s[1] + s[2], m = I1 / 3.0;
  const double d0 = s[0] - m, d1 = s[1] - m, d2 = s[2] - m;
  const double J2 = 0.5 * (d0 * d0 + d1 * d1 + d2 * d2) + s[3] * s[3] +
                    s[4] * s[4] + s[5] * s[5];
  const double J3 = d0 * (d1 * d2 - s[4] * s[4]) -
                    s[3] * (s[3] * d2 - s[4] * s[5]) +
                    s[5] * (s[3] * s[4] - d1 * s[5]);
  double c3 = J2 > 0.0 ? 1.5 * std::sqrt(3.0) * J3 / std::pow(J2, 1.5) : 1.0;
  c3 = std::clamp(c3, -1.0, 1.0);
  const double theta = std::acos(c3) / 3.0;
  return p.a * J2 + (p.d * std::cos(theta) + p.c) * std::sqrt(J2) + p.b * I1 -
         1.0;
}

double htc_strength_along(const HtcCoefficients& k, double fc,
                          const std::array<double, 3>& direction)
{
  const auto q = row(direction); // homogeneous: J2 ~ t^2, others ~ t
  const double qa = k.A * q[0] / (fc * fc);
  const double qb = (k.B * q[1] + k.C * q[2] + k.D * q[3]) / fc;
  if (qa <= 0.0)
    return qb > 0.0 ? 1.0 / qb : std::numeric_limits<double>::infinity();
  return (-qb + std::sqrt(qb * qb + 4.0 * qa)) / (2.0 * qa);
}

HtcFamily::HtcFamily(double fbc_ratio, double xi0, double rho0)
{
  Eigen::Matrix<double, 3, 4> R;
  R.row(0) = row({0.0, 0.0, -1.0});
  R.row(1) = row({0.0, -fbc_ratio, -fbc_ratio});
  R.row(2) = row(triaxial_point(1.0, xi0, rho0));
  Eigen::FullPivLU<Eigen::Matrix<double, 3, 4>> lu(R);
  if (lu.rank() != 3)
    throw std::invalid_argument("HtcFamily: dependent calibration points");
  const Eigen::Vector4d v = lu.kernel().col(0);
  const Eigen::Vector4d xp = lu.solve(Eigen::Vector3d::Ones());
  for (int i = 0; i < 4; ++i)
  {
    v_[i] = v[i];
    xp_[i] = xp[i];
  }
}

} // namespace damseis::material
