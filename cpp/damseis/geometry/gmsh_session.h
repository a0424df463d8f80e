// The gmsh library's lifetime: initialised on construction, finalised on
// destruction (rank 0 only uses gmsh). While it lives, an abort inside
// gmsh (an assertion of its mesher, e.g. tetgen's boundary recovery on
// too thin a face) ends the process with one line and exit code 1
// instead of a backtrace and a core.
#pragma once

#include <csignal>
#include <gmsh.h>
#include <unistd.h>

namespace damseis::geometry
{
/// Initialises gmsh on construction and finalises it on destruction.
class GmshSession
{
public:
  explicit GmshSession(bool verbose)
  {
    gmsh::initialize(0, nullptr, false);
    gmsh::option::setNumber("General.Terminal", verbose ? 1 : 0);
    gmsh::option::setNumber("General.Verbosity", verbose ? 5 : 0);
    gmsh::option::setNumber("General.NumThreads", 1);
    _previous = std::signal(SIGABRT, &GmshSession::on_abort);
  }
  GmshSession(const GmshSession&) = delete;
  GmshSession& operator=(const GmshSession&) = delete;
  ~GmshSession()
  {
    std::signal(SIGABRT, _previous);
    gmsh::finalize();
  }

private:
  static void on_abort(int)
  {
    static const char line[] =
        "damseis: internal error during meshing: gmsh aborted (an "
        "assertion of its mesher); expected another mesh.size, "
        "mesh.size_far or foundation.band_size\n";
    // write(2) and _exit(2) only: async-signal-safe.
    [[maybe_unused]] const ssize_t n = ::write(2, line, sizeof(line) - 1);
    ::_exit(1);
  }
  void (*_previous)(int) = SIG_DFL;
};
} // namespace damseis::geometry
