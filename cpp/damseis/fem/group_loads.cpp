#include "group_loads.h"
#include <algorithm>
#include <group_loads_2d_p1.h>
#include <group_loads_2d_p2.h>
#include <group_loads_3d_p1.h>
#include <group_loads_3d_p2.h>

namespace damseis::fem
{
namespace
{
enum class Over
{
  exterior_facets,
  cells,
  interior_facets
};

/// The compiled form: traction (exterior or interior facets) or body
/// force (cells).
const ufcx_form& group_form(int dim, int degree, Over over)
{
  static const std::array<const ufcx_form*, 3> forms[2][2] = {
      {{form_group_loads_2d_p1_L_traction, form_group_loads_2d_p1_L_body_force,
        form_group_loads_2d_p1_L_traction_interior},
       {form_group_loads_2d_p2_L_traction, form_group_loads_2d_p2_L_body_force,
        form_group_loads_2d_p2_L_traction_interior}},
      {{form_group_loads_3d_p1_L_traction, form_group_loads_3d_p1_L_body_force,
        form_group_loads_3d_p1_L_traction_interior},
       {form_group_loads_3d_p2_L_traction, form_group_loads_3d_p2_L_body_force,
        form_group_loads_3d_p2_L_traction_interior}}};
  return *forms[dim == 3][degree == 2][static_cast<int>(over)];
}

Vec assemble(const ElasticModel& fe, std::span<const std::int32_t> entities,
             const std::array<double, 3>& value, Over over,
             bool apply_bc = true)
{
  const int tdim = fe.mesh()->topology().dim();
  std::vector<std::int32_t> indices(entities.begin(), entities.end());
  std::sort(indices.begin(), indices.end());
  indices.erase(std::unique(indices.begin(), indices.end()), indices.end());
  std::vector<std::int32_t> ones(indices.size(), 1);
  const dolfinx::mesh::MeshTags<std::int32_t> group(
      fe.mesh(), over == Over::cells ? tdim : tdim - 1, std::move(indices),
      std::move(ones));
  std::map<std::string, double> constants = {{"value_x", value[0]},
                                             {"value_y", value[1]}};
  if (tdim == 3)
    constants["value_z"] = value[2];
  return fe.assemble_group_load(group_form(tdim, fe.degree(), over), constants,
                                group, over == Over::interior_facets, apply_bc);
}
} // namespace

Vec assemble_traction(const ElasticModel& fe,
                      std::span<const std::int32_t> facets,
                      const std::array<double, 3>& t)
{
  return assemble(fe, facets, t, Over::exterior_facets);
}

Vec assemble_body_force(const ElasticModel& fe,
                        std::span<const std::int32_t> cells,
                        const std::array<double, 3>& b)
{
  return assemble(fe, cells, b, Over::cells);
}

Vec group_weights(const ElasticModel& fe, int dim,
                  std::span<const std::int32_t> entities)
{
  const std::array<double, 3> one = {1.0, 1.0, 1.0};
  if (dim == fe.mesh()->topology().dim())
    return assemble(fe, entities, one, Over::cells, false);
  // A facet group may hold exterior and interior facets: each form
  // integrates its own kind.
  Vec w = assemble(fe, entities, one, Over::exterior_facets, false);
  Vec interior = assemble(fe, entities, one, Over::interior_facets, false);
  VecAXPY(w, 1.0, interior);
  VecDestroy(&interior);
  VecGhostUpdateBegin(w, INSERT_VALUES, SCATTER_FORWARD);
  VecGhostUpdateEnd(w, INSERT_VALUES, SCATTER_FORWARD);
  return w;
}
} // namespace damseis::fem
