// The rock's upper surface as a height field over the horizontal plane:
// where the free field of vertically incident waves sees the free surface
// above a point (the ground of its column: the valley floor, the rock under
// the dam, the plateau beyond a canyon's rims). The vertical axis is the
// last coordinate.
#pragma once

#include "gmsh_mesh.h"
#include <array>
#include <vector>

namespace damseis::geometry
{
class GroundSurface
{
public:
  /// The facets of the cells outside `dam_regions` that are exterior and
  /// not tagged with one of `excluded` (the truncated boundary) or that
  /// touch a cell of the dam, gathered on every rank. Collective.
  GroundSurface(const Model& model, const std::vector<int>& dam_regions,
                const std::vector<int>& excluded);

  /// The highest point of the surface above (or below) the horizontal
  /// position of p; where no facet covers it (round-off at the model's
  /// edge), the height of the nearest facet vertex.
  double height(const std::array<double, 3>& p) const;
  std::size_t size() const { return _facets; }

private:
  int _dim = 0; ///< spatial dimension; facets have _dim vertices
  std::size_t _facets = 0;
  std::vector<double> _x; ///< facet vertices, _dim x 3 coordinates each
  /// Bucket grid over the horizontal bounding box: facets per bucket.
  std::array<double, 2> _lo{}, _h{};
  std::array<int, 2> _n{1, 1};
  std::vector<std::vector<std::int32_t>> _buckets;
  std::array<int, 2> bucket_of(const double* p) const;
};
} // namespace damseis::geometry
