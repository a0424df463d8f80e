// Baseline correction and band-pass filtering (motion/baseline).
#include <cmath>
#include <damseis/motion/baseline.h>
#include <damseis/motion/spectrum.h>
#include <gtest/gtest.h>
#include <numbers>

using namespace damseis::motion;
namespace
{
constexpr double pi = std::numbers::pi;
}

// An acceleration that is a pure polynomial trend (2 c2 + 6 c3 t + 12 c4
// t^2: a displacement c2 t^2 + c3 t^3 + c4 t^4 in the fitted space) is
// removed whole: the corrected record is zero to round-off.
TEST(Baseline, PolynomialTrendIsRemovedExactly)
{
  const double dt = 0.01, c2 = 0.03, c3 = -0.004, c4 = 2e-4;
  std::vector<double> a(2001);
  for (std::size_t k = 0; k < a.size(); ++k)
  {
    const double t = dt * k;
    a[k] = 2 * c2 + 6 * c3 * t + 12 * c4 * t * t;
  }
  remove_displacement_trend(a, dt, 6);
  double worst = 0;
  for (double x : a)
    worst = std::max(worst, std::abs(x));
  // The trend's acceleration is up to 0.2 m/s2; linear interpolation of
  // the removed polynomial between samples leaves O(dt^2) = 1e-4 of it.
  EXPECT_LT(worst, 1e-4 * 0.2);
}

// a = A sin(w t) from rest drifts (v >= 0, d grows like A t / w): after
// correction the velocity and displacement end at zero (to the O(dt^2)
// of sampling the removed polynomial: asserted 1e-4 of PGV and PGD).
TEST(Baseline, DriftingMotionEndsAtRest)
{
  const double dt = 0.005, amp = 3.0, w = 2 * pi * 1.3;
  std::vector<double> a(4001);
  for (std::size_t k = 0; k < a.size(); ++k)
    a[k] = amp * std::sin(w * dt * k);
  const Measures before = measures(a, dt);
  remove_displacement_trend(a, dt, 6);
  const Measures after = measures(a, dt);
  EXPECT_GT(std::abs(before.final_displacement), 5.0);
  EXPECT_LT(std::abs(after.final_velocity), 1e-4 * after.pgv);
  EXPECT_LT(std::abs(after.final_displacement), 1e-4 * after.pgd);
}

// A motion that ends at rest (a sine burst in a sin^2 window) with a
// constant offset of 1% of its peak, the usual baseline error: the offset
// (a t^2 displacement) is removed and the shaking kept: the corrected
// record equals the burst within 1e-3 of its peak.
TEST(Baseline, OffsetIsRemovedAndShakingKept)
{
  const double dt = 0.005, amp = 3.0, w = 2 * pi * 1.3, tend = 20.0;
  const std::size_t n = 4001;
  std::vector<double> burst(n), a(n);
  for (std::size_t k = 0; k < n; ++k)
  {
    const double t = dt * k, window = std::sin(pi * t / tend);
    burst[k] = amp * std::sin(w * t) * window * window;
    a[k] = burst[k] + 0.01 * amp;
  }
  remove_displacement_trend(a, dt, 6);
  double worst = 0;
  for (std::size_t k = 0; k < n; ++k)
    worst = std::max(worst, std::abs(a[k] - burst[k]));
  EXPECT_LT(worst, 1e-3 * amp);
  const Measures m = measures(a, dt);
  EXPECT_LT(std::abs(m.final_velocity), 1e-4 * m.pgv);
  EXPECT_LT(std::abs(m.final_displacement), 1e-4 * m.pgd);
}

// Zero-phase Butterworth band-pass 0.1 - 25 Hz, order 4, on sines of
// 0.05, 2 and 40 Hz: the gains are 1 / ((1 + (0.1/f)^8)(1 + (f/25)^8)) =
// 0.0038911, 0.99999983 and 0.022525 (by hand), with no phase shift. The
// amplitudes are fitted over the middle half of a 400 s record (away
// from the ends): asserted 1e-3 of the input amplitude.
TEST(Baseline, ButterworthGainsAndZeroPhase)
{
  const double dt = 0.01;
  const std::size_t n = 40001;
  const double freqs[] = {0.05, 2.0, 40.0};
  std::vector<double> a(n, 0.0);
  for (std::size_t k = 0; k < n; ++k)
    for (double f : freqs)
      a[k] += std::sin(2 * pi * f * dt * k);
  butterworth_bandpass(a, dt, 0.1, 25.0, 4);
  for (double f : freqs)
  {
    const double gain =
        1.0 / ((1.0 + std::pow(0.1 / f, 8)) * (1.0 + std::pow(f / 25.0, 8)));
    // Least-squares sine and cosine coefficients over the middle half
    // (an integer number of periods of every frequency: 200 s).
    double s = 0, c = 0, ss = 0;
    for (std::size_t k = n / 4; k < n / 4 + 20000; ++k)
    {
      const double t = dt * k;
      s += a[k] * std::sin(2 * pi * f * t);
      c += a[k] * std::cos(2 * pi * f * t);
      ss += std::sin(2 * pi * f * t) * std::sin(2 * pi * f * t);
    }
    EXPECT_NEAR(s / ss, gain, 1e-3) << f << " Hz";
    EXPECT_NEAR(c / ss, 0.0, 1e-3) << f << " Hz";
  }
}

TEST(Baseline, BadArgumentsThrow)
{
  std::vector<double> a(100, 1.0);
  EXPECT_THROW(remove_displacement_trend(a, 0.01, 2), std::invalid_argument);
  EXPECT_THROW(butterworth_bandpass(a, 0.01, 5.0, 1.0), std::invalid_argument);
  EXPECT_THROW(butterworth_bandpass(a, 0.01, 0.1, 10.0, 0),
               std::invalid_argument);
}

// end_at_rest: a windowed burst plus an offset and a trend (its velocity
// and displacement do not end at zero) ends exactly at rest (the integrals
// of the piecewise-linear record: asserted 1e-12 of PGV and PGD) after
// subtracting shape (c0 + c1 t/T); the correction is that combination (a
// record that already ends at rest is unchanged to round-off).
TEST(Baseline, EndAtRestZeroesFinalVelocityAndDisplacement)
{
  const double dt = 0.01, tend = 20.0;
  const std::size_t n = 2001;
  std::vector<double> shape(n), a(n);
  for (std::size_t k = 0; k < n; ++k)
  {
    const double t = dt * k, window = std::sin(pi * t / tend);
    shape[k] = window * window;
    a[k] = 2.0 * std::sin(2 * pi * 1.7 * t) * shape[k] + 0.03 + 0.001 * t;
  }
  end_at_rest(a, dt, shape);
  Measures m = measures(a, dt);
  EXPECT_LT(std::abs(m.final_velocity), 1e-12 * m.pgv);
  EXPECT_LT(std::abs(m.final_displacement), 1e-12 * m.pgd);
  const std::vector<double> again = a;
  end_at_rest(a, dt, shape);
  for (std::size_t k = 0; k < n; ++k)
    EXPECT_NEAR(a[k], again[k], 1e-12);
}
