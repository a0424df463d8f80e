// The one time-history engine of damseis: the time loop of every dynamic
// analysis, with restart from a checkpoint, checkpoints every k steps and on
// a stop request (SIGINT/SIGTERM or a given step), progress lines, and the
// observers, written once. What is integrated, loaded and recorded plugs in
// through the parts of parts.h.
#pragma once

#include "parts.h"
#include "stop_signals.h"
#include <cstdint>
#include <filesystem>
#include <mpi.h>
#include <vector>

namespace damseis::engine
{
struct TimeHistorySettings
{
  int steps = 0;   ///< steps of the run (t_k = k dt, k = 0..steps)
  double dt = 0.0; ///< [s]
  CheckpointRule checkpoints;
  bool restart = false; ///< resume from the checkpoint in `checkpoint_dir`
  std::filesystem::path checkpoint_dir;
  /// Identifies the model and case a checkpoint belongs to
  /// (checkpoint::fingerprint of the dof coordinates ^ case_fingerprint).
  std::uint64_t fingerprint = 0;
};

/// The state the run starts from (fresh runs); null members: the stepper's
/// own initial displacement, zero velocity, the load's initial acceleration.
struct InitialState
{
  Vec u = nullptr, v = nullptr, a = nullptr;
};

struct TimeHistoryReport
{
  int restarted_from_step = 0; ///< 0 for a fresh run
  double loop_seconds = 0.0;   ///< wall time of the loop
};

/// The engine. Parts must outlive it; observers are called in the order
/// they were added (an observer may use what an earlier one computed in the
/// same step, such as the stresses).
class TimeHistory
{
public:
  TimeHistory(MPI_Comm comm, TimeHistorySettings settings, Stepper& stepper,
              const DynamicLoad& load);
  void observe(Observer& observer) { _observers.push_back(&observer); }
  /// Starts (from `initial`, or from the checkpoint with settings.restart)
  /// and runs to the last step. Throws Interrupted after writing a checkpoint
  /// on a stop request, dynamics::StepFailure (with the step and time) if a
  /// step cannot be solved. Collective.
  TimeHistoryReport run(const InitialState& initial = {});

private:
  /// The step to start from: 0, or the checkpoint's (everything restored).
  int start(const InitialState& initial, Vec f);
  void write_checkpoint(int k) const;

  MPI_Comm _comm;
  TimeHistorySettings _s;
  Stepper& _stepper;
  const DynamicLoad& _load;
  std::vector<Observer*> _observers;
};
} // namespace damseis::engine
