#include "linear_stepper.h"
#include <damseis/linalg/petsc_vectors.h>

namespace damseis::engine
{
namespace
{
using dolfinx::la::petsc::Vector;
const std::array<const char*, 3> state_names = {"u", "v", "a"};
} // namespace

LinearStepper::LinearStepper(
    Mat M, Mat K, dynamics::RayleighDamping damping,
    dynamics::TimeScheme scheme, linalg::Factorization factorization,
    const std::vector<Mat>& extra_damping,
    std::shared_ptr<dynamics::ConstrainedSolve> constrained, Vec u_start)
    : _K(K), _newmark(M, K, damping, scheme, factorization, extra_damping,
                      std::move(constrained)),
      _restored{Vector(nullptr, false), Vector(nullptr, false),
                Vector(nullptr, false)}
{
  if (u_start)
  {
    _u_start = Vector(create_vector(), false);
    VecCopy(u_start, _u_start.vec());
  }
}

Vec LinearStepper::create_vector() const
{
  Vec x;
  MatCreateVecs(_K, &x, nullptr);
  VecSet(x, 0.0);
  return x;
}

void LinearStepper::start(Vec u0, Vec v0, Vec a0, Vec f0)
{
  Vector zero(create_vector(), false);
  if (!u0)
    u0 = _u_start.vec() ? _u_start.vec() : zero.vec();
  _newmark.set_state(u0, v0 ? v0 : zero.vec(), a0, f0);
}

dynamics::StepReport LinearStepper::step(Vec f)
{
  _newmark.step(f);
  return {};
}

void LinearStepper::save(Arrays& arrays) const
{
  const std::array<Vec, 3> x = {u(), v(), a()};
  for (int i = 0; i < 3; ++i)
    arrays[state_names[i]] = linalg::owned_values(x[i]);
  const dynamics::EnergyBalance& e = _newmark.energy();
  arrays["energy"] = {e.kinetic0, e.strain0,         e.external_work,
                      e.damping,  e.constraint_work, e.impact};
  arrays["constraint_force"] =
      linalg::owned_values(_newmark.constraint_force());
  arrays["impulse"] = linalg::owned_values(_newmark.impulse());
}

void LinearStepper::restore(const CheckpointData& data)
{
  for (int i = 0; i < 3; ++i)
  {
    _restored[i] = Vector(create_vector(), false);
    linalg::set_owned_values(_restored[i].vec(),
                             checkpoint_array(data, state_names[i]));
  }
  for (auto [name, x] : {std::pair{"constraint_force", &_restored_r},
                         std::pair{"impulse", &_restored_impulse}})
  {
    *x = Vector(create_vector(), false);
    linalg::set_owned_values(x->vec(), checkpoint_array(data, name));
  }
  const std::vector<double> e = checkpoint_array(data, "energy", 6);
  dynamics::EnergyBalance balance;
  balance.kinetic0 = e[0];
  balance.strain0 = e[1];
  balance.external_work = e[2];
  balance.damping = e[3];
  balance.constraint_work = e[4];
  balance.impact = e[5];
  balance.started = true;
  _newmark.set_energy(balance);
}

void LinearStepper::resume(Vec f)
{
  _newmark.set_state(_restored[0].vec(), _restored[1].vec(), _restored[2].vec(),
                     f);
  _newmark.set_forces(_restored_r.vec(), _restored_impulse.vec());
  for (auto& x : _restored)
    x = Vector(nullptr, false);
  _restored_r = Vector(nullptr, false);
  _restored_impulse = Vector(nullptr, false);
}
} // namespace damseis::engine
