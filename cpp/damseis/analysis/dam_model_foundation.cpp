// dam_model's rock with mass and a viscous-spring boundary
// (supports.viscous_spring): the keys read into a WaveFoundation.
#include "dam_model_case.h"
#include <cmath>
#include <damseis/geometry/mesh_checks.h>
#include <damseis/geometry/tagged.h>
#include <dolfinx/mesh/Mesh.h>
#include <dolfinx/mesh/MeshTags.h>
#include <dolfinx/mesh/utils.h>

namespace damseis::analysis
{
namespace
{
/// The lowest elevation of the mesh (every rank).
double lowest_point(const geometry::Model& model)
{
  const auto& mesh = *model.mesh;
  const int gdim = mesh.geometry().dim();
  std::span<const double> x = mesh.geometry().x();
  double z = HUGE_VAL;
  for (std::size_t i = 0; i < x.size() / 3; ++i)
    z = std::min(z, x[3 * i + gdim - 1]);
  MPI_Allreduce(MPI_IN_PLACE, &z, 1, MPI_DOUBLE, MPI_MIN, mesh.comm());
  return z;
}

/// The one rock of the regions outside the dam; fails unless they share
/// one material with mass.
fem::Material the_rock(const input::Case& c, const DamModelConfig& cfg)
{
  const Region* rock = nullptr;
  for (const Region& r : cfg.regions)
  {
    if (r.dam)
      continue;
    if (!(r.material.rho > 0.0))
      c.fail("supports.viscous_spring",
             "needs rock with mass, and region \"" + r.group + "\" is massless",
             "regions.rho > 0 for the rock regions");
    if (rock && (rock->material.E != r.material.E ||
                 rock->material.nu != r.material.nu ||
                 rock->material.rho != r.material.rho))
      c.fail("supports.viscous_spring",
             "needs one homogeneous rock, and regions \"" + rock->group +
                 "\" and \"" + r.group + "\" differ",
             "the same E, nu and rho for every region outside the dam (the "
             "free field of layered rock is not available yet)");
    rock = &r;
  }
  if (!rock)
    c.fail("supports.viscous_spring", "needs a rock region",
           "a region outside regions.dam (the foundation)");
  return rock->material;
}
} // namespace

void read_wave_foundation(const input::Case& c, DamModelConfig& cfg)
{
  if (cfg.viscous_spring.empty())
    return;
  if (cfg.concrete.kind != ConcreteModelKind::linear)
    c.fail("supports.viscous_spring", "is not yet available with HTC concrete",
           "material.model = \"linear\", or supports.fixed");
  if (!cfg.initial_velocity.empty())
    c.fail("supports.viscous_spring",
           "is not yet available with an initial velocity",
           "initial.velocity_groups = [], or supports.fixed");
  const fem::Material rock = the_rock(c, cfg);
  const int dim = cfg.dim;
  WaveFoundation w;
  for (const auto& g : cfg.viscous_spring)
    w.boundary_tags.push_back(facet_tag(cfg, g));
  const auto recommended = boundary::SpringFactors::recommended(dim);
  const double an = c.real("foundation.spring_normal"),
               at = c.real("foundation.spring_tangential");
  w.factors = {an < 0 ? recommended.normal : an,
               at < 0 ? recommended.tangential : at};
  const auto centre = c.reals("foundation.centre");
  if (!centre.empty() && static_cast<int>(centre.size()) != dim)
    c.fail("foundation.centre",
           "has " + std::to_string(centre.size()) + " coordinates",
           std::to_string(dim) + " coordinates, or [] for the dam's lowest "
                                 "point");
  w.centre = cfg.seismic.base_point;
  for (std::size_t i = 0; i < centre.size(); ++i)
    w.centre[i] = centre[i];
  w.rock = {rock.E, rock.nu, rock.rho,
            dim == 2 && cfg.plane == fem::PlaneMode::plane_stress};
  w.z_base = lowest_point(cfg.mesh->model);
  w.z_surface = cfg.seismic.base_point[dim - 1];
  if (!(w.z_surface > w.z_base))
    c.fail("supports.viscous_spring",
           "needs rock below the dam, and the dam's lowest point is the "
           "model's",
           "a foundation under the dam");
  cfg.wave = w;
  cfg.seismic.gravity_regions = cfg.seismic.dam_regions;
}
} // namespace damseis::analysis
