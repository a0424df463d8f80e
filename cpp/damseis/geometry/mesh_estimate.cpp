#include "mesh_estimate.h"
#include "arch_dam.h"
#include "gravity_dam.h"
#include <algorithm>
#include <cmath>
#include <damseis/case/case.h>
#include <sstream>

namespace damseis::geometry
{
double triangle_count(double area, double h)
{
  return area / (std::sqrt(3.0) / 4.0 * h * h);
}

double tetrahedron_count(double volume, double h)
{
  return volume / (h * h * h / (6.0 * std::sqrt(2.0)));
}

double estimated_cells(const GravityDamSection& s)
{
  double n = triangle_count(section_area(s), s.mesh_size);
  if (s.foundation)
  {
    const double far = s.foundation_mesh_size > 0.0 ? s.foundation_mesh_size
                                                    : 2.5 * s.mesh_size;
    // Grading from the dam to the far size: mostly the far size; a far
    // size finer than the dam's rules the whole block.
    const double mean =
        far >= s.mesh_size ? (s.mesh_size + 2.0 * far) / 3.0 : far;
    n += triangle_count(s.foundation_width * s.foundation_depth, mean);
  }
  return n;
}

double estimated_cells(const ArchDamDefinition& d)
{
  const ArchDamGeometry g(d);
  const double h = d.mesh.size;
  const double far = d.mesh.size_far > 0.0 ? d.mesh.size_far : 4.0 * h;
  // The foundation block: the canyon's crest width plus the rims, the dam's
  // extent up and down stream, the depth below the floor (a box: an upper
  // bound of the rock).
  const double H = g.height();
  const auto& f = d.foundation;
  const double width = d.canyon.crest_width + 2.0 * f.beyond * H;
  const double length = (f.upstream + f.downstream) * H + 2.0 * H;
  const double depth = (f.below + 1.0) * H;
  // Most of the rock has the far size; the band where the size grades
  // (grading_distance x H around the dam, counted on the upstream face's
  // area) has the mean size.
  const double band = d.mesh.grading_distance * H * g.face_area(-1);
  // 0.6: measured on the presets (paper dam at 6 and 4 m, Xiluodu-like at
  // 20 m: 0.57-0.61 of the sum; the box counts the canyon as rock).
  return 0.6 * (tetrahedron_count(g.volume(), h) +
                tetrahedron_count(width * length * depth, far) +
                tetrahedron_count(band, 0.5 * (h + far)));
}

void check_cell_estimate(const input::Case& c, double estimate)
{
  const double limit = static_cast<double>(c.integer("mesh.max_cells"));
  if (!(estimate <= limit))
  {
    std::ostringstream problem, expected;
    problem.precision(3);
    problem << "of " << c.real("mesh.size") << " m gives about " << estimate
            << " cells (estimated before meshing), above mesh.max_cells = "
            << static_cast<long long>(limit);
    expected << "a larger mesh.size, or a larger mesh.max_cells if the "
                "machine has the memory";
    c.fail("mesh.size", problem.str(), expected.str());
  }
}
} // namespace damseis::geometry
