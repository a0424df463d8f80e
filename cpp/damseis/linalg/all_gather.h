// Every rank's values, concatenated in rank order, on every rank.
#pragma once

#include <cstdint>
#include <mpi.h>
#include <numeric>
#include <type_traits>
#include <vector>

namespace damseis::linalg
{
template <typename T>
MPI_Datatype mpi_type()
{
  if constexpr (std::is_same_v<T, double>)
    return MPI_DOUBLE;
  else if constexpr (std::is_same_v<T, std::int64_t>)
    return MPI_INT64_T;
  else if constexpr (std::is_same_v<T, std::int32_t>)
    return MPI_INT32_T;
  else
    static_assert(sizeof(T) == 0, "all_gather: unsupported type");
}

/// The values `v` of every rank of `comm`, in rank order (collective).
template <typename T>
std::vector<T> all_gather(MPI_Comm comm, const std::vector<T>& v)
{
  int size = 1;
  MPI_Comm_size(comm, &size);
  int n = static_cast<int>(v.size());
  std::vector<int> counts(size), offsets(size + 1, 0);
  MPI_Allgather(&n, 1, MPI_INT, counts.data(), 1, MPI_INT, comm);
  std::partial_sum(counts.begin(), counts.end(), offsets.begin() + 1);
  std::vector<T> all(offsets.back());
  MPI_Allgatherv(v.data(), n, mpi_type<T>(), all.data(), counts.data(),
                 offsets.data(), mpi_type<T>(), comm);
  return all;
}
} // namespace damseis::linalg
