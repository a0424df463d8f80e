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
/// The compiled form: traction (facets) or body force (cells).
const ufcx_form& group_form(int dim, int degree, bool traction)
{
  if (dim == 2)
  {
    if (degree == 1)
      return traction ? *form_group_loads_2d_p1_L_traction
                      : *form_group_loads_2d_p1_L_body_force;
    return traction ? *form_group_loads_2d_p2_L_traction
                    : *form_group_loads_2d_p2_L_body_force;
  }
  if (degree == 1)
    return traction ? *form_group_loads_3d_p1_L_traction
                    : *form_group_loads_3d_p1_L_body_force;
  return traction ? *form_group_loads_3d_p2_L_traction
                  : *form_group_loads_3d_p2_L_body_force;
}

Vec assemble(const ElasticModel& fe, std::span<const std::int32_t> entities,
             const std::array<double, 3>& value, bool traction)
{
  const int tdim = fe.mesh()->topology().dim();
  std::vector<std::int32_t> indices(entities.begin(), entities.end());
  std::sort(indices.begin(), indices.end());
  indices.erase(std::unique(indices.begin(), indices.end()), indices.end());
  std::vector<std::int32_t> ones(indices.size(), 1);
  const dolfinx::mesh::MeshTags<std::int32_t> group(
      fe.mesh(), traction ? tdim - 1 : tdim, std::move(indices),
      std::move(ones));
  std::map<std::string, double> constants = {{"value_x", value[0]},
                                             {"value_y", value[1]}};
  if (tdim == 3)
    constants["value_z"] = value[2];
  return fe.assemble_group_load(group_form(tdim, fe.degree(), traction),
                                constants, group);
}
} // namespace

Vec assemble_traction(const ElasticModel& fe,
                      std::span<const std::int32_t> facets,
                      const std::array<double, 3>& t)
{
  return assemble(fe, facets, t, true);
}

Vec assemble_body_force(const ElasticModel& fe,
                        std::span<const std::int32_t> cells,
                        const std::array<double, 3>& b)
{
  return assemble(fe, cells, b, false);
}
} // namespace damseis::fem
