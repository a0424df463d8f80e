#include "mesh_estimate.h"
#include "arch_dam.h"
#include "gravity_dam.h"
#include <algorithm>
#include <cmath>
#include <damseis/input/case.h>
#include <iomanip>
#include <sstream>
#include <unistd.h>

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

SizeEstimate estimate_size(double cells, int dim, int order)
{
  SizeEstimate e;
  e.cells = cells;
  if (dim == 2)
  {
    // Triangles: vertices ~ cells / 2, P2 nodes (vertices + edges) ~ 2
    // cells (Koyna: 8,946 dofs on 2,158 cells).
    e.dofs = 2.0 * (order == 1 ? 0.5 : 2.0) * cells;
    // Memory: Koyna P2 at 2, 1, 0.65 m (bench/results/koyna-2026-11-22.md:
    // 124, 214, 405 MB for 8,946 - 81,104 dofs). Time per step: fitted to
    // the 2D runs of bench/results/size-estimate-2026-11-25.md (0.46 ms at
    // 8,946 dofs, 3.6 ms at 34,502).
    e.memory_gb = 0.09 + 3.9e-6 * e.dofs;
    e.ms_per_step = 0.46 * std::pow(e.dofs / 8946.0, 1.5);
  }
  else
  {
    // Tetrahedra: P2 nodes ~ 1.6 cells (paper dam: 410,673 dofs on 86,074
    // cells), vertices ~ 0.3 cells (Euler: nodes = 2 vertices + cells).
    e.dofs = 3.0 * (order == 1 ? 0.3 : 1.6) * cells;
    // Paper dam at 2.3 m and Xiluodu-like at 5.5 m on 2 ranks
    // (bench/results/arch-2026-11-22.md): 12.6 and 14.4 GB, 0.46 - 0.55 s
    // per step; sparse direct fill grows as dofs^(4/3) in 3D.
    const double r = e.dofs / 410673.0;
    e.memory_gb = 0.4 + 12.3 * std::pow(r, 4.0 / 3.0);
    e.ms_per_step = 500.0 * std::pow(r, 4.0 / 3.0);
  }
  return e;
}

std::string describe(const SizeEstimate& e)
{
  // 2,158 cells; 0.12 GB; 0.43 ms, 130 ms (no exponents for a reader).
  auto count = [](double v)
  {
    if (!(v < 1e15))
      return (std::ostringstream() << std::setprecision(3) << v).str();
    std::string digits = std::to_string(std::llround(v));
    for (int i = static_cast<int>(digits.size()) - 3; i > 0; i -= 3)
      digits.insert(static_cast<std::size_t>(i), ",");
    return digits;
  };
  auto amount = [&](double v)
  {
    return v >= 100.0
               ? count(v)
               : (std::ostringstream() << std::setprecision(2) << v).str();
  };
  return "about " + count(e.cells) + " cells, " + count(e.dofs) + " dofs, " +
         amount(e.memory_gb) + " GB of memory, " + amount(e.ms_per_step) +
         " ms per linear time step";
}

double machine_memory_gb()
{
  const long pages = sysconf(_SC_PHYS_PAGES), size = sysconf(_SC_PAGE_SIZE);
  return pages > 0 && size > 0
             ? static_cast<double>(pages) * static_cast<double>(size) / 1e9
             : 0.0;
}
} // namespace damseis::geometry
