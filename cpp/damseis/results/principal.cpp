#include "principal.h"
#include <Eigen/Dense>

namespace damseis::results
{
std::array<double, 2> principal_extremes(const double* s, int n)
{
  if (n == 3)
  {
    const double c = 0.5 * (s[0] + s[1]);
    const double d = 0.5 * (s[0] - s[1]);
    // sqrt rather than hypot: no overflow risk at stress magnitudes, and
    // this runs at every stress point every step.
    const double r = std::sqrt(d * d + s[2] * s[2]);
    return {c + r, c - r};
  }
  Eigen::Matrix3d m;
  m << s[0], s[3], s[5], s[3], s[1], s[4], s[5], s[4], s[2];
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig;
  eig.computeDirect(m, Eigen::EigenvaluesOnly);
  return {eig.eigenvalues()[2], eig.eigenvalues()[0]};
}
} // namespace damseis::results
