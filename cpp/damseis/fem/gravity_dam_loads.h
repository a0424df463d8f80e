// Silt and uplift loads of a 2D gravity-dam section (forms/gravity_loads_2d.py,
// algorithms.md 5.3).
#pragma once

#include "elastic_model.h"
#include <petscvec.h>

namespace damseis::fem
{
/// Silt against the upstream face: horizontal Rankine active pressure
/// p = gamma_s' h tan^2(45 deg - phi/2) below the silt surface.
struct Silt
{
  double level = 0.0;             ///< elevation of the silt surface [m]
  double unit_weight = 9.0e3;     ///< submerged unit weight [N/m3]
  double friction_angle_deg = 15; ///< internal friction angle [deg]
  /// K_a gamma_s' [N/m3].
  double k() const;
};

/// Uplift on the dam base, piecewise linear: gamma_w H1 at the heel,
/// gamma_w (H2 + alpha (H1 - H2)) at the drainage line, gamma_w H2 at the
/// toe (heads above the base).
struct Uplift
{
  double head_upstream = 0.0;   ///< H1 [m]
  double head_downstream = 0.0; ///< H2 [m]
  double alpha = 0.25;          ///< residual ratio at the drains
  double x_heel = 0.0, x_drain = 0.0, x_toe = 0.0; ///< [m]
  double gamma_w = 9810.0;                         ///< [N/m3]
};

/// Load vectors (zero at fixed dofs). 2D models only.
Vec assemble_silt(const ElasticModel& fe, const Silt& silt);
Vec assemble_uplift(const ElasticModel& fe, const Uplift& uplift);
} // namespace damseis::fem
