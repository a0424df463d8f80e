#include "point_probe.h"
#include "progress.h"
#include <cmath>
#include <dolfinx/common/IndexMap.h>
#include <dolfinx/fem/DofMap.h>
#include <dolfinx/mesh/Mesh.h>
#include <limits>
#include <sstream>

namespace damseis::results
{
namespace
{
/// Nodes closer than this [m] are coincident (the joints' pair tolerance).
constexpr double coincident = 1e-8;
} // namespace

PointProbe::PointProbe(const dolfinx::fem::FunctionSpace& V,
                       std::array<double, 3> x)
{
  _bs = V.dofmap()->index_map_bs();
  const std::int32_t n = V.dofmap()->index_map->size_local();
  const std::vector<double> coords = V.tabulate_dof_coordinates(false);
  struct
  {
    double d;
    int rank;
  } local{std::numeric_limits<double>::infinity(), 0}, global;
  MPI_Comm comm = V.mesh()->comm();
  MPI_Comm_rank(comm, &local.rank);
  std::int32_t best = -1;
  for (std::int32_t i = 0; i < n; ++i)
  {
    const double d = std::hypot(coords[3 * i] - x[0], coords[3 * i + 1] - x[1],
                                coords[3 * i + 2] - x[2]);
    if (d < local.d)
    {
      local.d = d;
      best = i;
    }
  }
  MPI_Allreduce(&local, &global, 1, MPI_DOUBLE_INT, MPI_MINLOC, comm);
  _distance = global.d;
  if (global.rank == local.rank)
    _node = {coords[3 * best], coords[3 * best + 1], coords[3 * best + 2]};
  MPI_Bcast(_node.data(), 3, MPI_DOUBLE, global.rank, comm);

  // Coincident nodes (a joint's two faces): the probe is their mean, the
  // same whatever the numbering (so the number of ranks).
  for (std::int32_t i = 0; i < n; ++i)
  {
    if (std::hypot(coords[3 * i] - _node[0], coords[3 * i + 1] - _node[1],
                   coords[3 * i + 2] - _node[2]) <= coincident)
      _local.push_back(i);
  }
  _count = static_cast<int>(_local.size());
  MPI_Allreduce(MPI_IN_PLACE, &_count, 1, MPI_INT, MPI_SUM, comm);
  if (_count > 1)
  {
    std::ostringstream msg;
    msg << "output point (" << x[0] << ", " << x[1] << ", " << x[2]
        << "): on a joint, the mean of its " << _count << " coincident nodes";
    print(comm, msg.str());
  }
}

std::array<double, 3> PointProbe::value(Vec u) const
{
  std::array<double, 3> v = {0, 0, 0};
  if (_local.empty())
    return v;
  const double* a = nullptr;
  VecGetArrayRead(u, &a);
  for (std::int32_t i : _local)
    for (int k = 0; k < _bs; ++k)
      v[k] += a[i * _bs + k] / _count;
  VecRestoreArrayRead(u, &a);
  return v;
}

std::array<double, 3> PointProbe::value_on_all(Vec u) const
{
  std::array<double, 3> v = value(u);
  MPI_Comm comm;
  PetscObjectGetComm(reinterpret_cast<PetscObject>(u), &comm);
  MPI_Allreduce(MPI_IN_PLACE, v.data(), 3, MPI_DOUBLE, MPI_SUM, comm);
  return v;
}

void reduce_history(MPI_Comm comm, std::vector<double>& history)
{
  MPI_Allreduce(MPI_IN_PLACE, history.data(), history.size(), MPI_DOUBLE,
                MPI_SUM, comm);
}
} // namespace damseis::results
