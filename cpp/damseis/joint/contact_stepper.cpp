#include "contact_stepper.h"
#include <chrono>

namespace damseis::joint
{
ContactStepper::ContactStepper(Mat M, Mat K, dynamics::RayleighDamping damping,
                               dynamics::TimeScheme scheme,
                               std::shared_ptr<CondensedContact> contact,
                               Vec u_static, double restitution,
                               const std::vector<Mat>& extra_damping)
    : engine::LinearStepper(M, K, damping, scheme,
                            linalg::Factorization::automatic, extra_damping,
                            contact, u_static),
      _contact(std::move(contact))
{
  if (restitution >= 0.0)
    _impact = std::make_unique<ImpactCorrection>(M, *_contact, restitution);
}

dynamics::StepReport ContactStepper::step(Vec f)
{
  std::vector<double> gap_before;
  if (_impact)
    gap_before = _impact->gaps();
  const ContactTotals before = _contact->totals();
  engine::LinearStepper::step(f);
  const auto t0 = std::chrono::steady_clock::now();
  ContactTotals& t = _contact->totals();
  if (_impact)
  {
    dolfinx::la::petsc::Vector dv(create_vector(), false);
    const std::size_t closing =
        _impact->correction(gap_before, engine::LinearStepper::v(), dv.vec());
    if (closing > 0)
    {
      t.impacts += static_cast<long>(closing);
      newmark().correct_velocity(dv.vec());
    }
  }
  t.seconds_impact +=
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0)
          .count();
  _last = count_difference(t, before);
  dynamics::StepReport report;
  report.iterations = static_cast<int>(_last.ncp_iterations);
  return report;
}

void ContactStepper::save(engine::Arrays& arrays) const
{
  engine::LinearStepper::save(arrays);
  save_contact(*_contact, arrays);
}

void ContactStepper::restore(const engine::CheckpointData& data)
{
  engine::LinearStepper::restore(data);
  restore_contact(data, *_contact);
}

std::string ContactStepper::progress_note(const dynamics::StepReport&) const
{
  return contact_progress_note(*_contact, _last);
}
} // namespace damseis::joint
