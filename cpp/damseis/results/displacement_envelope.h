// Envelope over time of the horizontal displacement (relative to a base
// value) at the nodes of a tagged boundary, e.g. along the upstream face of
// a gravity dam (the paper's Fig. 7).
#pragma once

#include <dolfinx/fem/FunctionSpace.h>
#include <dolfinx/mesh/MeshTags.h>
#include <filesystem>
#include <mpi.h>
#include <petscvec.h>
#include <vector>

namespace damseis::results
{
class DisplacementEnvelope
{
public:
  /// Owned nodes of V on the facets tagged `tag`; component `comp`.
  DisplacementEnvelope(const dolfinx::fem::FunctionSpace& V,
                       const dolfinx::mesh::MeshTags<std::int32_t>& facet_tags,
                       int tag, int comp = 0);
  /// u: owned values (layout of V); `offset` is subtracted (e.g. the base
  /// point's displacement) and `reference` (same layout, may be null) too.
  void update(Vec u, double offset, Vec reference);
  /// CSV on rank 0: x, y, max and min displacement [m], sorted by y.
  void write_csv(MPI_Comm comm, const std::filesystem::path& file) const;
  /// The envelope so far (this rank's nodes: max then min), for
  /// checkpoints, and back.
  std::vector<double> save() const;
  void restore(const std::vector<double>& data);

private:
  int _bs = 0, _comp = 0;
  std::vector<std::int32_t> _nodes;
  std::vector<double> _x, _y, _max, _min;
};
} // namespace damseis::results
