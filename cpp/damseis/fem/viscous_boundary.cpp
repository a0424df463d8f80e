#include "viscous_boundary.h"
#include "facet_dofs.h"
#include "group_loads.h"
#include <algorithm>
#include <dolfinx/fem/DofMap.h>
#include <dolfinx/fem/utils.h>
#include <dolfinx/mesh/Mesh.h>
#include <dolfinx/mesh/MeshTags.h>
#include <viscous_boundary_2d_p1.h>
#include <viscous_boundary_2d_p2.h>
#include <viscous_boundary_3d_p1.h>
#include <viscous_boundary_3d_p2.h>

namespace damseis::fem
{
namespace
{
enum class Part
{
  spring,
  dashpot,
  traction
};

const ufcx_form& boundary_form(int dim, int degree, Part part)
{
  static const std::array<const ufcx_form*, 3> forms[2][2] = {
      {{form_viscous_boundary_2d_p1_a_spring,
        form_viscous_boundary_2d_p1_a_dashpot,
        form_viscous_boundary_2d_p1_a_traction},
       {form_viscous_boundary_2d_p2_a_spring,
        form_viscous_boundary_2d_p2_a_dashpot,
        form_viscous_boundary_2d_p2_a_traction}},
      {{form_viscous_boundary_3d_p1_a_spring,
        form_viscous_boundary_3d_p1_a_dashpot,
        form_viscous_boundary_3d_p1_a_traction},
       {form_viscous_boundary_3d_p2_a_spring,
        form_viscous_boundary_3d_p2_a_dashpot,
        form_viscous_boundary_3d_p2_a_traction}}};
  return *forms[dim == 3][degree == 2][static_cast<int>(part)];
}
} // namespace

ViscousBoundary::ViscousBoundary(
    const ElasticModel& fe, const dolfinx::mesh::MeshTags<std::int32_t>& tags,
    const std::vector<int>& boundary_tags, const std::array<double, 3>& centre,
    boundary::SpringFactors factors)
{
  std::vector<std::int32_t> facets;
  for (std::size_t i = 0; i < tags.indices().size(); ++i)
    if (std::find(boundary_tags.begin(), boundary_tags.end(),
                  tags.values()[i]) != boundary_tags.end())
      facets.push_back(tags.indices()[i]);
  std::sort(facets.begin(), facets.end());
  facets.erase(std::unique(facets.begin(), facets.end()), facets.end());
  const int tdim = fe.mesh()->topology().dim();
  // The nodes on those facets (owned and ghost).
  _blocks =
      dolfinx::fem::locate_dofs_topological(*fe.V(), tdim - 1, facets, true);
  // The boundary's measure: the sum of the weights of a unit traction.
  Vec w = group_weights(fe, tdim - 1, facets);
  PetscScalar sum = 0.0;
  VecSum(w, &sum);
  VecDestroy(&w);
  _measure = sum / fe.dim(); // each component carries the measure once
  if (!(_measure > 0.0))
    throw std::invalid_argument(
        "the transmitting boundary has no facets: the mesh has no facets "
        "with the boundary's tags");

  // The three operators over subdomain 1 of the marked facets.
  std::vector<std::int32_t> ones(facets.size(), 1);
  const dolfinx::mesh::MeshTags<std::int32_t> marked(
      fe.mesh(), tdim - 1, std::move(facets), std::move(ones));
  const int dim = fe.dim();
  auto assemble = [&](Part part)
  {
    return dolfinx::la::petsc::Matrix(
        fe.assemble_facet_matrix(
            boundary_form(dim, fe.degree(), part),
            {{"centre",
              std::vector<double>(centre.begin(), centre.begin() + dim)},
             {"alpha_n", {factors.normal}},
             {"alpha_t", {factors.tangential}}},
            marked),
        false);
  };
  _springs = assemble(Part::spring);
  _dashpots = assemble(Part::dashpot);
  _traction = assemble(Part::traction);
}
} // namespace damseis::fem
