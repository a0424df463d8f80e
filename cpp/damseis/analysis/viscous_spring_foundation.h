// What the linear and the concrete analyses build alike for a foundation
// with mass: the rock's surface and the record's free field (either
// transmitting boundary), and for a viscous-spring boundary its springs
// and dashpots on the system's unknowns.
#pragma once

#include "seismic_settings.h"
#include "wave_foundation.h"
#include <damseis/fem/viscous_boundary.h>
#include <dolfinx/la/petsc.h>
#include <memory>

namespace damseis::analysis
{
/// The rock's surface (each column's ground) and the free field of the
/// record's vertically incident waves.
struct IncidentWaves
{
  std::unique_ptr<geometry::GroundSurface> ground;
  std::shared_ptr<const boundary::FreeField> field;
};

/// Collective. Throws std::invalid_argument with an initial velocity
/// (`initial_velocity`: the run has one), which these loads do not yet
/// take.
IncidentWaves incident_waves(const fem::ElasticModel& fe,
                             const SeismicSettings& s, const WaveFoundation& w,
                             bool initial_velocity);

/// A viscous-spring boundary: springs and dashpots on the system's unknowns
/// (all dofs, or with `tie` the tied unknowns u = P u_r: P^T A P).
struct ViscousSpringParts
{
  std::unique_ptr<fem::ViscousBoundary> boundary;
  dolfinx::la::petsc::Matrix springs{nullptr, false}, dashpots{nullptr, false};
};

/// Builds the boundary of `w` and prints its line (the boundary's measure,
/// the surface's delay); warns where the Rayleigh damping would be fitted
/// to the model's own modes (the block's on its springs). Collective.
ViscousSpringParts viscous_spring_parts(const fem::ElasticModel& fe,
                                        const SeismicSettings& s,
                                        const WaveFoundation& w,
                                        const boundary::FreeField& field,
                                        Mat tie);
} // namespace damseis::analysis
