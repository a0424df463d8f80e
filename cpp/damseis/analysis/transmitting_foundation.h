// A foundation with mass on Liao's multi-transmitting boundary, as the
// linear analysis uses it: the band's cells the explicit group of the
// Hughes-Liu partition (its operators on all dofs without supports), the
// formula on the boundary's nodes (fem/MtfBoundary) with the wave-field
// separation, the band's stable step, the stepper and the load.
#pragma once

#include "wave_foundation.h"
#include <damseis/dynamics/newmark.h>
#include <damseis/dynamics/nonlinear_newmark.h>
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
  /// With bonded joints (`tie`, u = P u_r; null: none) the operators,
  /// the band's mass and the prescribed rows are those of the tied
  /// unknowns (the band's nodes are not tied: its rows keep their
  /// values).
  TransmittingFoundation(const fem::ElasticModel& fe,
                         const WaveFoundation& wave,
                         const fem::Reservoir* reservoir,
                         std::shared_ptr<const boundary::FreeField> field,
                         const geometry::GroundSurface& ground, double dt,
                         Mat tie = nullptr);

  /// Checks dt against the band's stable step with `damping` (stated in
  /// the log); input::InputError above it or with alpha != 0.
  void check_time_step(dynamics::RayleighDamping damping,
                       const dynamics::TimeScheme& scheme);
  /// The stepper (the partition) after check_time_step().
  std::unique_ptr<engine::Stepper> stepper(dynamics::RayleighDamping damping,
                                           const dynamics::TimeScheme& scheme,
                                           linalg::Factorization factorization);
  /// The partition for the nonlinear engine, whose state is total: the
  /// formula acts on the motion from the static displacement `u_static`
  /// (copied; the boundary's nodes are fixed in the static stage), the
  /// explicit elements' stiffness K - K_I (null with the band implicit).
  /// Call check_time_step() first.
  dynamics::Partition partition(Vec u_static);
  /// The mass of the partition: consistent on the implicit elements,
  /// lumped on the band.
  Mat mass() const { return _M.mat(); }
  /// The load: C v_ff at every node, C = a_M M + b_K K_I + b_E K_E (the
  /// prescribed nodes carry the rest of the free field), plus `sustained` (the
  /// static loads of a total-state run; null: none).
  std::unique_ptr<engine::DynamicLoad> load(dynamics::RayleighDamping damping,
                                            double dt,
                                            Vec sustained = nullptr) const;
  /// The summary's entries of the boundary.
  nlohmann::json summary() const;

private:
  const fem::ElasticModel& _fe;
  const WaveFoundation& _wave;
  std::shared_ptr<const boundary::FreeField> _field;
  const geometry::GroundSurface& _ground;
  dolfinx::la::petsc::Matrix _K{nullptr, false}, _K_implicit{nullptr, false},
      _M{nullptr, false}, _K_explicit{nullptr, false};
  dolfinx::la::petsc::Vector _band_mass{nullptr, false};
  Mat _tie = nullptr;
  std::shared_ptr<fem::MtfBoundary> _mtf;
  /// The formula on the system's unknowns (_mtf itself without a tie).
  std::shared_ptr<dynamics::PrescribedMotion> _prescribed;
  double _omega = 0.0;      ///< the band's highest circular frequency
  double _b_explicit = 0.0; ///< the band's stiffness damping b_E [s]
  double _stable_dt = 0.0;  ///< set by stepper()
};
} // namespace damseis::analysis
