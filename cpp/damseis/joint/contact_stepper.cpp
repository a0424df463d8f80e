#include "contact_stepper.h"

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
      _contact(std::move(contact)), _work(M, *_contact, restitution)
{
}

dynamics::StepReport ContactStepper::step(Vec f)
{
  _work.before();
  engine::LinearStepper::step(f);
  dolfinx::la::petsc::Vector dv(create_vector(), false);
  if (_work.after(engine::LinearStepper::v(), dv.vec()))
    newmark().correct_velocity(dv.vec());
  dynamics::StepReport report;
  report.iterations = static_cast<int>(_work.last().ncp_iterations);
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
  return contact_progress_note(*_contact, _work.last());
}
} // namespace damseis::joint
