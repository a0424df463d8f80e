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
    : _fe(fe), _centre(centre), _factors(factors)
{
  std::vector<std::int32_t> facets;
  for (std::size_t i = 0; i < tags.indices().size(); ++i)
    if (std::find(boundary_tags.begin(), boundary_tags.end(),
                  tags.values()[i]) != boundary_tags.end())
      facets.push_back(tags.indices()[i]);
  std::sort(facets.begin(), facets.end());
  facets.erase(std::unique(facets.begin(), facets.end()), facets.end());
  std::vector<std::int32_t> ones(facets.size(), 1);
  const int tdim = fe.mesh()->topology().dim();
  _marked = std::make_shared<dolfinx::mesh::MeshTags<std::int32_t>>(
      fe.mesh(), tdim - 1, facets, std::move(ones));
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
}

Mat ViscousBoundary::assemble(const ufcx_form& form) const
{
  const int dim = _fe.dim();
  return _fe.assemble_facet_matrix(
      form,
      {{"centre", std::vector<double>(_centre.begin(), _centre.begin() + dim)},
       {"alpha_n", {_factors.normal}},
       {"alpha_t", {_factors.tangential}}},
      *_marked);
}

Mat ViscousBoundary::springs() const
{
  return assemble(boundary_form(_fe.dim(), _fe.degree(), Part::spring));
}

Mat ViscousBoundary::dashpots() const
{
  return assemble(boundary_form(_fe.dim(), _fe.degree(), Part::dashpot));
}

Mat ViscousBoundary::traction_operator() const
{
  return assemble(boundary_form(_fe.dim(), _fe.degree(), Part::traction));
}
} // namespace damseis::fem
