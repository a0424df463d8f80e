#include "gravity_dam_loads.h"
#include <cmath>
#include <damseis/geometry/tags.h>
#include <dolfinx/fem/utils.h>
#include <gravity_loads_2d_p1.h>
#include <gravity_loads_2d_p2.h>
#include <numbers>
#include <stdexcept>

namespace damseis::fem
{
double Silt::k() const
{
  const double t =
      std::tan((45.0 - 0.5 * friction_angle_deg) * std::numbers::pi / 180.0);
  return unit_weight * t * t;
}

namespace
{
const ufcx_form& form_of(const ElasticModel& fe, bool silt)
{
  if (fe.dim() != 2)
    throw std::invalid_argument("silt and uplift loads are 2D only");
  if (fe.degree() == 1)
    return silt ? *form_gravity_loads_2d_p1_L_silt
                : *form_gravity_loads_2d_p1_L_uplift;
  return silt ? *form_gravity_loads_2d_p2_L_silt
              : *form_gravity_loads_2d_p2_L_uplift;
}
} // namespace

Vec assemble_silt(const ElasticModel& fe, const Silt& s)
{
  return fe.assemble_load_form(form_of(fe, true),
                               {{"silt_k", s.k()}, {"silt_level", s.level}});
}

Vec assemble_uplift(const ElasticModel& fe, const Uplift& u)
{
  const double h1 = u.head_upstream, h2 = u.head_downstream;
  // Indicator of the dam cells (DG0).
  auto space = fe.degree() == 1
                   ? functionspace_form_gravity_loads_2d_p1_L_uplift
                   : functionspace_form_gravity_loads_2d_p2_L_uplift;
  auto Q = std::make_shared<dolfinx::fem::FunctionSpace>(
      dolfinx::fem::create_functionspace(space, "in_dam", fe.model().mesh));
  auto in_dam = std::make_shared<dolfinx::fem::Function<double>>(Q);
  const auto& tags = *fe.model().cell_tags;
  std::span<double> a = in_dam->x()->mutable_array();
  for (std::size_t i = 0; i < tags.indices().size(); ++i)
  {
    if (tags.values()[i] == tags::dam)
      a[Q->dofmap()->cell_dofs(tags.indices()[i])[0]] = 1.0;
  }
  in_dam->x()->scatter_fwd();
  return fe.assemble_load_form(
      form_of(fe, false),
      {{"p_heel", u.gamma_w * h1},
       {"p_drain", u.gamma_w * (h2 + u.alpha * (h1 - h2))},
       {"p_toe", u.gamma_w * h2},
       {"x_heel", u.x_heel},
       {"x_drain", u.x_drain},
       {"x_toe", u.x_toe}},
      {{"in_dam", in_dam}});
}
} // namespace damseis::fem
