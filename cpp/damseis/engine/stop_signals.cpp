#include "stop_signals.h"
#include <csignal>

namespace damseis::engine
{
namespace
{
volatile std::sig_atomic_t stop_requested = 0;
extern "C" void request_stop(int)
{
  stop_requested = 1;
}
} // namespace

StopSignals::StopSignals()
{
  stop_requested = 0;
  _old_int = std::signal(SIGINT, request_stop);
  _old_term = std::signal(SIGTERM, request_stop);
}

StopSignals::~StopSignals()
{
  std::signal(SIGINT, _old_int);
  std::signal(SIGTERM, _old_term);
}

bool StopSignals::requested(MPI_Comm comm, bool forced) const
{
  int stop = stop_requested || forced, any = 0;
  MPI_Allreduce(&stop, &any, 1, MPI_INT, MPI_MAX, comm);
  return any != 0;
}

void StopSignals::checkpoint_or_stop(
    MPI_Comm comm, const CheckpointRule& rule, int k, int n,
    const std::function<void(int)>& checkpoint,
    const std::filesystem::path& ckpt_dir) const
{
  const bool stop = requested(comm, k == rule.stop_at_step);
  if (stop || (rule.every > 0 && k % rule.every == 0 && k < n))
    checkpoint(k);
  if (stop)
  {
    throw Interrupted("stopped at step " + std::to_string(k) +
                      "; checkpoint written to " + ckpt_dir.string() +
                      "; resume with --set run.restart=true");
  }
}
} // namespace damseis::engine
