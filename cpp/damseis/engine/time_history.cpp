#include "time_history.h"
#include <chrono>
#include <damseis/results/progress.h>
#include <dolfinx/la/petsc.h>
#include <stdexcept>

namespace damseis::engine
{
TimeHistory::TimeHistory(MPI_Comm comm, TimeHistorySettings settings,
                         Stepper& stepper, const DynamicLoad& load)
    : _comm(comm), _s(std::move(settings)), _stepper(stepper), _load(load)
{
}

int TimeHistory::start(const InitialState& initial, Vec f)
{
  std::optional<CheckpointData> restart;
  if (_s.restart)
    restart = read_checkpoint(_comm, _s.checkpoint_dir, _s.fingerprint);
  if (!restart)
  {
    // From the initial state (at rest by default) under the load at t = 0.
    dolfinx::la::petsc::Vector a0(_stepper.create_vector(), false);
    if (initial.a)
      VecCopy(initial.a, a0.vec());
    else
      _load.initial_acceleration(a0.vec());
    _load.assemble(0, f);
    _stepper.start(initial.u, initial.v, a0.vec(), f);
    return 0;
  }
  restore_collectively(_comm, _s.checkpoint_dir,
                       [&]
                       {
                         _stepper.restore(*restart);
                         for (Observer* o : _observers)
                           o->restore(*restart);
                       });
  _load.assemble(restart->step, f);
  _stepper.resume(f);
  results::print(_comm, "restarting from the checkpoint at step " +
                            std::to_string(restart->step));
  return restart->step;
}

void TimeHistory::write_checkpoint(int k) const
{
  CheckpointData data;
  data.step = k;
  _stepper.save(data.arrays);
  for (const Observer* o : _observers)
  {
    // Each part's arrays by their own names: a name used twice would
    // overwrite another part's state.
    Arrays arrays;
    o->save(arrays);
    for (auto& [name, values] : arrays)
    {
      if (!data.arrays.emplace(name, std::move(values)).second)
        throw std::logic_error("checkpoint array \"" + name +
                               "\" saved by two parts");
    }
  }
  engine::write_checkpoint(_comm, _s.checkpoint_dir, data, _s.fingerprint);
}

TimeHistoryReport TimeHistory::run(const InitialState& initial)
{
  const int n = _s.steps;
  const double dt = _s.dt;
  dolfinx::la::petsc::Vector f(_stepper.create_vector(), false);
  const int k0 = start(initial, f.vec());
  for (Observer* o : _observers)
    o->begin(k0);

  results::set_stage("time history");
  results::print(_comm, "time history: " + std::to_string(n) + " steps of " +
                            std::to_string(dt) + " s, factorisation " +
                            _stepper.solver_name());
  if (k0 == 0)
  {
    for (Observer* o : _observers)
      o->record(0, 0.0);
  }
  StopSignals signals;
  results::Progress progress(_comm, n - k0);
  const auto loop_start = std::chrono::steady_clock::now();
  for (int k = k0 + 1; k <= n; ++k)
  {
    _load.assemble(k, f.vec());
    dynamics::StepReport report;
    try
    {
      report = _stepper.step(f.vec());
    }
    catch (const dynamics::StepFailure& e)
    {
      throw dynamics::StepFailure("step " + std::to_string(k) + " (t = " +
                                  std::to_string(k * dt) + " s): " + e.what());
    }
    for (Observer* o : _observers)
      o->record(k, k * dt);
    progress.report(k - k0, k * dt, _stepper.progress_note(report));
    signals.checkpoint_or_stop(
        _comm, _s.checkpoints, k, n, [&](int step) { write_checkpoint(step); },
        _s.checkpoint_dir);
  }
  const std::chrono::duration<double> loop =
      std::chrono::steady_clock::now() - loop_start;
  return {k0, loop.count()};
}
} // namespace damseis::engine
