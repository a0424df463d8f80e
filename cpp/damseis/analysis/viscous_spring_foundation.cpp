#include "viscous_spring_foundation.h"
#include <damseis/fem/tied_dofs.h>
#include <damseis/results/progress.h>
#include <stdexcept>

namespace damseis::analysis
{
using dolfinx::la::petsc::Matrix;

IncidentWaves incident_waves(const fem::ElasticModel& fe,
                             const SeismicSettings& s, const WaveFoundation& w,
                             bool initial_velocity)
{
  if (initial_velocity)
    throw std::invalid_argument(
        "a foundation with mass and a transmitting boundary does not yet "
        "take an initial velocity");
  IncidentWaves waves;
  waves.ground = std::make_unique<geometry::GroundSurface>(
      fe.model(), s.dam_regions, w.boundary_tags);
  std::array<std::vector<double>, 3> outcrop;
  for (int c = 0; c < fe.dim(); ++c)
    if (s.motion[c].active)
      outcrop[c] = s.motion[c].acceleration;
  waves.field = make_free_field(w, fe.dim(), outcrop, s.scheme.dt, s.steps);
  return waves;
}

ViscousSpringParts viscous_spring_parts(const fem::ElasticModel& fe,
                                        const SeismicSettings& s,
                                        const WaveFoundation& w,
                                        const boundary::FreeField& field,
                                        Mat tie)
{
  const MPI_Comm comm = fe.mesh()->comm();
  if (s.damping_frequencies_hz.empty() && s.damping_ratio > 0.0)
    results::warn(comm, "rock with mass on a viscous-spring boundary: the "
                        "lowest modes may be the rock block's on its springs, "
                        "and damping.modes fits the Rayleigh damping to them; "
                        "give damping.frequencies_hz (e.g. the massless "
                        "model's) to fit it to the dam's");
  ViscousSpringParts p;
  p.boundary = std::make_unique<fem::ViscousBoundary>(
      fe, *fe.model().facet_tags, w.boundary_tags, w.centre, w.factors);
  p.springs = Matrix(p.boundary->springs(), true);
  p.dashpots = Matrix(p.boundary->dashpots(), true);
  if (tie) // on the tied unknowns
  {
    p.springs = Matrix(fem::reduce_to_tied(p.springs.mat(), tie), false);
    p.dashpots = Matrix(fem::reduce_to_tied(p.dashpots.mat(), tie), false);
  }
  results::print(comm, "foundation with mass, viscous-spring boundary (" +
                           std::to_string(p.boundary->measure()) +
                           (fe.dim() == 3 ? " m2" : " m") +
                           "), vertically incident waves: the surface "
                           "moves with the record " +
                           std::to_string(field.surface_delay()) + " s late");
  return p;
}
} // namespace damseis::analysis
