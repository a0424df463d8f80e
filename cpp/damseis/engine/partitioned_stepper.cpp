#include "partitioned_stepper.h"
#include <damseis/linalg/petsc_vectors.h>

namespace damseis::engine
{
namespace
{
using dolfinx::la::petsc::Vector;
const std::array<const char*, 6> state_names = {"u",      "v",      "a",
                                                "u_prev", "v_prev", "a_prev"};
} // namespace

PartitionedStepper::PartitionedStepper(
    Mat M, Mat K, Mat K_implicit, dynamics::RayleighDamping damping, double dt,
    linalg::Factorization factorization,
    std::shared_ptr<dynamics::PrescribedMotion> prescribed, double b_explicit)
    : _K(K), _newmark(M, K, K_implicit, damping, dt, factorization,
                      std::move(prescribed), b_explicit),
      _restored{Vector(nullptr, false), Vector(nullptr, false),
                Vector(nullptr, false), Vector(nullptr, false),
                Vector(nullptr, false), Vector(nullptr, false)}
{
}

Vec PartitionedStepper::create_vector() const
{
  Vec x;
  MatCreateVecs(_K, &x, nullptr);
  VecSet(x, 0.0);
  return x;
}

void PartitionedStepper::start(Vec u0, Vec v0, Vec a0, Vec f0)
{
  Vector zero(create_vector(), false);
  _newmark.set_state(u0 ? u0 : zero.vec(), v0 ? v0 : zero.vec(), a0, f0, {}, 0);
  _step = 0;
}

dynamics::StepReport PartitionedStepper::step(Vec f)
{
  _newmark.step(f);
  ++_step;
  return {};
}

void PartitionedStepper::save(Arrays& arrays) const
{
  const dynamics::Kinematics prev = _newmark.prev();
  const std::array<Vec, 6> x = {u(), v(), a(), prev.u, prev.v, prev.a};
  for (int i = 0; i < 6; ++i)
    arrays[state_names[i]] = linalg::owned_values(x[i]);
  const dynamics::EnergyBalance& e = _newmark.energy();
  arrays["energy"] = {e.kinetic0, e.strain0, e.external_work, e.damping,
                      e.constraint_work};
  arrays["step"] = {static_cast<double>(_step)};
}

void PartitionedStepper::restore(const CheckpointData& data)
{
  for (int i = 0; i < 6; ++i)
  {
    _restored[i] = Vector(create_vector(), false);
    linalg::set_owned_values(_restored[i].vec(),
                             checkpoint_array(data, state_names[i]));
  }
  const std::vector<double> e = checkpoint_array(data, "energy", 5);
  dynamics::EnergyBalance balance;
  balance.kinetic0 = e[0];
  balance.strain0 = e[1];
  balance.external_work = e[2];
  balance.damping = e[3];
  balance.constraint_work = e[4];
  balance.started = true;
  _newmark.set_energy(balance);
  _step = static_cast<int>(checkpoint_array(data, "step", 1)[0]);
}

void PartitionedStepper::resume(Vec f)
{
  _newmark.set_state(
      _restored[0].vec(), _restored[1].vec(), _restored[2].vec(), f,
      {_restored[3].vec(), _restored[4].vec(), _restored[5].vec()}, _step);
  for (auto& x : _restored)
    x = Vector(nullptr, false);
}
} // namespace damseis::engine
