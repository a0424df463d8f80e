// Stopping a time history on SIGINT/SIGTERM or at a given step, with a
// checkpoint.
#pragma once

#include <filesystem>
#include <functional>
#include <mpi.h>
#include <stdexcept>

namespace damseis::engine
{
/// Thrown when a run was stopped (a signal, or the step asked for) after
/// writing a checkpoint.
struct Interrupted : std::runtime_error
{
  using std::runtime_error::runtime_error;
};

/// When to write checkpoints and where to stop.
struct CheckpointRule
{
  int every = 0;        ///< steps between checkpoints (0: none)
  int stop_at_step = 0; ///< stop after this step with a checkpoint (0: never)
};

/// SIGINT/SIGTERM request a stop while an instance lives (the previous
/// handlers come back on destruction).
class StopSignals
{
public:
  StopSignals();
  ~StopSignals();
  /// True on every rank if any rank got a signal or `forced`; collective.
  bool requested(MPI_Comm comm, bool forced) const;
  /// After step k of n: calls checkpoint(k) every rule.every steps (not at
  /// the last) and on a stop request (a signal or rule.stop_at_step), then
  /// throws Interrupted on a stop. Collective.
  void checkpoint_or_stop(MPI_Comm comm, const CheckpointRule& rule, int k,
                          int n, const std::function<void(int)>& checkpoint,
                          const std::filesystem::path& ckpt_dir) const;

private:
  void (*_old_int)(int);
  void (*_old_term)(int);
};
} // namespace damseis::engine
