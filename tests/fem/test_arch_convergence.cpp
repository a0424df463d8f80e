// Mesh convergence of the 3D arch-dam analysis (issue 4, verification:
// "Convergence of the first natural frequencies and of the crest
// displacement under hydrostatic load with mesh refinement (state the
// observed order)"), and shell locking of P1 tetrahedra.
//
// LONG test (about a minute serial): the tests are DISABLED_ so that the
// default fem_tests run skips them; ctest runs them as "arch_convergence"
// (label "long"; `ctest -LE long` skips it) with
// --gtest_also_run_disabled_tests.
//
// Setup: the paper's 102 m three-centred dam in its V-shaped canyon, the
// preset demos/arch_dam/presets/paper_102m_v.toml read through
// geometry::read_arch_dam, no joints; the analysis values of
// demos/arch_dam/arch_dam.toml: concrete E = 28.6 GPa, nu = 0.2,
// rho = 2400 kg/m3; massless rock E = 28.6 GPa, nu = 0.25, fixed at the far
// boundaries (bottom, sides, upstream, downstream). Uniform refinement:
// mesh.size h = 16, 16/sqrt(2), 8 m in the dam and mesh.size_far = 4 h
// (the default), so the whole mesh (foundation too) refines by sqrt(2).
// Quantities: the first 3 natural frequencies, dry and with the
// generalised Westergaard added mass for a reservoir level of 100 m
// (bottom 0), and the crown crest upstream displacement under the
// hydrostatic load alone (level 100 m): the stream (y, downstream) component
// of u at (0, y_u + 1 m, H - 0.5 m), where (0, y_u, H) is the upstream crest
// point of the crown (evaluated in the cell that contains it; 1 m inside
// the 5 m crest so that the point is inside the faceted mesh for every h:
// the chordal sag of the coarsest crest edges is about 0.6 m).
//
// Checked: for each of the 7 quantities the successive differences
// d1 = |q(h1) - q(h2)|, d2 = |q(h2) - q(h3)| decrease (d2 < d1) with the same
// sign (monotone convergence); the observed order p = log(d1 / d2) /
// log(sqrt 2) is printed (and the one from the effective sizes
// N_dam^(-1/3)); the crest displacement order must exceed 1 and the mean
// order lie in [0.5, 4.5] (loose: see the scatter below).
//
// Observed (serial; deterministic meshes; P2):
//   h [m]             16        11.31     8        order p
//   dam cells         500       979       2,048    (11k, 22k, 47k dofs)
//   f1 dry [Hz]       4.0089    3.9460    3.8930   0.49
//   f2 dry            4.1915    4.1613    4.1422   1.32
//   f3 dry            5.3075    5.2057    5.1399   1.26
//   f1 wet (100 m)    2.6562    2.6149    2.5775   0.29
//   f2 wet            2.7008    2.6806    2.6668   1.09
//   f3 wet            3.5811    3.5134    3.4652   0.98
//   crest u_y [mm]    19.203    19.375    19.473   1.58
// i.e. changes of 0.4-1.9 %, then 0.3-1.4 %, per refinement. Run time
// about 4 + 10 + 30-45 s, plus 3 s for P1.
// Extended study with the same code (not run here: h = 16 / 2^(k/4),
// k = 0..6, down to 5.66 m = 4,319 dam cells, 111k dofs, 163 s), least-
// squares fits q = q_inf + C h^p: over all 7 meshes p = 1.2, 1.5, 1.5
// (dry), 1.1, 1.4, 1.4 (wet), 2.1 (crest); over the 5 finest (11.3 to
// 5.66 m) p = 2.0, 1.5, 1.5, 2.2, 2.1, 1.8, 3.9. The mesh-to-mesh scatter
// of unstructured meshes (fit residuals 0.1-0.2 %) is as large as the
// increments, so a 3-mesh order moves by +-0.7 with the choice of sizes
// (0.3 to 3.1 seen), hence the loose bounds.
// Why about 1-2 and not the 4 (eigenvalues) or 3 (displacement) of P2 on
// an exact geometry: the geometry is P1-faceted, the curved faces are
// replaced by chords, an O(h^2) perturbation of the domain (thickness,
// curvature, volume) and so of the stiffness and mass (a variational
// crime: Strang's lemma adds this O(h^2) consistency error), which caps
// every quantity at order 2. The frequencies (energy quantities) fall below
// 2 on the coarse meshes: the dam is then 1-2 elements thick, and the
// re-entrant corners where the faces meet the rock (heel and toe, about
// 270 deg of material) carry stress singularities r^(lambda - 1), lambda
// about 0.54, whose eigenvalue error on quasi-uniform meshes is
// O(h^(2 lambda)) = O(h^1.1). The crest displacement, a local quantity far
// from the corners, converges at about 2 or faster. The dam cells grow like
// h^-2, not h^-3 (a thin shell with few elements through its thickness),
// so orders from N_dam^(-1/3) overstate (about 1.6 x the nominal ones); the
// nominal h is the in-plane size that sets the faceting.
//
// P1 vs P2 (same mesh, h = 11.31 m): linear tetrahedra lock in the
// bending of the thin shell (constant strain: they cannot bend without
// spurious shear): crest u_y 15.12 mm (P1) vs 19.37 mm (P2), ratio 0.78;
// f1 dry 5.24 vs 3.95 Hz (ratio 1.33, i.e. a 1.77 x stiffer first mode).
// Required: u(P1) < 0.85 u(P2) and f1(P1) > 1.15 f1(P2).
#include "fem_test_support.h"

#include <damseis/fem/elastic_model.h>
#include <damseis/geometry/arch_case.h>
#include <damseis/geometry/arch_dam.h>
#include <damseis/geometry/arch_mesh.h>
#include <damseis/geometry/tags.h>
#include <damseis/input/case.h>
#include <damseis/linalg/direct_solver.h>
#include <damseis/linalg/modal.h>

#include <array>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include <dolfinx/common/IndexMap.h>
#include <dolfinx/fem/Function.h>
#include <dolfinx/geometry/BoundingBoxTree.h>
#include <dolfinx/geometry/utils.h>
#include <dolfinx/la/petsc.h>
#include <gtest/gtest.h>
#include <mpi.h>

namespace
{
using damseis::fem::ElasticModel;
using damseis::fem::Material;
using damseis::fem::Reservoir;
using namespace damseis::test;
namespace tags = damseis::tags;
namespace geometry = damseis::geometry;
namespace input = damseis::input;
using Clock = std::chrono::steady_clock;

const std::filesystem::path preset_file =
    std::filesystem::path(DAMSEIS_SOURCE_DIR) /
    "demos/arch_dam/presets/paper_102m_v.toml";
const Material concrete = {28.6e9, 0.2, 2400};
const Material rock = {28.6e9, 0.25, 0.0};
constexpr double reservoir_level = 100.0;
constexpr int num_modes = 3;

geometry::ArchDamDefinition paper_dam(double h)
{
  input::Schema s;
  geometry::arch_dam_schema(s);
  return geometry::read_arch_dam(input::Case::load(
      s, preset_file,
      {"mesh.size=" + std::to_string(h), "mesh.size_far=0", "joints.count=0"}));
}

/// Value of the function u (vector, 3 components) at the point p (the
/// lowest rank whose cells contain it); throws if no cell contains it.
std::array<double, 3> eval_at(const dolfinx::fem::Function<double>& u,
                              const Point& p)
{
  const auto& mesh = *u.function_space()->mesh();
  const int tdim = mesh.topology().dim();
  dolfinx::geometry::BoundingBoxTree tree(mesh, tdim);
  const std::span<const double> x(p.data(), 3);
  const auto candidates = dolfinx::geometry::compute_collisions(tree, x);
  const auto cells =
      dolfinx::geometry::compute_colliding_cells(mesh, candidates, x);
  int rank = 0;
  MPI_Comm_rank(mesh.comm(), &rank);
  struct
  {
    int found;
    int rank;
  } local{cells.links(0).empty() ? 1 : 0, rank}, best;
  MPI_Allreduce(&local, &best, 1, MPI_2INT, MPI_MINLOC, mesh.comm());
  if (best.found != 0)
    throw std::runtime_error("eval_at: the point is in no cell");
  std::array<double, 3> v = {0, 0, 0};
  if (best.rank == rank)
  {
    const std::int32_t c = cells.links(0)[0];
    u.eval(x, {1, 3}, std::span<const std::int32_t>(&c, 1), v, {1, 3});
  }
  MPI_Bcast(v.data(), 3, MPI_DOUBLE, best.rank, mesh.comm());
  return v;
}

/// Results of one mesh and degree.
struct Result
{
  double h = 0; ///< nominal size in the dam [m]
  int degree = 2;
  std::int64_t cells = 0, dam_cells = 0, dofs = 0;
  double h_eff = 0;          ///< (V_dam / N_dam)^(1/3) [m]
  std::vector<double> f_dry; ///< first 3 frequencies [Hz]
  std::vector<double> f_wet; ///< with the Westergaard added mass
  double crest = 0;          ///< crest u_y under hydrostatic load [m]
  double mesh_seconds = 0;   ///< build_arch_dam (gmsh, distribution)
  double seconds = 0;        ///< everything
};

Result run(double h, int degree)
{
  const auto t0 = Clock::now();
  const geometry::ArchDamDefinition def = paper_dam(h);
  const geometry::ArchDamGeometry g(def);
  const geometry::ArchModel am = geometry::build_arch_dam(MPI_COMM_WORLD, def);
  ElasticModel fe(am.model, degree,
                  {{tags::dam, concrete}, {tags::foundation, rock}});
  fe.fix({tags::foundation_bottom, tags::foundation_sides,
          tags::foundation_upstream, tags::foundation_downstream});
  Reservoir water;
  water.level = reservoir_level;
  water.bottom = 0.0;

  Result r;
  r.h = h;
  r.degree = degree;
  r.cells = am.num_cells;
  r.dam_cells = am.num_dam_cells;
  r.dofs = fe.V()->dofmap()->index_map->size_global() * 3;
  r.h_eff = std::cbrt(g.volume() / double(am.num_dam_cells));
  r.mesh_seconds = am.total_seconds;

  PMat K = own(fe.assemble_stiffness());
  {
    PMat M = own(fe.assemble_mass(nullptr));
    r.f_dry = damseis::linalg::solve_modes(K.mat(), M.mat(), num_modes)
                  .frequencies_hz;
  }
  {
    PMat M = own(fe.assemble_mass(&water));
    r.f_wet = damseis::linalg::solve_modes(K.mat(), M.mat(), num_modes)
                  .frequencies_hz;
  }
  PVec f = own(fe.assemble_hydrostatic(water));
  dolfinx::fem::Function<double> u(fe.V());
  solve(K.mat(), f.vec(), u);
  const auto up = g.face_point(g.height(), 0.0, -1);
  r.crest = eval_at(u, {up[0], up[1] + 1.0, g.height() - 0.5})[1];
  r.seconds = std::chrono::duration<double>(Clock::now() - t0).count();
  print_metric(fmt("paper dam P", degree, " h = ", h, " m: ", r.cells,
                   " cells (", r.dam_cells, " in the dam, h_eff ", r.h_eff,
                   " m), ", r.dofs, " dofs; f dry ", r.f_dry[0], " ",
                   r.f_dry[1], " ", r.f_dry[2], " Hz, wet ", r.f_wet[0], " ",
                   r.f_wet[1], " ", r.f_wet[2], " Hz; crest u_y ",
                   r.crest * 1000, " mm; ", r.seconds, " s (mesh ",
                   r.mesh_seconds, " s)"));
  return r;
}

/// Order p with (h1^p - h2^p) / (h2^p - h3^p) = d1 / d2 (bisection; the
/// left side increases with p for h1 > h2 > h3).
double order_general(double h1, double h2, double h3, double d1, double d2)
{
  auto ratio = [&](double p)
  {
    return (std::pow(h1, p) - std::pow(h2, p)) /
           (std::pow(h2, p) - std::pow(h3, p));
  };
  double a = 0.01, b = 12;
  const double target = d1 / d2;
  if (target <= ratio(a) or target >= ratio(b))
    return std::nan("");
  for (int i = 0; i < 200; ++i)
  {
    const double m = 0.5 * (a + b);
    (ratio(m) < target ? a : b) = m;
  }
  return 0.5 * (a + b);
}

/// Results kept between the tests of the suite (P2 at three sizes).
std::map<std::pair<double, int>, Result>& results()
{
  static std::map<std::pair<double, int>, Result> r;
  return r;
}

const Result& result(double h, int degree)
{
  auto& r = results();
  auto it = r.find({h, degree});
  if (it == r.end())
    it = r.emplace(std::pair{h, degree}, run(h, degree)).first;
  return it->second;
}

const double sizes[3] = {16.0, 16.0 / std::sqrt(2.0), 8.0};
} // namespace

TEST(ArchConvergence, DISABLED_FrequenciesAndCrestDisplacementP2)
{
  const Result& a = result(sizes[0], 2);
  const Result& b = result(sizes[1], 2);
  const Result& c = result(sizes[2], 2);
  EXPECT_LT(a.dam_cells, b.dam_cells);
  EXPECT_LT(b.dam_cells, c.dam_cells);

  struct Quantity
  {
    std::string name;
    double q[3];
  };
  std::vector<Quantity> qs;
  for (int i = 0; i < num_modes; ++i)
  {
    qs.push_back(
        {fmt("f", i + 1, " dry"), {a.f_dry[i], b.f_dry[i], c.f_dry[i]}});
  }
  for (int i = 0; i < num_modes; ++i)
  {
    qs.push_back(
        {fmt("f", i + 1, " wet"), {a.f_wet[i], b.f_wet[i], c.f_wet[i]}});
  }
  qs.push_back({"crest u_y", {a.crest, b.crest, c.crest}});

  double sum_p = 0;
  for (const Quantity& q : qs)
  {
    const double d1 = std::abs(q.q[0] - q.q[1]);
    const double d2 = std::abs(q.q[1] - q.q[2]);
    const double p = std::log(d1 / d2) / std::log(sizes[0] / sizes[1]);
    const double pe = order_general(a.h_eff, b.h_eff, c.h_eff, d1, d2);
    print_metric(fmt(q.name, ": ", q.q[0], " ", q.q[1], " ", q.q[2],
                     "; differences ", d1, " ", d2, " (relative ",
                     d1 / std::abs(q.q[2]), " ", d2 / std::abs(q.q[2]),
                     "); observed order ", p, " (from N_dam^(-1/3): ", pe,
                     ")"));
    EXPECT_LT(d2, d1) << q.name << ": differences must decrease";
    // Same direction of change: monotone convergence
    EXPECT_GT((q.q[0] - q.q[1]) * (q.q[1] - q.q[2]), 0.0) << q.name;
    sum_p += p;
    if (q.name == "crest u_y")
      EXPECT_GT(p, 1.0) << "crest displacement: observed order";
  }
  const double mean_p = sum_p / qs.size();
  print_metric(fmt("mean observed order ", mean_p));
  EXPECT_GT(mean_p, 0.5);
  EXPECT_LT(mean_p, 4.5);
  // Sanity: the added mass lowers the frequencies; the water pushes the
  // crest downstream
  for (int i = 0; i < num_modes; ++i)
    EXPECT_LT(c.f_wet[i], c.f_dry[i]);
  EXPECT_GT(c.crest, 0.0);
}

TEST(ArchConvergence, DISABLED_P1LocksInBending)
{
  const Result& p2 = result(sizes[1], 2);
  const Result& p1 = result(sizes[1], 1);
  print_metric(fmt("h = ", sizes[1], " m: crest u_y P1 ", p1.crest * 1000,
                   " mm vs P2 ", p2.crest * 1000, " mm (ratio ",
                   p1.crest / p2.crest, "); f1 dry P1 ", p1.f_dry[0],
                   " Hz vs P2 ", p2.f_dry[0], " Hz (ratio ",
                   p1.f_dry[0] / p2.f_dry[0], ")"));
  EXPECT_GT(p1.crest, 0.0);
  EXPECT_LT(p1.crest, 0.85 * p2.crest) << "P1 must be visibly stiffer";
  EXPECT_GT(p1.f_dry[0], 1.15 * p2.f_dry[0]);
}
