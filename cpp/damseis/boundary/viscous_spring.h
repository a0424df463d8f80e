// The viscous-spring (visco-elastic) artificial boundary: springs and
// dashpots per unit area of the boundary of a truncated rock foundation
// (algorithms.md 3.6; Deeks & Randolph 1994, Liu et al. 2006).
//   k_n = alpha_n G / R,  k_t = alpha_t G / R,  c_n = rho c_p,  c_t = rho c_s,
// with R the distance from the scattering centre (the dam) to the boundary
// point. The dashpots alone are Lysmer and Kuhlemeyer's (1969) boundary,
// exact for plane waves at normal incidence; the springs carry the static
// and low-frequency part of the scattered field (a cylindrical or
// spherical wave).
#pragma once

namespace damseis::boundary
{
/// An isotropic elastic rock (SI). In 2D with plane stress the P modulus
/// is that of a plate (lambda* = 2 lambda G / (lambda + 2 G)), as the
/// finite element model's.
struct Rock
{
  double E = 0.0;   ///< [Pa]
  double nu = 0.0;  ///< [-]
  double rho = 0.0; ///< [kg/m3]
  bool plane_stress = false;

  double G() const { return E / (2.0 * (1.0 + nu)); }
  /// lambda (lambda* in plane stress).
  double lambda() const;
  /// The P-wave modulus lambda + 2 G.
  double p_modulus() const { return lambda() + 2.0 * G(); }
  double cp() const;
  double cs() const;
  /// sigma_xx / sigma_zz of a vertical P wave (lambda / (lambda + 2 G)).
  double lateral_ratio() const { return lambda() / p_modulus(); }
};

/// The dimensionless spring factors alpha_n, alpha_t.
struct SpringFactors
{
  double normal = 0.0, tangential = 0.0;
  /// 3D: 4/3 and 2/3 (Liu et al. 2006); 2D: 1 and 1/2.
  static SpringFactors recommended(int dim);
};

/// Springs [N/m3] and dashpots [N s/m3] per unit area.
struct SpringDashpot
{
  double kn = 0.0, kt = 0.0, cn = 0.0, ct = 0.0;
};

/// The coefficients at distance R > 0 from the scattering centre.
SpringDashpot viscous_spring(const Rock& rock, double R, SpringFactors f);
} // namespace damseis::boundary
