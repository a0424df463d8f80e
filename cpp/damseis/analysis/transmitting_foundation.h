// A foundation with mass on Liao's multi-transmitting boundary, as the
// linear analysis uses it: the band's cells the explicit group of the
// Hughes-Liu partition (its operators on all dofs without supports), the
// formula on the boundary's nodes (fem/MtfBoundary) with the wave-field
// separation, the band's stable step, the stepper and the load.
#pragma once

#include "wave_foundation.h"
#include <damseis/dynamics/newmark.h>
#include <damseis/engine/parts.h>
#include <damseis/fem/elastic_model.h>
#include <damseis/fem/mtf_boundary.h>
#include <dolfinx/la/petsc.h>
#include <memory>
#include <nlohmann/json.hpp>

namespace damseis::analysis
{
class TransmittingFoundation
{
public:
  /// The partition's operators of `fe` (with the added mass of
  /// `reservoir`), the formula of `wave.mtf` with the known field of
  /// `field` over `ground` (both must outlive this), the band's highest
  /// frequency; prints the boundary's line. Collective; throws
  /// std::invalid_argument if the mesh has no band for the formula.
  TransmittingFoundation(const fem::ElasticModel& fe,
                         const WaveFoundation& wave,
                         const fem::Reservoir* reservoir,
                         std::shared_ptr<const boundary::FreeField> field,
                         const geometry::GroundSurface& ground, double dt);

  /// The stepper (the partition) after checking dt against the band's
  /// stable step with `damping` (stated in the log); input::InputError
  /// above it or with alpha != 0.
  std::unique_ptr<engine::Stepper> stepper(dynamics::RayleighDamping damping,
                                           const dynamics::TimeScheme& scheme,
                                           linalg::Factorization factorization);
  /// The load: C v_ff at every node, C = a_M M + b_K K_I (the prescribed
  /// nodes carry the rest of the free field).
  std::unique_ptr<engine::DynamicLoad> load(dynamics::RayleighDamping damping,
                                            double dt) const;
  /// The summary's entries of the boundary.
  nlohmann::json summary() const;

private:
  const fem::ElasticModel& _fe;
  const WaveFoundation& _wave;
  std::shared_ptr<const boundary::FreeField> _field;
  const geometry::GroundSurface& _ground;
  dolfinx::la::petsc::Matrix _K{nullptr, false}, _K_implicit{nullptr, false},
      _M{nullptr, false};
  dolfinx::la::petsc::Vector _band_mass{nullptr, false};
  std::shared_ptr<fem::MtfBoundary> _mtf;
  double _omega = 0.0;     ///< the band's highest circular frequency
  double _stable_dt = 0.0; ///< set by stepper()
};
} // namespace damseis::analysis
