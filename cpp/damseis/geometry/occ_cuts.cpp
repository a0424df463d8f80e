#include "occ_cuts.h"
#include <vector>

namespace damseis::geometry
{
gmsh::vectorpair cut_by_surfaces(const gmsh::vectorpair& volumes,
                                 const gmsh::vectorpair& tools)
{
  namespace occ = gmsh::model::occ;
  gmsh::vectorpair out, pieces, loose;
  std::vector<gmsh::vectorpair> map;
  occ::fragment(volumes, tools, out, map);
  for (const auto& dt : out)
    (dt.first == 3 ? pieces : loose).push_back(dt);
  occ::synchronize();
  gmsh::vectorpair drop;
  for (const auto& [d, t] : loose)
  {
    std::vector<int> up, down;
    gmsh::model::getAdjacencies(d, t, up, down);
    if (up.empty())
      drop.push_back({d, t});
  }
  occ::remove(drop, true);
  return pieces;
}
} // namespace damseis::geometry
