#include "arch_dam_case.h"
#include <damseis/geometry/arch_case.h>
#include <damseis/geometry/tags.h>

namespace damseis::analysis
{
const std::vector<Direction>& arch_dam_directions()
{
  static const std::vector<Direction> d = {
      {"cross_stream", 0, "", 0.0},
      {"stream", 1, DAMSEIS_SOURCE_DIR "/data/records/elcentro_1940_ns.at2",
       0.2},
      {"vertical", 2, "", 0.0}};
  return d;
}

input::Schema arch_dam_schema()
{
  input::Schema s;
  geometry::arch_dam_schema(s);
  s.integer("mesh.order", "2", "-",
            "displacement polynomial degree (2: no shell locking)")
      .between(1, 2);
  s.real("material.E", "28.6e9", "Pa", "Young's modulus of the dam concrete")
      .between(1e8, 2e11);
  s.real("material.nu", "0.2", "-", "Poisson's ratio of the dam concrete")
      .between_exclusive(-1, 0.5);
  s.real("material.rho", "2400", "kg/m3", "mass density of the dam concrete")
      .between(100, 20000);
  s.real("rock.E", "28.6e9", "Pa",
         "Young's modulus of the (massless) foundation rock")
      .between(1e7, 2e11);
  s.real("rock.nu", "0.25", "-", "Poisson's ratio of the foundation rock")
      .between_exclusive(-1, 0.5);
  s.string("joints.model", "bonded", "-",
           "contraction joints in a linear analysis (bonded: tied pairs)",
           {"bonded"});
  add_seismic_keys(s, arch_dam_directions(), "[]", "[]");
  return s;
}

ArchDamConfig read_arch_dam_config(const input::Case& c)
{
  ArchDamConfig a;
  a.geometry = geometry::read_arch_dam(c);
  // The mesh follows the water line: the wetted part of the upstream face
  // gets its own tag (upstream_wetted).
  a.geometry.mesh.water_level = c.real("reservoir.level");
  a.order = static_cast<int>(c.integer("mesh.order"));
  a.concrete = {c.real("material.E"), c.real("material.nu"),
                c.real("material.rho")};
  a.rock = {c.real("rock.E"), c.real("rock.nu"), 0.0};
  const geometry::ArchDamGeometry shape(a.geometry);
  const double h = shape.height();
  // Crown section: crest and base points on the upstream face.
  const auto crest = shape.face_point(h, 0.0, -1);
  const auto base = shape.face_point(0.0, 0.0, -1);
  a.seismic =
      read_seismic_settings(c, arch_dam_directions(), 3, h, crest, base);
  const double level = a.geometry.mesh.water_level;
  const double size = a.geometry.mesh.size;
  for (const auto& [key, x] :
       {std::pair{"output.crest_point", a.seismic.crest_point},
        std::pair{"output.base_point", a.seismic.base_point}})
  {
    check_output_point(c, key, x, 3, geometry::distance_from_model(shape, x),
                       size, "the dam or the foundation rock");
  }
  if (level > 0.0 && (level < 0.1 * size || level > h - 0.1 * size))
    c.fail("reservoir.level",
           "is within a tenth of mesh.size of the base or of the crest, where "
           "the mesh cannot follow the water line",
           "0 (no reservoir) or a level between the base and the crest at "
           "least mesh.size / 10 from both");
  a.seismic.faces = {{"upstream", {tags::upstream_face, tags::upstream_wetted}},
                     {"downstream", {tags::downstream_face}}};
  return a;
}
} // namespace damseis::analysis
