// dam_model's rock with mass and a viscous-spring boundary
// (supports.viscous_spring) or a multi-transmitting one
// (supports.transmitting, its band foundation.band): the keys read into a
// WaveFoundation.
#include "dam_model_case.h"
#include "run_outputs.h"
#include "transmitting_keys.h"
#include <algorithm>
#include <cmath>
#include <damseis/fem/mtf_boundary.h>
#include <damseis/geometry/mesh_checks.h>
#include <damseis/geometry/tagged.h>
#include <dolfinx/common/IndexMap.h>
#include <dolfinx/mesh/Mesh.h>
#include <dolfinx/mesh/MeshTags.h>
#include <dolfinx/mesh/utils.h>
#include <sstream>

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

/// The one rock of the regions outside the dam; fails (naming the
/// support's `key`) unless they share one material with mass.
fem::Material the_rock(const input::Case& c, const DamModelConfig& cfg,
                       const std::string& key)
{
  const Region* rock = nullptr;
  for (const Region& r : cfg.regions)
  {
    if (r.dam)
      continue;
    if (!(r.material.rho > 0.0))
      c.fail(key,
             "needs rock with mass, and region \"" + r.group + "\" is massless",
             "regions.rho > 0 for the rock regions");
    if (rock && (rock->material.E != r.material.E ||
                 rock->material.nu != r.material.nu ||
                 rock->material.rho != r.material.rho))
      c.fail(key,
             "needs one homogeneous rock, and regions \"" + rock->group +
                 "\" and \"" + r.group + "\" differ",
             "the same E, nu and rho for every region outside the dam (the "
             "free field of layered rock is not available yet)");
    rock = &r;
  }
  if (!rock)
    c.fail(key, "needs a rock region",
           "a region outside regions.dam (the foundation)");
  return rock->material;
}

/// The mean edge length of the owned facets tagged `tags` (every rank).
double mean_facet_edge(const geometry::Model& model,
                       const std::vector<int>& tags)
{
  const auto& mesh = *model.mesh;
  const int fdim = mesh.topology().dim() - 1;
  mesh.topology_mutable().create_entities(fdim);
  const std::int32_t owned = mesh.topology().index_map(fdim)->size_local();
  std::vector<std::int32_t> facets;
  for (std::int32_t f : geometry::tagged_entities(*model.facet_tags, tags))
    if (f < owned)
      facets.push_back(f);
  const auto nodes =
      dolfinx::mesh::entities_to_geometry(mesh, fdim, facets, false);
  std::span<const double> x = mesh.geometry().x();
  const int nv = fdim + 1; // vertices of a facet
  double sum[2] = {0.0, 0.0};
  for (std::size_t f = 0; f < facets.size(); ++f)
    for (int a = 0; a < nv; ++a)
      for (int b = a + 1; b < nv; ++b)
      {
        const std::int32_t i = nodes[nv * f + a], j = nodes[nv * f + b];
        sum[0] += std::hypot(x[3 * i] - x[3 * j], x[3 * i + 1] - x[3 * j + 1],
                             x[3 * i + 2] - x[3 * j + 2]);
        sum[1] += 1.0;
      }
  MPI_Allreduce(MPI_IN_PLACE, sum, 2, MPI_DOUBLE, MPI_SUM, mesh.comm());
  return sum[1] > 0.0 ? sum[0] / sum[1] : 0.0;
}

/// supports.transmitting: the formula's keys, its band (cell groups of
/// rock), its node spacing, and the time step against s <= 1.
Transmitting read_transmitting(const input::Case& c, const DamModelConfig& cfg,
                               const boundary::Rock& rock,
                               const std::vector<int>& boundary_tags)
{
  Transmitting t = read_formula_keys(c, cfg.order, true);
  const auto band = c.strings("foundation.band");
  if (band.empty())
    c.fail("foundation.band", "is empty",
           "the cell groups of the band along supports.transmitting (rock "
           "regions reaching 2N node spacings inward of the boundary)");
  for (const auto& g : band)
  {
    auto it = std::find_if(cfg.regions.begin(), cfg.regions.end(),
                           [&](const Region& r) { return r.group == g; });
    if (it == cfg.regions.end())
      c.fail("foundation.band", "names \"" + g + "\", which is not a region",
             "cell groups of regions.groups outside regions.dam");
    if (it->dam)
      c.fail("foundation.band", "names \"" + g + "\", a region of the dam",
             "rock regions along supports.transmitting");
    t.band_regions.push_back(cfg.mesh->groups.at(g).tag);
  }
  t.spacing = c.real("foundation.mtf_spacing");
  if (t.spacing == -1.0)
    t.spacing = mean_facet_edge(cfg.mesh->model, boundary_tags) / cfg.order;
  else if (!(t.spacing > 0.0))
    c.fail("foundation.mtf_spacing", "must be positive",
           "the node spacing along the normals [m], or -1 (the boundary "
           "facets' mean edge / mesh.order)");
  // Every stencil point in the band (the formula's own set-up, on the
  // displacement space of the run).
  const geometry::Model& model = cfg.mesh->model;
  const auto V = fem::displacement_space(model.mesh, cfg.order);
  const std::string gap =
      fem::band_gap(*V, *model.facet_tags, boundary_tags,
                    region_cells(model, t.band_regions), t.order, t.spacing);
  if (!gap.empty())
  {
    std::ostringstream fix;
    fix << "band cells reaching 2N node spacings = " << 2 * t.order * t.spacing
        << " m inward of every node of supports.transmitting, or a smaller "
           "foundation.mtf_spacing or foundation.mtf_order";
    c.fail("foundation.band", gap, fix.str());
  }
  if (cfg.contact.enabled && cfg.concrete.kind == ConcreteModelKind::linear)
    c.fail("supports.transmitting",
           "takes contact joints in the nonlinear engine only",
           "material.model = \"elastic\" (the same linear elastic dam in the "
           "nonlinear engine), or supports.viscous_spring");
  check_transmitting_step(c, cfg.seismic.scheme.alpha, t,
                          cfg.concrete.kind != ConcreteModelKind::linear, rock,
                          cfg.seismic.scheme.dt,
                          "a larger foundation.mtf_spacing (a band of larger "
                          "cells)");
  return t;
}
} // namespace

void read_wave_foundation(const input::Case& c, DamModelConfig& cfg)
{
  const bool mtf = !cfg.transmitting.empty();
  if (cfg.viscous_spring.empty() && !mtf)
    return;
  const std::string support =
      mtf ? "supports.transmitting" : "supports.viscous_spring";
  if (!cfg.initial_velocity.empty())
    c.fail(support, "is not yet available with an initial velocity",
           "initial.velocity_groups = [], or supports.fixed");
  const fem::Material rock = the_rock(c, cfg, support);
  const int dim = cfg.dim;
  WaveFoundation w;
  for (const auto& g : mtf ? cfg.transmitting : cfg.viscous_spring)
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
    c.fail(support,
           "needs rock below the dam, and the dam's lowest point is the "
           "model's",
           "a foundation under the dam");
  if (!mtf && !(clearance(model, w.boundary_tags, w.centre) >
                1e-3 * (w.z_surface - w.z_base)))
    c.fail("foundation.centre",
           "is on the viscous-spring boundary (the springs G / R would be "
           "infinite)",
           "a point inside the model, near the dam's base");
  if (mtf)
    w.mtf = read_transmitting(c, cfg, w.rock, w.boundary_tags);
  cfg.wave = w;
  cfg.seismic.gravity_regions = cfg.seismic.dam_regions;
}
} // namespace damseis::analysis
