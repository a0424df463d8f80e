/// @file baseline.h
/// Baseline correction of ground accelerations: a least-squares polynomial
/// removed from the displacement (so that velocity and displacement end
/// near zero), and a zero-phase Butterworth band-pass (FFTW).
#pragma once

#include <cstddef>
#include <vector>

namespace damseis::motion
{
/// Fits the displacement d(t) (integrated from rest, exact for linear a)
/// with c_2 t^2 + ... + c_degree t^degree by least squares, constrained to
/// end with the record's displacement and velocity, and subtracts the fit's
/// second derivative from `a`: the corrected motion still starts at rest
/// (no t^0, t^1 terms) and ends with zero velocity and displacement (to
/// O(dt^2): the removed polynomial is sampled). 3 <= degree <= 8. The basis is
/// in t / t_end; Eigen's QR solves the constrained fit (null-space method).
void remove_displacement_trend(std::vector<double>& a, double dt,
                               int degree = 6);

/// Makes a motion end at rest (zero velocity and displacement, exactly for
/// the piecewise-linear record) by subtracting shape(t) (c0 + c1 t / t_end)
/// with the two coefficients that do it. With `shape` the record's
/// intensity envelope the correction is smooth and spread over the strong
/// motion (little content at structural periods, unlike a polynomial
/// in t). `shape` holds one value per sample; throws if it cannot
/// (a shape whose two moments are dependent).
void end_at_rest(std::vector<double>& a, double dt,
                 const std::vector<double>& shape);

/// The smallest n' >= n whose prime factors are 2, 3 and 5 (fast FFT sizes).
std::size_t fast_fft_size(std::size_t n);

/// Zero-phase Butterworth band-pass of order `order` (per direction: the
/// gain is |H|^2, as a forward-backward filter): gain
/// 1 / ((1 + (f_low/f)^(2n)) (1 + (f/f_high)^(2n))) applied to the FFT of
/// `a` padded with zeros (FFTW). f_low = 0 or f_high >= Nyquist switches
/// that side off. Throws std::invalid_argument for bad frequencies.
void butterworth_bandpass(std::vector<double>& a, double dt, double f_low,
                          double f_high, int order = 4);
} // namespace damseis::motion
