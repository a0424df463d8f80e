// The gmsh library's lifetime: initialised on construction, finalised on
// destruction (rank 0 only uses gmsh).
#pragma once

#include <gmsh.h>

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
  }
  GmshSession(const GmshSession&) = delete;
  GmshSession& operator=(const GmshSession&) = delete;
  ~GmshSession() { gmsh::finalize(); }
};
} // namespace damseis::geometry
