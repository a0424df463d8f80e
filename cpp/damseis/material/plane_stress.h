/// @file plane_stress.h
/// Plane stress at a material point: the out-of-plane strain increment that
/// makes sigma_33 = 0, by a safeguarded Newton iteration around
/// HtcConcrete::integrate (the 3D return map).
#pragma once

#include "concrete.h"

#include <cstdint>

namespace damseis::material
{

/// Work of one plane-stress integration.
struct PlaneStressCounts
{
  int return_maps = 0;               ///< integrate() calls
  std::int64_t local_iterations = 0; ///< their local Newton iterations
};

/// One backward-Euler step in plane stress (sigma_33 = 0; the shears 23, 13
/// stay zero). d_strain: the increment; its [2] (eps_33) is ignored on entry
/// and holds the solved value on return. The update is not converged if the
/// return map fails, or if sigma_33 = 0 has no solution near the iterates
/// (the return map jumps across zero; see plane_stress.cpp).
/// closed_form_tension: try HtcConcrete::plane_stress_tension first (one
/// closed-form return instead of the iteration, where a crack opens in the
/// plane); false: always the iteration (the reference of its test).
Update integrate_plane_stress(const HtcConcrete& m, const State& old,
                              Vector6& d_strain, double dt,
                              PlaneStressCounts* counts = nullptr,
                              bool closed_form_tension = true);

} // namespace damseis::material
