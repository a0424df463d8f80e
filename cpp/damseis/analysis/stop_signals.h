// Stopping a time history on SIGINT/SIGTERM or at a given step, with a
// checkpoint.
#pragma once

#include "seismic_settings.h"
#include <filesystem>
#include <functional>
#include <mpi.h>

namespace damseis::analysis
{
/// SIGINT/SIGTERM request a stop while an instance lives (the previous
/// handlers come back on destruction).
class StopSignals
{
public:
  StopSignals();
  ~StopSignals();
  /// True on every rank if any rank got a signal or `forced`; collective.
  bool requested(MPI_Comm comm, bool forced) const;
  /// After step k of n: calls checkpoint(k) every s.checkpoint_every steps
  /// (not at the last) and on a stop request (a signal or
  /// s.stop_at_step), then throws Interrupted on a stop. Collective.
  void checkpoint_or_stop(MPI_Comm comm, const SeismicSettings& s, int k, int n,
                          const std::function<void(int)>& checkpoint,
                          const std::filesystem::path& ckpt_dir) const;

private:
  void (*_old_int)(int);
  void (*_old_term)(int);
};
} // namespace damseis::analysis
