// Collecting per-rank rows of numbers on rank 0 (for CSV tables).
#pragma once

#include <mpi.h>
#include <vector>

namespace damseis::results
{
/// Concatenates every rank's `local` values on rank 0 (rank order); other
/// ranks get an empty vector. Collective.
std::vector<double> gather_to_root(MPI_Comm comm,
                                   const std::vector<double>& local);
} // namespace damseis::results
