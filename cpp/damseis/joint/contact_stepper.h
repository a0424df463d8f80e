// The engine's stepper for a linear bulk with frictional contact at the
// joint pairs: HHT/Newmark (dynamics::LinearNewmark) whose effective system
// is solved with the contact condensed onto the pairs (CondensedContact),
// then the impact correction of the pairs that closed during the step
// (impact_correction.h).
// The state is total (static solution included): contact is not additive.
#pragma once

#include "condensed_contact.h"
#include "contact_run.h"
#include "impact_correction.h"
#include <damseis/engine/linear_stepper.h>
#include <dolfinx/la/petsc.h>
#include <memory>

namespace damseis::joint
{
class ContactStepper : public engine::LinearStepper, public ContactRun
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

  dynamics::StepReport step(Vec f) override;
  /// The linear stepper's state and the contact state (forces, relative
  /// displacements, gap references, pair states, totals).
  void save(engine::Arrays& arrays) const override;
  void restore(const engine::CheckpointData& data) override;
  std::string progress_note(const dynamics::StepReport&) const override;

  const CondensedContact& contact() const override { return *_contact; }
  const ContactTotals& last_step() const override { return _work.last(); }

private:
  std::shared_ptr<CondensedContact> _contact;
  ContactStepWork _work; ///< impact correction and the step's totals
};
} // namespace damseis::joint
