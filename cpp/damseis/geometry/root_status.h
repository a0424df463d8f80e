// Work done on rank 0 (gmsh) reported to every rank: its status, its error
// message, and any text it produced.
#pragma once

#include <mpi.h>
#include <string>

namespace damseis::geometry
{
/// `text` of rank 0, on every rank. Collective.
std::string broadcast_from_root(MPI_Comm comm, std::string text);

/// Broadcasts rank 0's success flag and error message; if it failed, throws
/// the message on every rank (std::invalid_argument if `invalid`, else
/// std::runtime_error). Collective.
void check_root_status(MPI_Comm comm, bool ok, const std::string& message,
                       bool invalid = false);
} // namespace damseis::geometry
