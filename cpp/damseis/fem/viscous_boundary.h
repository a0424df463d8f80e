// The viscous-spring boundary of a truncated foundation on the finite
// element model (forms/viscous_boundary_{2d,3d}.py): its springs join the
// stiffness, its dashpots the damping, and its traction operator turns a
// free field's stresses into boundary loads (analysis/free_field_load).
#pragma once

#include "elastic_model.h"
#include <array>
#include <damseis/boundary/viscous_spring.h>
#include <dolfinx/la/petsc.h>
#include <vector>

namespace damseis::fem
{
class ViscousBoundary
{
public:
  /// The boundary on the exterior facets whose tag in `tags` is one of
  /// `boundary_tags`, the springs at distance R from `centre`. Throws
  /// std::invalid_argument if no facet carries those tags. Collective.
  ViscousBoundary(const ElasticModel& fe,
                  const dolfinx::mesh::MeshTags<std::int32_t>& tags,
                  const std::vector<int>& boundary_tags,
                  const std::array<double, 3>& centre,
                  boundary::SpringFactors factors);

  /// Springs K_b, dashpots C_b and the traction operator T (f = T w for a
  /// nodal field w of free-field stresses, see the forms), with the layout
  /// and storage of the model's matrices, assembled once here; the
  /// boundary owns them (share them with PetscObjectReference, e.g.
  /// dolfinx::la::petsc::Matrix(A, true)).
  Mat springs() const { return _springs.mat(); }
  Mat dashpots() const { return _dashpots.mat(); }
  Mat traction_operator() const { return _traction.mat(); }
  /// Local node (block) indices of V on the boundary, owned and ghost.
  const std::vector<std::int32_t>& blocks() const { return _blocks; }
  /// The boundary's area (length in 2D), summed over the ranks.
  double measure() const { return _measure; }

private:
  dolfinx::la::petsc::Matrix _springs{nullptr, false},
      _dashpots{nullptr, false}, _traction{nullptr, false};
  std::vector<std::int32_t> _blocks;
  double _measure = 0.0;
};
} // namespace damseis::fem
