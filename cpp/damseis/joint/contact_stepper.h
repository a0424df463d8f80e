// The engine's stepper for a linear bulk with frictional contact at the
// joint pairs: HHT/Newmark (dynamics::LinearNewmark) whose effective system
// is solved with the contact condensed onto the pairs (CondensedContact),
// then the impact correction of the pairs that closed during the step
// (algorithms.md 2.7): their normal velocities keep the normal momentum and
// rebound with the restitution e (e = 1: kinetic energy kept, the paper).
// The state is total (static solution included): contact is not additive.
#pragma once

#include "condensed_contact.h"
#include <damseis/engine/linear_stepper.h>
#include <dolfinx/la/petsc.h>
#include <memory>

namespace damseis::joint
{
/// Pairs closing from a gap narrower than this get no impact correction:
/// the gaps of nodes that carry almost no force (the vertices of P2 faces
/// under even pressure) flicker at the solver's precision, and rebounds
/// there would feed the flicker. 1 micrometre: far below the openings
/// engineers read (millimetres), far above the solver's gap precision.
constexpr double impact_min_gap = 1e-6; // m

class ContactStepper : public engine::LinearStepper
{
public:
  /// M (with any added mass), K, damping and scheme as for
  /// dynamics::LinearNewmark; `contact` holds the pairs and the contact
  /// state the run starts from (the static stage's); `u_static` the
  /// displacement it starts from (copied); `restitution` e in [0, 1], or
  /// negative for no impact correction; `extra_damping`: damping matrices
  /// beside the Rayleigh damping (a viscous-spring boundary's dashpots).
  ContactStepper(Mat M, Mat K, dynamics::RayleighDamping damping,
                 dynamics::TimeScheme scheme,
                 std::shared_ptr<CondensedContact> contact, Vec u_static,
                 double restitution,
                 const std::vector<Mat>& extra_damping = {});
  ~ContactStepper() override;

  dynamics::StepReport step(Vec f) override;
  /// The linear stepper's state and the contact state (forces, relative
  /// displacements, gap references, pair states, totals).
  void save(engine::Arrays& arrays) const override;
  void restore(const engine::CheckpointData& data) override;
  std::string progress_note(const dynamics::StepReport&) const override;

  const CondensedContact& contact() const { return *_contact; }
  /// NCP iterations of the last step.
  long last_ncp_iterations() const { return _last.ncp_iterations; }
  /// The contact work of the last step (counts, the same on every rank).
  const ContactTotals& last_step() const { return _last; }

private:
  /// Corrects the velocities of the pairs that closed in the last step
  /// from a gap wider than impact_min_gap (`gap_before`: the gaps before
  /// the step). Collective.
  void impact_correction(const std::vector<double>& gap_before);
  /// The values of x at the pair nodes' unknowns, on rank 0.
  Eigen::VectorXd at_pairs(Vec x) const;

  std::shared_ptr<CondensedContact> _contact;
  double _e;
  VecScatter _to_root = nullptr; ///< pair unknowns to rank 0
  Vec _pair_values = nullptr;
  Eigen::VectorXd _mass;      ///< lumped mass at the pair unknowns (rank 0)
  std::vector<char> _movable; ///< both nodes of the pair have mass
  ContactTotals _last;        ///< the totals' increments over the last step
};
} // namespace damseis::joint
