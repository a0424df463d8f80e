// Progress lines for long runs (rank 0): step, time, elapsed, ETA.
#pragma once

#include <chrono>
#include <mpi.h>
#include <string>
#include <vector>

namespace damseis::results
{
class Progress
{
public:
  /// @param[in] total number of steps; @param[in] interval seconds between
  /// lines (the last step is always reported).
  Progress(MPI_Comm comm, int total, double interval = 2.0);
  /// Reports step `step` (1-based) at time t; `extra` is appended.
  void report(int step, double t, const std::string& extra = "");
  /// Seconds since construction.
  double elapsed() const;

private:
  int _rank = 0, _total;
  double _interval, _last = -1e300;
  std::chrono::steady_clock::time_point _start;
};

/// Silences DOLFINx's INFO log lines (warnings and errors still show).
void quiet_library_logging();

/// Prints a line on rank 0 only.
void print(MPI_Comm comm, const std::string& line);

/// Prints "warning: <text>" on rank 0 and keeps the text for the run's
/// summary (summary.json "warnings").
void warn(MPI_Comm comm, const std::string& text);
/// The warnings of this process so far.
const std::vector<std::string>& warnings();

/// The stage the run is in ("meshing", "static stage", "modal analysis",
/// "time history", "writing outputs"), named in the one-line report of an
/// internal error (analysis/demo_main). Empty before the analysis starts.
void set_stage(const std::string& name);
const std::string& current_stage();
} // namespace damseis::results
