// Physical tags shared by the geometry builders, the UFL forms (forms/*.py)
// and the solvers. Keep in sync with the comments in forms/elasticity_*.py.
#pragma once

namespace damseis::tags
{
/// Cell (region) tags.
enum Region : int
{
  dam = 1,
  foundation = 2,
};

/// Facet (boundary) tags.
enum Boundary : int
{
  upstream_face = 1,   ///< dam upstream face (wetted below the water level)
  downstream_face = 2, ///< dam downstream face
  crest = 3,           ///< dam crest
  dam_base = 4,        ///< dam base: rigid base or dam-foundation interface
  foundation_bottom = 5,
  foundation_sides = 6,
  reservoir_floor = 7, ///< foundation top surface upstream of the dam
  foundation_top_downstream = 8,
};
} // namespace damseis::tags
