#include "concrete_stepper.h"
#include <damseis/linalg/petsc_vectors.h>

namespace damseis::analysis
{
namespace
{
using dolfinx::la::petsc::Vector;
const std::array<const char*, 4> state_names = {"u", "v", "a", "f_int"};
/// The transmitting boundary's history (partitioned runs).
const std::array<const char*, 3> prev_names = {"u_prev", "v_prev", "a_prev"};

Vector copy(Vec x)
{
  Vec y;
  VecDuplicate(x, &y);
  VecCopy(x, y);
  return Vector(y, false);
}
} // namespace

void NewtonTotals::add(const dynamics::StepReport& r,
                       const ConcreteSystem& system, double t)
{
  iterations += r.iterations;
  tangent_factorizations += r.tangent_factorizations;
  cuts += r.cuts;
  max_iterations_in_a_step =
      std::max(max_iterations_in_a_step, double(r.iterations));
  max_inelastic_points =
      std::max(max_inelastic_points, double(system.accepted.inelastic));
  krylov_iterations += r.krylov_iterations;
  seconds_residual += r.seconds_residual;
  seconds_tangent += r.seconds_tangent;
  seconds_factorization += r.seconds_factorization;
  seconds_solve += r.seconds_solve;
  substepped += static_cast<double>(system.substepped);
  return_maps += static_cast<double>(system.return_maps);
  local_iterations += static_cast<double>(system.local_iterations);
  returned_points += static_cast<double>(system.returned_points);
  return_map_seconds += system.return_map_seconds;
  implex_error_squares += r.extrapolation_error * r.extrapolation_error;
  if (r.extrapolation_error > implex_error_max)
  {
    implex_error_max = r.extrapolation_error;
    implex_error_time = t;
  }
}

// The order of the checkpoint array "newton".
std::vector<double> NewtonTotals::to_array() const
{
  return {iterations,
          tangent_factorizations,
          cuts,
          max_iterations_in_a_step,
          max_inelastic_points,
          krylov_iterations,
          seconds_residual,
          seconds_tangent,
          seconds_factorization,
          seconds_solve,
          substepped,
          return_maps,
          local_iterations,
          returned_points,
          return_map_seconds,
          implex_error_squares,
          implex_error_max,
          implex_error_time};
}

void NewtonTotals::from_array(std::vector<double> a)
{
  const std::size_t n = to_array().size();
  if (a.size() > n)
    throw std::runtime_error("array newton is too long");
  a.resize(n, 0.0);
  double* fields[] = {&iterations,
                      &tangent_factorizations,
                      &cuts,
                      &max_iterations_in_a_step,
                      &max_inelastic_points,
                      &krylov_iterations,
                      &seconds_residual,
                      &seconds_tangent,
                      &seconds_factorization,
                      &seconds_solve,
                      &substepped,
                      &return_maps,
                      &local_iterations,
                      &returned_points,
                      &return_map_seconds,
                      &implex_error_squares,
                      &implex_error_max,
                      &implex_error_time};
  for (std::size_t i = 0; i < n; ++i)
    *fields[i] = a[i];
}

ConcreteStepper::ConcreteStepper(
    Mat M, Mat K0, dynamics::RayleighDamping damping,
    dynamics::TimeScheme scheme, ConcreteSystem& system,
    fem::ConcreteModel& model, dynamics::NewtonSettings newton,
    linalg::Factorization factorization, Vec u_static, Vec f_int_static,
    Mat extra_damping)
    : _K0(K0), _system(system), _model(model),
      _newmark(M, K0, damping, scheme, system, newton, factorization,
               extra_damping),
      _u_static(copy(u_static)),
      _f_int_static(copy(f_int_static)), _restored{Vector(nullptr, false),
                                                   Vector(nullptr, false),
                                                   Vector(nullptr, false),
                                                   Vector(nullptr, false)}
{
}

Vec ConcreteStepper::create_vector() const
{
  Vec x;
  MatCreateVecs(_K0, &x, nullptr);
  VecSet(x, 0.0);
  return x;
}

void ConcreteStepper::start(Vec u0, Vec v0, Vec a0, Vec f0)
{
  if (u0)
    throw std::logic_error("a concrete run starts from its static stage");
  Vector zero(create_vector(), false);
  _newmark.set_state(_u_static.vec(), v0 ? v0 : zero.vec(), a0, f0,
                     _f_int_static.vec());
  _system.reset_counts(); // count the time history only
}

void ConcreteStepper::set_contact(
    std::shared_ptr<joint::NonlinearContact> contact)
{
  _contact = std::move(contact);
  _newmark.set_constraint(_contact.get());
}

void ConcreteStepper::set_partition(dynamics::Partition partition)
{
  _newmark.set_partition(std::move(partition));
  _partitioned = true;
}

dynamics::StepReport ConcreteStepper::step(Vec f)
{
  if (_contact)
    _contact->before_step();
  const dynamics::StepReport r = _newmark.step(f);
  if (_contact)
  {
    Vector dv(create_vector(), false);
    if (_contact->after_step(_newmark.v(), dv.vec()))
      _newmark.correct_velocity(dv.vec());
  }
  ++_step;
  _totals.add(r, _system, _step * _newmark.scheme().dt);
  _system.reset_counts();
  return r;
}

void ConcreteStepper::save(engine::Arrays& arrays) const
{
  for (auto& [name, values] : _model.save())
    arrays[name] = values;
  const std::array<Vec, 4> x = {u(), v(), a(), _newmark.f_int()};
  for (int i = 0; i < 4; ++i)
    arrays[state_names[i]] = linalg::owned_values(x[i]);
  arrays["newton"] = _totals.to_array();
  if (_partitioned)
  {
    const dynamics::Kinematics prev = _newmark.prev();
    const std::array<Vec, 3> x = {prev.u, prev.v, prev.a};
    for (int i = 0; i < 3; ++i)
      arrays[prev_names[i]] = linalg::owned_values(x[i]);
  }
  if (_contact)
    joint::save_contact(_contact->contact(), arrays);
}

void ConcreteStepper::restore(const engine::CheckpointData& data)
{
  for (int i = 0; i < 4; ++i)
  {
    _restored[i] = Vector(create_vector(), false);
    linalg::set_owned_values(_restored[i].vec(),
                             engine::checkpoint_array(data, state_names[i]));
  }
  _model.restore(data.arrays);
  _totals.from_array(engine::checkpoint_array(data, "newton"));
  if (_partitioned)
    for (int i = 0; i < 3; ++i)
    {
      _restored_prev[i] = Vector(create_vector(), false);
      linalg::set_owned_values(_restored_prev[i].vec(),
                               engine::checkpoint_array(data, prev_names[i]));
    }
  if (_contact)
    joint::restore_contact(data, _contact->contact());
  _step = data.step;
}

void ConcreteStepper::resume(Vec f)
{
  _newmark.set_state(_restored[0].vec(), _restored[1].vec(), _restored[2].vec(),
                     f, _restored[3].vec());
  if (_partitioned)
    _newmark.set_history({_restored_prev[0].vec(), _restored_prev[1].vec(),
                          _restored_prev[2].vec()},
                         _step);
  for (auto& x : _restored)
    x = Vector(nullptr, false);
  for (auto& x : _restored_prev)
    x = Vector(nullptr, false);
  _system.reset_counts();
}

std::string ConcreteStepper::progress_note(const dynamics::StepReport& r) const
{
  std::string note = "  Newton " + std::to_string(r.iterations);
  if (r.tangent_factorizations)
    note += " (" + std::to_string(r.tangent_factorizations) + " tangents)";
  if (r.cuts)
    note += ", " + std::to_string(r.cuts) + " cuts";
  note += ", inelastic points " + std::to_string(_system.accepted.inelastic);
  if (_contact)
    note += joint::contact_progress_note(_contact->contact(),
                                         _contact->last_step());
  return note;
}
} // namespace damseis::analysis
