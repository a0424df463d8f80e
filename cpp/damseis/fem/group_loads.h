// Loads on groups of the user's mesh: a traction on facets and a body force
// on cells (forms/group_loads_{2d,3d}.py).
#pragma once

#include "elastic_model.h"
#include <array>
#include <span>

namespace damseis::fem
{
/// The load of the traction `t` [Pa] on the exterior facets `facets`
/// (local indices); zero at fixed dofs. Collective.
Vec assemble_traction(const ElasticModel& fe,
                      std::span<const std::int32_t> facets,
                      const std::array<double, 3>& t);

/// The load of the body force `b` [N/m3] on the cells `cells` (local
/// indices); zero at fixed dofs. Collective.
Vec assemble_body_force(const ElasticModel& fe,
                        std::span<const std::int32_t> cells,
                        const std::array<double, 3>& b);
/// The weights of the mean over a group of cells or facets (`dim`): w_i =
/// the integral of basis function i over the group (every dof, the fixed
/// ones too), so that the mean of a field x over the group's volume or
/// area is sum_i w_i x_i / sum_i w_i per component (for a uniform density,
/// the motion of the group's centre of mass). Collective.
Vec group_weights(const ElasticModel& fe, int dim,
                  std::span<const std::int32_t> entities);
} // namespace damseis::fem
