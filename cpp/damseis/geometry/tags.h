// Physical tags shared by the geometry builders, the UFL forms (forms/*.py)
// and the solvers. Keep in sync with the comments in forms/elasticity_*.py.
#pragma once

#include <string>

namespace damseis::geometry::tags
{
/// Cell (region) tags.
enum Region : int
{
  dam = 1,
  foundation = 2,
  /// A second rock region (2D sections with a split foundation block: the
  /// right half, or the lower layer).
  foundation_2 = 3,
  /// The structured band of a transmitting boundary along the
  /// foundation's sides and bottom (its explicit elements).
  foundation_band = 4,
};

/// Facet (boundary) tags.
enum Boundary : int
{
  /// dam upstream face (2D: the whole face, wetted below the water level;
  /// 3D meshes that follow the water line: its dry part, see
  /// upstream_wetted)
  upstream_face = 1,
  downstream_face = 2, ///< dam downstream face
  crest = 3,           ///< dam crest
  dam_base = 4,        ///< dam base: rigid base or dam-foundation interface
  foundation_bottom = 5,
  foundation_sides = 6,
  reservoir_floor = 7, ///< foundation top surface upstream of the dam
  foundation_top_downstream = 8,
  // 3D arch-dam models (arch_mesh.h). There upstream_face, downstream_face,
  // crest and dam_base (= the dam-foundation interface, abutments included)
  // keep their meaning; foundation_sides are the cross-canyon ends (x = min,
  // max); reservoir_floor is the rock surface of the valley upstream of the
  // dam (floor and banks) and foundation_top_downstream the valley surface
  // downstream of it.
  foundation_top = 9,         ///< 3D: rock plateau at the crest elevation
  foundation_upstream = 10,   ///< 3D: far boundary y = y_min (upstream end)
  foundation_downstream = 11, ///< 3D: far boundary y = y_max

  /// 3D: the part of the upstream face below the reservoir level (arch
  /// meshes built with a water level; upstream_face is then the dry part
  /// above it, and the mesh has edges along the water line).
  upstream_wetted = 12,
  /// 3D: contraction joints: joint k (0 for label A) has the facet tags
  /// joint_side1(k) = 100 + 2k (side 1, the block on its left, smaller x)
  /// and joint_side2(k) = 101 + 2k (side 2, duplicated nodes).
  joint_base = 100,
};

/// Facet tag of side 1 of joint k (k = 0 for label 'A').
constexpr int joint_side1(int k)
{
  return joint_base + 2 * k;
}
/// Facet tag of side 2 of joint k.
constexpr int joint_side2(int k)
{
  return joint_base + 2 * k + 1;
}
/// True if the facet tag is a joint side; then (tag - joint_base) / 2 is
/// the joint's label index and (tag - joint_base) % 2 + 1 the side.
constexpr bool is_joint_tag(int tag)
{
  return tag >= joint_base and tag < joint_base + 2 * 26;
}

/// The name of a region tag ("dam", "foundation"), as the builders name
/// their physical groups in gmsh (and so in exported mesh files).
inline std::string region_name(int tag)
{
  switch (tag)
  {
  case dam:
    return "dam";
  case foundation:
    return "foundation";
  case foundation_2:
    return "foundation_2";
  case foundation_band:
    return "foundation_band";
  default:
    return "region_" + std::to_string(tag);
  }
}

/// The name of a boundary tag: the enumerator's name, "joint_A_side1" ...
/// for joints.
inline std::string boundary_name(int tag)
{
  if (is_joint_tag(tag))
    return std::string("joint_") +
           static_cast<char>('A' + (tag - joint_base) / 2) + "_side" +
           std::to_string((tag - joint_base) % 2 + 1);
  switch (tag)
  {
  case upstream_face:
    return "upstream_face";
  case downstream_face:
    return "downstream_face";
  case crest:
    return "crest";
  case dam_base:
    return "dam_base";
  case foundation_bottom:
    return "foundation_bottom";
  case foundation_sides:
    return "foundation_sides";
  case reservoir_floor:
    return "reservoir_floor";
  case foundation_top_downstream:
    return "foundation_top_downstream";
  case foundation_top:
    return "foundation_top";
  case foundation_upstream:
    return "foundation_upstream";
  case foundation_downstream:
    return "foundation_downstream";
  case upstream_wetted:
    return "upstream_wetted";
  default:
    return "boundary_" + std::to_string(tag);
  }
}
} // namespace damseis::geometry::tags

namespace damseis
{
/// The tags are used everywhere: damseis::tags names them for short.
namespace tags = geometry::tags;
} // namespace damseis
