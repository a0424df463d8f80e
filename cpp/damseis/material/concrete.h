/// @file concrete.h
/// Rate-dependent concrete: consistency viscoplasticity on the
/// Hsieh-Ting-Chen surface with a Rankine tension cut-off (Lin, Hu, Xiao &
/// Li, section I; algorithms.md section 1). A pure material-point library,
/// MGIS-like: integrate(old state, strain increment, dt) -> new stress, new
/// state, consistent tangent. See README.md in this folder for the design.
///
/// Conventions: stress tension-positive, SI units, Voigt order
/// (11, 22, 33, 12, 23, 13), engineering shear strains (gamma = 2 eps), the
/// tangent is d(stress)/d(engineering strain), 6x6 row-major.
#pragma once

#include "htc.h"
#include "rate.h"

#include <array>
#include <string>

namespace damseis::material
{

using Matrix6 = std::array<double, 36>; ///< 6x6 row-major

/// Which constitutive law integrate() applies (one code path for all three).
enum class Mode
{
  elastic,     ///< Hooke's law, no return map
  plastic,     ///< rate-independent plasticity: R = 1, s = 0
  viscoplastic ///< consistency viscoplasticity: R(kappa_dot), hbar = h + s/dt
};

/// How the tensile strength softens after cracking.
enum class TensionSoftening
{
  /// Exponential softening dissipating Gf per unit crack area (crack band,
  /// h = element size); an element larger than the snap-back limit gets a
  /// lower ft0 so that the energy stays Gf / h.
  crack_band,
  /// The same, but an element larger than the snap-back limit keeps ft0 and
  /// softens as steeply as the limit allows (energy above Gf / h).
  crack_band_keep_strength,
  /// None: perfectly plastic in tension (Ht = 1; no localisation, no mesh
  /// size in the law).
  none
};

/// "crack_band", "crack_band_keep_strength" or "none".
std::string to_string(TensionSoftening s);

/// Material data. Strengths are static values; dynamic_30_percent applies
/// the Chinese-specification convention used by the paper (E, fc0, ft0 x
/// dynamic_factor).
struct ConcreteParameters
{
  double E = 24e9;    ///< Young's modulus [Pa]
  double nu = 0.17;   ///< Poisson's ratio
  double fc0 = 30e6;  ///< static uniaxial compressive strength [Pa] (> 0)
  double ft0 = 2.5e6; ///< static uniaxial tensile strength [Pa] (> 0)
  /// HTC calibration: fbc/fc, and the triaxial point (sigma_oct, tau_oct) =
  /// (-xi0 fc, rho0 fc) on the compressive meridian.
  double fbc_ratio = 1.15, xi0 = 1.95, rho0 = 1.61;
  /// Use the classic constants' calibration points instead of fbc_ratio,
  /// xi0, rho0 (with ft/fc = 0.1 the surface is exactly A = 2.0108,
  /// B = 0.9714, C = 9.1412, D = 0.2312).
  bool classic_shape = false;
  double Gf = 200.0;         ///< tensile fracture energy [N/m]
  double Gc = 20e3;          ///< compressive fracture energy [N/m]
  double element_size = 0.1; ///< crack-band width h [m]
  /// The HTC surface passes through (1 + offset) ft in uniaxial tension so
  /// that the Rankine plane, not the HTC, carries tension (no coincident
  /// corner at the uniaxial tension point).
  double htc_tension_offset = 0.05;
  /// Convexity guard: the HTC tension point is kept in
  /// [rho_min, rho_max] * fc (A, B, C >= 0 there; algorithms.md 1.2, 1.4).
  double rho_min = 0.065, rho_max = 0.25;
  /// Residual compressive strength ratio (numerical floor of Hc).
  double compressive_floor = 1e-3;
  /// Softening moduli are limited to E / snap_back_safety (see README).
  double snap_back_safety = 1.25;
  /// The tension softening (see TensionSoftening).
  TensionSoftening tension_softening = TensionSoftening::crack_band;
  Mode mode = Mode::viscoplastic;
  RateLaw rate_law = RateLaw::ceb_fip;
  double eta_c = 0.0, eta_t = 0.0; ///< linear rate law viscosities [s]
  /// Multipliers of the power-law reference rates kdot0 (1: the CEB-FIP
  /// conversion described in README.md).
  double rate_shift_c = 1.0, rate_shift_t = 1.0;
  bool dynamic_30_percent = false;
  double dynamic_factor = 1.3;
  /// Local Newton: scaled residual tolerance and iteration limit.
  double tolerance = 1e-10;
  int max_iterations = 60;
  /// Crack openings (the Rankine plane sigma_1 <= ft alone) by the closed
  /// form of the scalar consistency equation where it is the answer
  /// (false: always the general active-set iteration; for tests).
  bool closed_form_tension = true;
  /// > 1: a step that does not converge is retried with 2, 4, ... up to
  /// max_substeps equal sub-steps (composite tangent by central
  /// differences). Off by default: the callers (path driver, FE solver) cut
  /// their own steps, and the finite-difference tangent is expensive.
  int max_substeps = 1;
};

/// State at a material point.
struct State
{
  Vector6 stress{};         ///< [Pa]
  Vector6 plastic_strain{}; ///< engineering shear [-]
  double kappa_c = 0.0;     ///< equivalent viscoplastic strain, compression
  double kappa_t = 0.0;     ///< equivalent viscoplastic strain, tension
  double kappa_c_rate = 0.0, kappa_t_rate = 0.0; ///< [1/s], of the last step
};

/// Bits of the active set.
enum Surface : unsigned
{
  htc_surface = 1u, ///< HTC with the largest principal stress
  htc_edge = 2u,    ///< HTC second branch (compressive meridian edge)
  rankine_1 = 4u,   ///< sigma_1 <= ft
  rankine_2 = 8u,   ///< sigma_2 <= ft
  rankine_3 = 16u,  ///< sigma_3 <= ft
  htc_apex = 32u    ///< the HTC apex (hydrostatic stress, alone)
};

/// "elastic", or the active surfaces joined by '+', e.g. "HTC+edge", "R1+R2".
std::string active_set_name(unsigned active);

/// Result of one integration.
struct Update
{
  State state;
  Matrix6 tangent{};   ///< consistent (algorithmic) tangent
  unsigned active = 0; ///< Surface bits of the converged active set
  int iterations = 0;  ///< local Newton iterations (all active-set passes)
  int passes = 0;      ///< active sets tried
  int substeps = 1;    ///< > 1: the sub-stepping fall-back was used
  bool converged = true;
};

/// Values derived from the parameters at construction.
struct DerivedProperties
{
  double E, nu, G, lambda, K;     ///< elasticity (after the dynamic factor)
  double fc0, ft0;                ///< effective initial strengths
  double kappa_tu, kappa_cs;      ///< softening scales of Ht, Hc
  double l_ch;                    ///< E Gf / ft0^2 with the nominal ft0 [m]
  bool tension_strength_reduced;  ///< h too large: ft0 lowered (snap-back)
  bool tension_energy_raised;     ///< h too large: ft0 kept, energy > Gf / h
  bool compression_energy_raised; ///< h too large: Gc/h not reachable
  double uniaxial_compression_dissipation; ///< k_c = |deps_p,axial|/dkappa_c
  RateFunction rate_c, rate_t;
  HtcCalibration calibration; ///< the fixed points (ft_ratio unused)
};

class HtcConcrete
{
public:
  /// Throws std::invalid_argument on inconsistent parameters.
  explicit HtcConcrete(const ConcreteParameters& p);

  /// Backward-Euler integration over one step. d_strain: total strain
  /// increment; dt: time step (> 0 in viscoplastic mode with a rate law; may
  /// be 0 otherwise). Rates kappa_dot = delta kappa / dt (0 if dt = 0).
  Update integrate(const State& old, const Vector6& d_strain, double dt) const;

  /// Strengths for given internal variables and their rates.
  double compressive_strength(double kappa_c, double kappa_c_rate) const;
  double tensile_strength(double kappa_t, double kappa_t_rate) const;
  /// The HTC coefficients (A, B, C, D) relative to the current fc.
  HtcCoefficients htc_coefficients(double kappa_c, double kappa_t,
                                   double kappa_c_rate,
                                   double kappa_t_rate) const;
  /// max over all surfaces of f / fc0 (<= 0: admissible) for a stress and
  /// internal variables, from an independent eigen-decomposition.
  double yield_value(const Vector6& stress, double kappa_c, double kappa_t,
                     double kappa_c_rate, double kappa_t_rate) const;
  double yield_value(const State& s) const
  {
    return yield_value(s.stress, s.kappa_c, s.kappa_t, s.kappa_c_rate,
                       s.kappa_t_rate);
  }

  const ConcreteParameters& parameters() const { return _p; }
  const DerivedProperties& derived() const { return _d; }
  Matrix6 elastic_tangent() const;
  /// The elastic-trial test of integrate(): true if `stress` lies on or
  /// inside every surface for these internal variables at zero rates (a step
  /// ending there is elastic); always true in elastic mode.
  bool admissible(const Vector6& stress, double kappa_c, double kappa_t) const;
  /// Radius r of a ball around `stress` that admissible() accepts whole:
  /// every stress s with |s - stress|_F <= r (Frobenius norm of the tensor,
  /// shears counted twice) passes admissible() for the same internal
  /// variables; 0 if `stress` itself is not (safely) admissible, +inf in
  /// elastic mode. From Lipschitz bounds of the yield functions (Weyl's
  /// inequality for sigma_1, the quadratic growth of J2), with a round-off
  /// guard: a cheap exact pre-test for points far from the surfaces.
  double admissible_radius(const Vector6& stress, double kappa_c,
                           double kappa_t) const;

  /// Plane stress (sigma_33 = 0, no 23/13 shear), in closed form, for the
  /// return to the tensile plane sigma_1 <= ft alone (a crack opening in
  /// the plane): the multiplier from the scalar consistency equation with
  /// the plane-stress modulus E / (1 - nu^2). Applies only where that set
  /// is the answer: sigma_1 of the plane-stress trial above ft, the result
  /// on no other surface (sigma_2 <= ft and the HTC within tolerance), and
  /// a power or no rate law; then true, with u as integrate() at the
  /// eps_33 that makes sigma_33 = 0 (d_strain[2] holds it) and the 3D
  /// tangent there. Otherwise false and nothing written.
  bool plane_stress_tension(const State& old, Vector6& d_strain, double dt,
                            Update& u) const;

  /// The five yield functions (stress units) and, if n != nullptr, their
  /// gradients in principal space; s: principal stresses (descending).
  /// HTC coefficients of the strengths ft, fc (ifc = 1 / fc): the ratio
  /// (1 + htc_tension_offset) ft / fc clamped to [rho_min, rho_max].
  template <class T>
  std::array<T, 4> htc_of(const T& ft, const T& fc, const T& ifc) const;
  template <class T>
  void surfaces(const std::array<T, 3>& s, const T& kc, const T& kt,
                const T& kcd, const T& ktd, std::array<T, 5>& phi,
                std::array<std::array<T, 3>, 5>* n) const;

private:
  /// One backward-Euler step (no sub-stepping).
  Update integrate_step(const State& old, const Vector6& d_strain,
                        double dt) const;
  /// Solves one active set (Surface bits) of the return map; x = (sigma_1..3,
  /// kappa_c, kappa_t, multipliers), dsig_dtr = d(sigma)/d(trial sigma) in
  /// principal space (row-major 3x3). patient: no early exit on stalling.
  /// warm (if warm_set != 0): the solution x of another set, the last
  /// starting point tried. probe_edge (viscoplastic {HTC, edge}): give up
  /// (false, edge_left = true) when the rate-independent return puts less
  /// than 30% of the HTC flow on the edge branch.
  template <int M>
  bool solve_set(unsigned set, const std::array<double, 3>& str, double kcn,
                 double ktn, double kcd_old, double ktd_old, double dt,
                 bool patient, unsigned warm_set,
                 const std::array<double, 9>& warm, std::array<double, 9>& x,
                 std::array<double, 9>& dsig_dtr, int& iterations,
                 bool probe_edge, bool& edge_left) const;
  /// The return to the Rankine plane alone in 3D (str: trial principal
  /// stresses, descending, dir their directions; tr the trial stress), if
  /// that set is the answer; else false and nothing written.
  bool rankine_1_closed_form(const State& old, const Vector6& tr,
                             const std::array<double, 3>& str,
                             const std::array<std::array<double, 3>, 3>& dir,
                             double dt, Update& u) const;
  /// The other surfaces at the result x (principal, descending) of a return
  /// to the Rankine plane alone: the HTC branches at kappa_c = kc (zero
  /// rate) and sigma_2, sigma_3 <= ft, within integrate_step's tolerance.
  bool rankine_1_others_hold(const std::array<double, 3>& x, double kc,
                             double ft) const;
  /// The consistent tangent of a return to the Rankine plane alone (x the
  /// returned principal stresses, ft the strength at multiplier mu); false
  /// where d(ft - sigma_1)/d mu is not positive.
  bool rankine_1_tangent(double ft, double mu, double dt,
                         const std::array<double, 3>& str, const double* x,
                         const std::array<std::array<double, 3>, 3>& dir,
                         Matrix6& T) const;
  /// The multiplier of the return to the Rankine plane sigma_1 <= ft alone,
  /// by a safeguarded scalar Newton iteration (rates: power-law R of the
  /// kappa_t rate): the start of the reduced iteration of that set.
  /// modulus: the stiffness along sigma_1 (0: lambda + 2G, the 3D return;
  /// E / (1 - nu^2) in plane stress). guess >= 0: the first iterate (the
  /// old rate's increment), else the rate-independent frozen-strength one.
  /// ft_out: the tensile strength at the returned multiplier.
  double rankine_1_multiplier(double s1, double ktn, double dt, bool rates,
                              double modulus = 0.0, double guess = -1.0,
                              double* ft_out = nullptr) const;
  /// The consistent tangent of a coaxial return: dsig_dtr = d(sigma)/
  /// d(trial sigma) in principal space (row-major 3x3), str the trial and x
  /// the returned principal stresses, dir the principal directions; spin
  /// terms from the eigenvalue differences (de Souza Neto et al. 2008,
  /// App. A), times D.
  Matrix6
  coaxial_tangent(const std::array<double, 9>& dsig_dtr,
                  const std::array<double, 3>& str, const double* x,
                  const std::array<std::array<double, 3>, 3>& dir) const;
  /// The full system (principal stresses, kappas, multipliers; exact
  /// Jacobian by AD): the second-line solver of a set.
  template <int M>
  bool solve_full(unsigned set, const std::array<double, 3>& str, double kcn,
                  double ktn, double kcd_old, double ktd_old, double dt,
                  std::array<double, 9>& x, std::array<double, 9>& dsig_dtr,
                  int& iterations) const;
  template <class T, int M>
  void residual_full(const std::array<T, 5 + M>& x, const int* ids,
                     const std::array<double, 3>& str, double kcn, double ktn,
                     double dt, bool lc, bool lt, bool rates,
                     std::array<T, 5 + M>& r) const;
  /// Reduced residual of one active set: unknowns y = (multipliers,
  /// kappa_c or its log-rate, kappa_t or its log-rate); the principal
  /// stresses are eliminated in closed form (isotropic elasticity, HTC flow
  /// a(q) s + b 1 + c e_k); sig receives them.
  template <class T, int M>
  void reduced(const T* y, const int* ids, const T* str, double kcn, double ktn,
               double dt, bool lc, bool lt, bool rates, T* r, T* sig) const;
  template <class T>
  T hc(const T& kc) const;
  /// The second half of surfaces(): the yield functions for given current
  /// tensile strength ft, 1 / fc and HTC coefficients X.
  template <class T>
  void surfaces_at(const std::array<T, 3>& s, const T& ft, const T& ifc,
                   const std::array<T, 4>& X, std::array<T, 5>& phi,
                   std::array<std::array<T, 3>, 5>* n) const;
  /// First active set to try, from the trial state (frozen surfaces).
  unsigned predict_set(const std::array<double, 3>& str, double kc, double kt,
                       const std::array<double, 5>& phi,
                       const std::array<std::array<double, 3>, 5>& n) const;

  ConcreteParameters _p;
  DerivedProperties _d{};
  HtcFamily _family;
  bool _rate_on = false;
  bool _log_c = false, _log_t = false; ///< log-rate unknowns (power law)
  /// ft, 1 / fc and the HTC coefficients for internal variables kc, kt at
  /// zero rates, as surfaces() computes them (the surfaces of admissible());
  /// those of the untouched point (most points of a dam) made once.
  void rest_strengths(double kc, double kt, double& ft, double& ifc,
                      std::array<double, 4>& X) const;
  double _virgin_ft = 0.0, _virgin_ifc = 0.0; ///< 0: not made yet
  std::array<double, 4> _virgin_htc{};
};

} // namespace damseis::material
