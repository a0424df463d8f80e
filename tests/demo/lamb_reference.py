"""Lamb's problem in 2D (plane strain): the surface displacement of an
elastic half-space under a vertical traction q(t) on the strip |x| <= b of
its surface, q(t) = q0 sin(pi t / T) for 0 <= t <= T (a half sine), zero
after.

The solution is Lamb's (1904) Fourier integral over the wavenumber k and
the frequency w, evaluated here numerically (no finite elements):

  potentials phi = A exp(-nu_a z), psi = B exp(-nu_b z), times
  exp(i (k x - w t)), z downward, nu_c = sqrt(k^2 - w^2 / c^2) (Re > 0);
  sigma_xz = 0 and sigma_zz = -q at z = 0 give, per unit downward traction
  exp(i k x),

    u_z(k, w) = -nu_a k_b^2 / (mu R),
    u_x(k, w) = -i k (2 k^2 - k_b^2 - 2 nu_a nu_b) / (mu R),
    R = (2 k^2 - k_b^2)^2 - 4 k^2 nu_a nu_b   (Rayleigh's function),

  k_b = w / c_s. (Derived for this test; w -> 0 gives the static
  half-space: u_z = (1 - nu) q / (mu k), u_x = i (1 - 2 nu) q / (2 mu k),
  i.e. Flamant's inward surface displacement, which `self_check` tests.)

The frequency integral runs along w = w_r + i eta (eta > 0, the complex-
frequency method of Phinney 1965 / Bouchon 1981): there the Rayleigh pole
and the branch points lie off the real k axis, so the k integral is a
smooth one (trapezoid rule), and the causal time signal is exp(eta t)
times the inverse transform along the shifted line. Nothing is damped:
the half-space is elastic.

Units SI; x to the right, y upward (the finite element model's axes):
uy = -u_z.
"""
import numpy as np


class HalfSpace:
    def __init__(self, E, nu, rho):
        self.mu = E / (2 * (1 + nu))
        lam = E * nu / ((1 + nu) * (1 - 2 * nu))
        self.nu = nu
        self.cs = np.sqrt(self.mu / rho)
        self.cp = np.sqrt((lam + 2 * self.mu) / rho)

    def rayleigh_speed(self):
        """The root of (2 - r)^2 = 4 sqrt(1 - r a) sqrt(1 - r), r = (c/cs)^2,
        a = (cs/cp)^2, between 0 and 1 (bisection)."""
        a = (self.cs / self.cp) ** 2
        f = lambda r: (2 - r) ** 2 - 4 * np.sqrt(1 - r * a) * np.sqrt(1 - r)
        lo, hi = 0.5, 0.999999
        for _ in range(200):
            mid = 0.5 * (lo + hi)
            if f(lo) * f(mid) <= 0:
                hi = mid
            else:
                lo = mid
        return self.cs * np.sqrt(0.5 * (lo + hi))

    def kernels(self, k, w):
        """u_z, u_x per unit downward traction exp(i k x) at frequency w
        (complex, Im w > 0)."""
        ka2 = (w / self.cp) ** 2
        kb2 = (w / self.cs) ** 2
        na = np.sqrt(k * k - ka2)
        nb = np.sqrt(k * k - kb2)
        R = (2 * k * k - kb2) ** 2 - 4 * k * k * na * nb
        uz = -na * kb2 / (self.mu * R)
        ux = -1j * k * (2 * k * k - kb2 - 2 * na * nb) / (self.mu * R)
        return uz, ux


def half_sine_spectrum(w, T):
    """int_0^T sin(pi t / T) exp(i w t) dt."""
    a = np.pi / T
    return a * (1 + np.exp(1j * w * T)) / (a * a - w * w)


def surface_response(hs, xs, times, q0, b, T, period=4.0, f_max=150.0,
                     k_max=6.0, dk=2e-4, derivative=0):
    """ux[i, j], uy[i, j] at x = xs[i] (> b), t = times[j] (< period / 2);
    with derivative = 1 the velocities."""
    eta = np.pi / period
    dw = 2 * np.pi / period
    ws = np.arange(0.0, 2 * np.pi * f_max + dw / 2, dw)
    k = np.arange(dk / 2, k_max, dk)          # midpoint rule, k > 0
    strip = 2 * np.sin(k * b) / k             # the strip's transform
    xs = np.asarray(xs, dtype=float)
    times = np.asarray(times, dtype=float)
    cos_kx = np.cos(np.outer(xs, k))
    sin_kx = np.sin(np.outer(xs, k))
    uz_w = np.zeros((len(xs), len(ws)), complex)
    ux_w = np.zeros((len(xs), len(ws)), complex)
    for n, wr in enumerate(ws):
        w = wr + 1j * eta
        gz, gx = hs.kernels(k, w)
        f = q0 * half_sine_spectrum(w, T)
        # u_z even in k, u_x odd: (1 / 2 pi) int over the whole k axis.
        uz_w[:, n] = f * (cos_kx @ (gz * strip)) * dk / np.pi
        ux_w[:, n] = f * (sin_kx @ (1j * gx * strip)) * dk / np.pi
    # u(t) = exp(eta t) / pi Re sum' u(w_n + i eta) exp(-i w_n t) dw
    weight = np.full(len(ws), dw / np.pi)
    weight[0] *= 0.5
    # d/dt exp(-i w t) = -i w exp(-i w t), w on the shifted line.
    weight = weight * (-1j * (ws + 1j * eta)) ** derivative
    phase = np.exp(-1j * np.outer(ws, times)) * weight[:, None]
    grow = np.exp(eta * times)
    uz = np.real(uz_w @ phase) * grow
    ux = np.real(ux_w @ phase) * grow
    return ux, -uz


def self_check(hs):
    """Two properties of the kernels the derivation must have: the static
    limit (Flamant) and the Rayleigh pole at the Rayleigh speed."""
    k = np.array([0.3])
    w = 1e-6 * (1 + 1j)
    uz, ux = hs.kernels(k, w)
    assert abs(uz[0] * hs.mu * k[0] / (1 - hs.nu) - 1) < 1e-6, uz
    assert abs(ux[0] / (1j * (1 - 2 * hs.nu) / (2 * hs.mu * k[0])) - 1) < 1e-6
    cR = hs.rayleigh_speed()
    # The kernels' pole lies at k = w / c_R on the real line (tiny Im w).
    w = 100.0 + 1e-9j
    ks = np.linspace(0.9, 1.1, 20001) * w.real / cR
    uz, _ = hs.kernels(ks, w)
    assert abs(ks[np.argmax(np.abs(uz))] * cR / w.real - 1) < 1e-4
    return cR
