#include "progress.h"
#include <cstdio>
#include <dolfinx/common/log.h>

namespace damseis::results
{
Progress::Progress(MPI_Comm comm, int total, double interval)
    : _total(total), _interval(interval),
      _start(std::chrono::steady_clock::now())
{
  MPI_Comm_rank(comm, &_rank);
}

double Progress::elapsed() const
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() -
                                       _start)
      .count();
}

void Progress::report(int step, double t, const std::string& extra)
{
  if (_rank != 0)
    return;
  const double now = elapsed();
  if (now - _last < _interval && step != _total)
    return;
  _last = now;
  const double eta = step > 0 ? now / step * (_total - step) : 0.0;
  std::printf("step %6d/%d  t = %8.3f s  elapsed %7.1f s  ETA %7.1f s%s%s\n",
              step, _total, t, now, eta, extra.empty() ? "" : "  ",
              extra.c_str());
  std::fflush(stdout);
}

void quiet_library_logging()
{
  loguru::g_stderr_verbosity = loguru::Verbosity_WARNING;
}

void print(MPI_Comm comm, const std::string& line)
{
  int rank = 0;
  MPI_Comm_rank(comm, &rank);
  if (rank == 0)
  {
    std::printf("%s\n", line.c_str());
    std::fflush(stdout);
  }
}
} // namespace damseis::results

namespace damseis::results
{
namespace
{
std::vector<std::string>& warning_list()
{
  static std::vector<std::string> list;
  return list;
}
} // namespace

void warn(MPI_Comm comm, const std::string& text)
{
  warning_list().push_back(text);
  print(comm, "warning: " + text);
}

const std::vector<std::string>& warnings()
{
  return warning_list();
}

namespace
{
std::string& stage_name()
{
  static std::string name;
  return name;
}
} // namespace

void set_stage(const std::string& name)
{
  stage_name() = name;
}

const std::string& current_stage()
{
  return stage_name();
}
} // namespace damseis::results
