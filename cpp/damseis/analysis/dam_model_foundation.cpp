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
/// The distance from `centre` to the nearest vertex of the facets tagged
/// `boundary` (every rank).
double clearance(const geometry::Model& model, const std::vector<int>& boundary,
                 const std::array<double, 3>& centre)
{
  const auto& mesh = *model.mesh;
  const int tdim = mesh.topology().dim();
  std::span<const double> x = mesh.geometry().x();
  const auto facets = geometry::tagged_entities(*model.facet_tags, boundary);
  const auto nodes =
      dolfinx::mesh::entities_to_geometry(mesh, tdim - 1, facets, false);
  double d = HUGE_VAL;
  for (std::int32_t n : nodes)
    d = std::min(d, std::hypot(x[3 * n] - centre[0], x[3 * n + 1] - centre[1],
                               x[3 * n + 2] - centre[2]));
  MPI_Allreduce(MPI_IN_PLACE, &d, 1, MPI_DOUBLE, MPI_MIN, mesh.comm());
  return d;
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
  for (auto [key, value] : {std::pair{"foundation.spring_normal", an},
                            std::pair{"foundation.spring_tangential", at}})
    if (value != -1.0 && !(value > 0.0))
      c.fail(key, "must be positive (the springs hold the model)",
             "a factor > 0, or -1 for the recommended one");
  w.factors = {an == -1.0 ? recommended.normal : an,
               at == -1.0 ? recommended.tangential : at};
  const auto centre = c.reals("foundation.centre");
  if (!centre.empty() && static_cast<int>(centre.size()) != dim)
    c.fail("foundation.centre",
           "has " + std::to_string(centre.size()) + " coordinates",
           std::to_string(dim) + " coordinates, or [] for the dam's lowest "
                                 "point");
  const geometry::Model& model = cfg.mesh->model;
  const std::set<int> dam(cfg.seismic.dam_regions.begin(),
                          cfg.seismic.dam_regions.end());
  std::set<int> all;
  for (const Region& r : cfg.regions)
    all.insert(cfg.mesh->groups.at(r.group).tag);
  const std::array<double, 3> lowest = extreme_vertices(model, dam)[1];
  w.centre = lowest;
  for (std::size_t i = 0; i < centre.size(); ++i)
    w.centre[i] = centre[i];
  w.rock = {rock.E, rock.nu, rock.rho,
            dim == 2 && cfg.plane == fem::PlaneMode::plane_stress};
  w.z_base = extreme_vertices(model, all)[1][dim - 1];
  w.z_surface = lowest[dim - 1];
  if (!(w.z_surface > w.z_base))
    c.fail("supports.viscous_spring",
           "needs rock below the dam, and the dam's lowest point is the "
           "model's",
           "a foundation under the dam");
  if (!(clearance(model, w.boundary_tags, w.centre) >
        1e-3 * (w.z_surface - w.z_base)))
    c.fail("foundation.centre",
           "is on the viscous-spring boundary (the springs G / R would be "
           "infinite)",
           "a point inside the model, near the dam's base");
  cfg.wave = w;
  cfg.seismic.gravity_regions = cfg.seismic.dam_regions;
}
} // namespace damseis::analysis
