/// @file spectrum.h
/// Response spectra of ground accelerations, exact for piecewise-linear
/// input (Nigam & Jennings 1969), and the intensity measures engineers
/// quote with them (PGA, PGV, PGD, Arias intensity, significant duration).
#pragma once

#include <span>
#include <vector>

namespace damseis::motion
{
/// Response of a linear SDOF system u'' + 2 zeta w u' + w^2 u = -a_g(t),
/// at rest at t = 0, to a_g sampled at t_k = k dt and linear in between.
/// One step maps (u_k, v_k, a_k, a_k+1) to (u_k+1, v_k+1) exactly: the
/// Nigam-Jennings recurrence. Needs 0 <= zeta < 1, period > 0, dt > 0.
class Sdof
{
public:
  Sdof(double period, double damping, double dt);
  /// Relative displacement u_k [m] and velocity v_k [m/s] at every sample.
  void respond(std::span<const double> a, std::vector<double>& u,
               std::vector<double>& v) const;
  /// The recurrence: u+ = a11 u + a12 v + b11 a_k + b12 a_k+1 and
  /// v+ = a21 u + a22 v + b21 a_k + b22 a_k+1.
  double a11, a12, a21, a22, b11, b12, b21, b22;
};

/// Oscillators of one damping ratio and one sub-step count, stepped
/// together over the same input. Their recurrences are independent, so the
/// loop over them runs side by side (pipelined and vectorised): several
/// times faster than one oscillator after another. Same arithmetic as Sdof.
class SdofBank
{
public:
  /// Oscillators of `periods` (> 0), each record step dt cut into
  /// `substeps` steps of the same linear input.
  SdofBank(std::span<const double> periods, double damping, double dt,
           int substeps);
  std::size_t size() const { return _a11.size(); }
  int substeps() const { return _substeps; }

  /// From rest over the whole record `a`: for each oscillator the largest
  /// |u| (peak), the substep index where it occurs (at, counted from sample
  /// 0: k * substeps + j), u there (signed), and u, v at the end.
  struct Peaks
  {
    std::vector<double> peak, u_at_peak, u_end, v_end;
    std::vector<long> at;
  };
  Peaks peaks(std::span<const double> a) const;

  /// From rest over x[k0] ... x[k_last] (x indexed like the record), each
  /// selected oscillator `which[i]` until the substep index stop[i] or the
  /// last sample: u[i], v[i] there and the substep index reached[i].
  void run_to(const double* x, long k0, long k_last,
              std::span<const std::size_t> which, std::span<const long> stop,
              std::span<double> u, std::span<double> v,
              std::span<long> reached) const;

private:
  int _substeps;
  std::vector<double> _a11, _a12, _a21, _a22, _b11, _b12, _b21, _b22;
};

/// Oscillators of any periods (> 0) in banks of equal sub-step counts
/// (substeps_for), as response_spectrum steps them.
struct SdofBanks
{
  SdofBanks(std::span<const double> periods, double damping, double dt,
            int samples_per_period = 64);
  std::vector<SdofBank> banks;
  /// Indices into `periods` of each bank's oscillators, in bank order.
  std::vector<std::vector<std::size_t>> members;
};

/// Sub-steps per record step that sample a period at least
/// `samples_per_period` times (at least 1).
int substeps_for(double period, double dt, int samples_per_period = 64);

/// u(t) of the free vibration from (u0, v0) (at rest input).
double free_vibration_displacement(double u0, double v0, double period,
                                   double damping, double t);

/// Largest |u(t)| for t >= 0 of the free vibration from (u0, v0): |u0| or
/// the first extremum (where v = 0), whichever is larger (the later ones
/// decay).
double free_vibration_peak(double u0, double v0, double period, double damping);

/// Spectral ordinates at each period: displacement SD = max|u| [m],
/// pseudo-velocity PSV = w SD [m/s], pseudo-acceleration PSA = w^2 SD
/// [m/s2]. Period 0 gives SD = PSV = 0 and PSA = PGA (the rigid limit).
struct Spectrum
{
  std::vector<double> period, sd, psv, psa;
};

/// The response spectrum of `a` (m/s2, sampled at dt) for one damping
/// ratio (0 <= damping < 1) over the given periods (>= 0), including the
/// free vibration after the record. The response is sampled at least
/// `samples_per_period` times per period (sub-steps of the same linear
/// input): the sampled peak of a harmonic response is then within
/// 1 - cos(pi / 64) = 0.12% of the continuous one. Throws
/// std::invalid_argument for bad arguments (a message naming the value).
Spectrum response_spectrum(std::span<const double> a, double dt,
                           std::span<const double> periods, double damping,
                           int samples_per_period = 64);

/// n periods spaced evenly in log between t_min and t_max (> 0, n >= 2).
std::vector<double> log_spaced(double t_min, double t_max, int n);

/// Intensity measures of a ground acceleration (m/s2 at t_k = k dt, linear
/// in between; velocity and displacement integrated exactly from rest).
struct Measures
{
  double pga = 0;                ///< max |a| [m/s2]
  double pgv = 0;                ///< max |v| [m/s]
  double pgd = 0;                ///< max |d| [m]
  double final_velocity = 0;     ///< v at the end [m/s]
  double final_displacement = 0; ///< d at the end [m]
  double arias = 0;       ///< Arias intensity pi / (2 g) int a^2 dt [m/s]
  double t5 = 0, t95 = 0; ///< times of 5% and 95% of the Arias intensity [s]
  double significant_duration = 0; ///< t95 - t5 [s]
};
Measures measures(std::span<const double> a, double dt);

/// Velocity and displacement from rest (exact for piecewise-linear a).
void integrate(std::span<const double> a, double dt, std::vector<double>& v,
               std::vector<double>& d);
} // namespace damseis::motion
