#include "facet_dofs.h"
#include <damseis/geometry/tagged.h>
#include <dolfinx/common/IndexMap.h>
#include <dolfinx/fem/DirichletBC.h>
#include <dolfinx/fem/DofMap.h>
#include <dolfinx/mesh/Mesh.h>

namespace damseis::fem
{
std::vector<std::int32_t>
owned_blocks_on(const dolfinx::fem::FunctionSpace& V,
                const dolfinx::mesh::MeshTags<std::int32_t>& facet_tags,
                int tag)
{
  const auto facets = geometry::tagged_entities(facet_tags, {tag});
  const int tdim = V.mesh()->topology().dim();
  auto blocks =
      dolfinx::fem::locate_dofs_topological(V, tdim - 1, facets, true);
  const std::int32_t n = V.dofmap()->index_map->size_local();
  std::erase_if(blocks, [n](std::int32_t b) { return b >= n; });
  return blocks;
}
} // namespace damseis::fem
