// The entities (local indices, owned and ghost) that carry given values in
// mesh tags: the cells of regions, the facets of boundary groups.
#pragma once

#include <cstdint>
#include <dolfinx/mesh/MeshTags.h>
#include <vector>

namespace damseis::geometry
{
/// The entities of `tags` whose value is one of `values`, in tag order.
inline std::vector<std::int32_t>
tagged_entities(const dolfinx::mesh::MeshTags<std::int32_t>& tags,
                const std::vector<int>& values)
{
  std::vector<std::int32_t> out;
  for (std::size_t i = 0; i < tags.indices().size(); ++i)
  {
    for (int v : values)
    {
      if (tags.values()[i] == v)
      {
        out.push_back(tags.indices()[i]);
        break;
      }
    }
  }
  return out;
}
} // namespace damseis::geometry
