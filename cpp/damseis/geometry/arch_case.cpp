// Case-file keys of the arch-dam geometry.
#include "arch_case.h"
#include "mesh_estimate.h"

#include <stdexcept>
#include <string>

namespace damseis::geometry
{
void arch_dam_schema(input::Schema& s)
{
  // Dam body (default: the paper's 102 m three-centred dam, assumed
  // tables documented in demos/arch_dam/presets/paper_102m_v.toml)
  s.real("dam.height", "102.0", "m", "crest elevation above the crown base")
      .between(0.1, 500);
  s.real_array("dam.levels", "[0.0, 25.5, 51.0, 76.5, 102.0]", "m",
               "elevations of the level tables (0 ... dam.height)")
      .between(0, 500);
  s.real_array("dam.crown_upstream_y", "[4.0, -1.0, -2.5, -1.8, 0.0]", "m",
               "y of the upstream face of the crown cantilever per level "
               "(downstream positive)")
      .between(-2000, 2000);
  s.real_array("dam.crown_thickness", "[24.6, 19.0, 13.6, 8.9, 5.0]", "m",
               "crown thickness per level")
      .above(0)
      .at_most(300);
  s.real_array("dam.abutment_thickness", "[29.5, 24.0, 18.0, 12.0, 7.0]", "m",
               "arch thickness at the canyon walls per level")
      .above(0)
      .at_most(300);
  s.string("dam.arch_shape", "three_centred", "-",
           "plan shape of the arch rings (centre line)",
           {"three_centred", "parabolic", "circular"});
  s.real_array("dam.radius_central", "[45.0, 70.0, 92.0, 110.0, 122.0]", "m",
               "centre-line radius at the crown per level (parabolic: "
               "radius of curvature at the crown)")
      .above(0)
      .at_most(1e4);
  s.real_array("dam.radius_lateral", "[75.0, 115.0, 155.0, 190.0, 215.0]", "m",
               "three-centred: radius of the lateral arcs per level")
      .above(0)
      .at_most(1e4);
  s.real_array("dam.central_angle", "[25.0, 25.0, 25.0, 25.0, 25.0]", "deg",
               "three-centred: half-angle of the central arc per level")
      .between_exclusive(0, 89.5);
  s.real("dam.thickening_exponent", "2.0", "-",
         "T = T_c + (T_a - T_c) |x/X|^p along the arch: p")
      .above(0)
      .at_most(20);
  s.string("dam.interpolation", "cubic", "-",
           "interpolation of the level tables in z", {"cubic", "linear"});
  // Canyon
  s.string("canyon.shape", "v", "-",
           "canyon cross-section: v, u or points (piecewise-linear walls)",
           {"v", "u", "points"});
  s.real("canyon.bottom_width", "24.0", "m", "v, u: floor width at z = 0")
      .above(0)
      .at_most(5000);
  s.real("canyon.crest_width", "260.8", "m",
         "v, u: valley width at the crest elevation")
      .above(0)
      .at_most(10000);
  s.real("canyon.u_radius", "40.0", "m", "u: radius of the floor fillets")
      .above(0)
      .at_most(5000);
  s.integer("canyon.u_segments", "12", "-",
            "u: straight segments per fillet (the walls are polylines)")
      .between(1, 200);
  s.real_array("canyon.z", "[]", "m",
               "points: elevations of the wall points, 0 ... >= dam.height")
      .between(0, 1000);
  s.real_array("canyon.x_left", "[]", "m",
               "points: x of the left wall (< 0) at canyon.z")
      .at_least(-5000)
      .below(0);
  s.real_array("canyon.x_right", "[]", "m",
               "points: x of the right wall (> 0) at canyon.z")
      .above(0)
      .at_most(5000);
  // Foundation block
  s.real("foundation.extent_upstream", "1.0", "H",
         "foundation beyond the most upstream dam point, x dam height")
      .above(0)
      .at_most(20);
  s.real("foundation.extent_downstream", "1.0", "H",
         "foundation beyond the most downstream dam point, x dam height")
      .above(0)
      .at_most(20);
  s.real("foundation.extent_below", "1.0", "H",
         "foundation depth below the canyon floor, x dam height")
      .above(0)
      .at_most(20);
  s.real("foundation.extent_beyond", "1.0", "H",
         "foundation beyond each valley rim (crest level), x dam height")
      .above(0)
      .at_most(20);
  // Joints
  s.integer("joints.count", "0", "-",
            "candidate joint positions evenly spaced along the crest (used "
            "if joints.positions is empty)")
      .between(0, 26);
  s.real_array("joints.positions", "[]", "-",
               "candidate positions as fractions of the crest arc length "
               "from the left wall, increasing; labelled A, B, ...")
      .between_exclusive(0, 1);
  s.string("joints.active", "", "-",
           "labels of the candidates that are joints, e.g. \"DGJ\" (empty: "
           "all)");
  // Mesh
  s.real("mesh.size", "6.0", "m", "element size in the dam")
      .between(0.001, 1000);
  s.real("mesh.size_far", "0.0", "m",
         "element size at the far foundation (0: 4 x mesh.size)")
      .between(0, 10000);
  s.real("mesh.grading_distance", "0.5", "H",
         "distance from the dam over which the size grades, x dam height")
      .above(0)
      .at_most(20);
  s.integer("mesh.dam_layers", "0", "-",
            "minimum elements through the crown thickness (0: off)")
      .between(0, 20);
  s.integer("mesh.sections", "0", "-",
            "lofted arch sections (0: automatic = 12)")
      .between(0, 200);
  s.integer("mesh.arch_points", "17", "-",
            "spline points per face of a lofted section")
      .between(5, 400);
  s.boolean("mesh.optimize", "true", "-", "gmsh tetrahedron optimisation");
  s.integer("mesh.max_cells", "200000", "-",
            "refuse a mesh estimated above this many cells before meshing "
            "(raise it if the machine has the memory: about 15 GB per "
            "100,000 P2 tetrahedra)")
      .at_least(1);
  s.boolean("mesh.split_joints", "true", "-",
            "duplicate the joint nodes (false: jointless mesh, same cells)");
}
//-----------------------------------------------------------------------------
ArchDamDefinition read_arch_dam(const input::Case& c)
{
  ArchDamDefinition d;
  ArchDamShape& a = d.dam;
  a.height = c.real("dam.height");
  a.levels = c.reals("dam.levels");
  a.crown_upstream_y = c.reals("dam.crown_upstream_y");
  a.crown_thickness = c.reals("dam.crown_thickness");
  a.abutment_thickness = c.reals("dam.abutment_thickness");
  const std::string shape = c.string("dam.arch_shape");
  a.shape = shape == "parabolic"  ? ArchShape::parabolic
            : shape == "circular" ? ArchShape::circular
                                  : ArchShape::three_centred;
  a.radius_central = c.reals("dam.radius_central");
  a.radius_lateral = c.reals("dam.radius_lateral");
  a.central_angle_deg = c.reals("dam.central_angle");
  a.thickening_exponent = c.real("dam.thickening_exponent");
  a.interpolation = c.string("dam.interpolation") == "linear"
                        ? LevelInterpolation::linear
                        : LevelInterpolation::cubic;
  CanyonDefinition& k = d.canyon;
  const std::string cs = c.string("canyon.shape");
  k.shape = cs == "u"        ? CanyonShape::u
            : cs == "points" ? CanyonShape::points
                             : CanyonShape::v;
  k.bottom_width = c.real("canyon.bottom_width");
  k.crest_width = c.real("canyon.crest_width");
  k.u_radius = c.real("canyon.u_radius");
  k.u_segments = int(c.integer("canyon.u_segments"));
  k.z = c.reals("canyon.z");
  k.x_left = c.reals("canyon.x_left");
  k.x_right = c.reals("canyon.x_right");
  d.foundation.upstream = c.real("foundation.extent_upstream");
  d.foundation.downstream = c.real("foundation.extent_downstream");
  d.foundation.below = c.real("foundation.extent_below");
  d.foundation.beyond = c.real("foundation.extent_beyond");
  d.joints.count = int(c.integer("joints.count"));
  d.joints.positions = c.reals("joints.positions");
  d.joints.active = c.string("joints.active");
  d.mesh.size = c.real("mesh.size");
  d.mesh.size_far = c.real("mesh.size_far");
  d.mesh.grading_distance = c.real("mesh.grading_distance");
  d.mesh.dam_layers = int(c.integer("mesh.dam_layers"));
  d.mesh.sections = int(c.integer("mesh.sections"));
  d.mesh.arch_points = int(c.integer("mesh.arch_points"));
  d.mesh.optimize = c.boolean("mesh.optimize");
  d.mesh.split_joints = c.boolean("mesh.split_joints");
  try
  {
    ArchDamGeometry g(d);
  }
  catch (const std::invalid_argument& e)
  {
    // Messages are "<field>: <problem>"; fields named as the case keys
    std::string msg = e.what();
    const auto colon = msg.find(": ");
    std::string key = colon == std::string::npos ? "dam" : msg.substr(0, colon);
    if (key == "dam.central_angle" or key.rfind("dam.", 0) == 0 or
        key.rfind("canyon", 0) == 0 or key.rfind("joints.", 0) == 0 or
        key.rfind("mesh.", 0) == 0)
      ;
    else if (key.rfind("foundation.", 0) == 0)
      key = "foundation.extent_" + key.substr(11);
    const std::string problem =
        colon == std::string::npos ? msg : msg.substr(colon + 2);
    c.fail(key, problem,
           "a realisable arch dam (see the comments of the presets in "
           "demos/arch_dam/presets)");
  }
  check_cell_estimate(c, estimated_cells(d));
  return d;
}
} // namespace damseis::geometry
