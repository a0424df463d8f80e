// The degrees of freedom on tagged facets.
#pragma once

#include <cstdint>
#include <dolfinx/fem/FunctionSpace.h>
#include <dolfinx/mesh/MeshTags.h>
#include <vector>

namespace damseis::fem
{
/// The owned blocks (nodes) of V on the facets tagged `tag`, local indices.
std::vector<std::int32_t>
owned_blocks_on(const dolfinx::fem::FunctionSpace& V,
                const dolfinx::mesh::MeshTags<std::int32_t>& facet_tags,
                int tag);
} // namespace damseis::fem
