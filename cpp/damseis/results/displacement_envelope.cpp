#include "displacement_envelope.h"
#include "gather.h"
#include <algorithm>
#include <damseis/geometry/tagged.h>
#include <dolfinx/common/IndexMap.h>
#include <dolfinx/fem/DirichletBC.h>
#include <dolfinx/fem/DofMap.h>
#include <dolfinx/mesh/Mesh.h>
#include <fstream>
#include <limits>
#include <numeric>
#include <stdexcept>
#include <string>

namespace damseis::results
{
DisplacementEnvelope::DisplacementEnvelope(
    const dolfinx::fem::FunctionSpace& V,
    const dolfinx::mesh::MeshTags<std::int32_t>& facet_tags, int tag, int comp)
    : _bs(V.dofmap()->index_map_bs()), _comp(comp)
{
  const auto facets = geometry::tagged_entities(facet_tags, {tag});
  const int tdim = V.mesh()->topology().dim();
  auto blocks = dolfinx::fem::locate_dofs_topological(V, tdim - 1, facets);
  const std::int32_t owned = V.dofmap()->index_map->size_local();
  const std::vector<double> X = V.tabulate_dof_coordinates(false);
  for (std::int32_t b : blocks)
  {
    if (b >= owned)
      continue;
    _nodes.push_back(b);
    _x.push_back(X[3 * b]);
    _y.push_back(X[3 * b + 1]);
  }
  _max.assign(_nodes.size(), -std::numeric_limits<double>::infinity());
  _min.assign(_nodes.size(), std::numeric_limits<double>::infinity());
}

void DisplacementEnvelope::update(Vec u, double offset, Vec reference)
{
  const double* a = nullptr;
  const double* r = nullptr;
  VecGetArrayRead(u, &a);
  if (reference)
    VecGetArrayRead(reference, &r);
  for (std::size_t i = 0; i < _nodes.size(); ++i)
  {
    const std::int32_t k = _nodes[i] * _bs + _comp;
    const double v = a[k] - offset - (r ? r[k] : 0.0);
    _max[i] = std::max(_max[i], v);
    _min[i] = std::min(_min[i], v);
  }
  if (reference)
    VecRestoreArrayRead(reference, &r);
  VecRestoreArrayRead(u, &a);
}

std::vector<double> DisplacementEnvelope::save() const
{
  std::vector<double> data(_max);
  data.insert(data.end(), _min.begin(), _min.end());
  return data;
}

void DisplacementEnvelope::restore(const std::vector<double>& data)
{
  if (data.size() != 2 * _max.size())
    throw std::runtime_error("displacement envelope in the checkpoint has " +
                             std::to_string(data.size()) +
                             " values, expected " +
                             std::to_string(2 * _max.size()));
  std::copy(data.begin(), data.begin() + _max.size(), _max.begin());
  std::copy(data.begin() + _max.size(), data.end(), _min.begin());
}

void DisplacementEnvelope::write_csv(MPI_Comm comm,
                                     const std::filesystem::path& file) const
{
  std::vector<double> local;
  for (std::size_t i = 0; i < _nodes.size(); ++i)
    local.insert(local.end(), {_x[i], _y[i], _max[i], _min[i]});
  int rank = 0;
  MPI_Comm_rank(comm, &rank);
  const std::vector<double> all = gather_to_root(comm, local);
  if (rank != 0)
    return;
  std::vector<std::size_t> order(all.size() / 4);
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(),
            [&](std::size_t a, std::size_t b)
            { return all[4 * a + 1] < all[4 * b + 1]; });
  std::ofstream csv(file);
  csv << "x_m,y_m,max_m,min_m\n";
  csv.precision(10);
  for (std::size_t i : order)
    csv << all[4 * i] << "," << all[4 * i + 1] << "," << all[4 * i + 2] << ","
        << all[4 * i + 3] << "\n";
}
} // namespace damseis::results
