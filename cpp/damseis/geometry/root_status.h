// Work done on rank 0 (gmsh) reported to every rank: its status, its error
// message, and any text it produced.
#pragma once

#include <functional>
#include <mpi.h>
#include <string>

namespace damseis::geometry
{
/// `text` of rank `root` (0 by default), on every rank. Collective.
std::string broadcast_from_root(MPI_Comm comm, std::string text, int root = 0);

/// Broadcasts rank 0's success flag and error message; if it failed, throws
/// the message on every rank (std::invalid_argument if `invalid`, else
/// std::runtime_error). Collective.
void check_root_status(MPI_Comm comm, bool ok, const std::string& message,
                       bool invalid = false);

/// How on_root words an exception of rank 0's work.
struct RootErrors
{
  std::string prefix;  ///< before the message of a std::exception
  std::string unknown; ///< the message for anything else (gmsh throws strings)
  bool keep_invalid = false; ///< std::invalid_argument as such, unprefixed
};

/// Runs `work` on rank 0 and throws what it threw on every rank (worded by
/// `errors`; std::runtime_error unless kept invalid). Collective.
void on_root(MPI_Comm comm, const std::function<void()>& work,
             const RootErrors& errors);
} // namespace damseis::geometry
