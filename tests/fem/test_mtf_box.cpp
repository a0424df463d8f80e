// Liao's multi-transmitting boundary in 3D (fem/MtfBoundary with
// dynamics/PartitionedNewmark): a box of rock (P1 tetrahedra on 2.5 m
// cubes, DOLFINx's six-tetrahedra split), its band of four cell layers
// along the bottom and the four sides explicit with lumped mass, the
// formula (order 2) on their nodes, a free top.
//
// 1. A flat top and a vertically incident S or P pulse given as the
//    outcrop motion: the free field solves the truncated model, so the
//    surface moves with the record, delayed by the travel time, and the
//    box is at rest once the pulse reflected at the surface has left
//    through the bottom (the 2D soil column of test_mtf_boundary.cpp, now
//    with four sides, their vertical edges and the bottom's corners).
// 2. A notch in the top (a valley's walls meeting the boundary's faces)
//    and a point-force pulse: the formula is unstable there without the
//    band's own stiffness damping (PartitionedNewmark's b_E): a mode of
//    the band's shortest waves (the displacement alternating from node to
//    node down the wall, a quarter wave along the normal) grows at the
//    wall next to the faces the notch crosses, on the side where the six-
//    tetrahedra split leans against the slope. With b_E at 5 % of critical
//    at the band's highest frequency the waves leave and the box comes to
//    rest.
// 3. Both on P2 tetrahedra with order 1 (5 m cells, the same node
//    spacing), where the stencil's points are interpolated in the band's
//    cells; the notch needs the band damped 10 %.
// 4. Both with the band implicit (no partition) at s = 0.97, four times
//    the explicit band's step: transparent, and the notch stable without
//    the band's damping.
#include "fem_test_support.h"
#include "soil_column.h"
#include <damseis/analysis/free_field_load.h>
#include <damseis/analysis/wave_foundation.h>
#include <damseis/boundary/free_field.h>
#include <damseis/dynamics/partitioned_newmark.h>
#include <damseis/fem/mtf_boundary.h>
#include <damseis/geometry/ground_surface.h>
#include <damseis/linalg/duplicate_matrix.h>
#include <numbers>

using namespace damseis;
using namespace damseis::test;

namespace
{
constexpr int bottom = 5, sides = 6, band_region = tags::foundation_band;
constexpr double W = 40.0; // box width [m]

struct BoxCase
{
  double H = 50.0;            ///< depth [m]
  double notch = 0.0;         ///< the notch's depth [m] (0: a flat top)
  int component = 0;          ///< of the outcrop pulse (0: S, 2: P)
  bool point = false;         ///< a point-force pulse in place of the wave
  double T = 0.1;             ///< the pulse's duration [s]
  double drift = 1e-4;        ///< gamma_d
  double xi_band = 0.05;      ///< the band's damping at its highest frequency
  int degree = 1;             ///< of the elements (1: P1, 2: P2)
  bool implicit_band = false; ///< the band in the implicit group
  double dt = 2e-4;           ///< time step [s]
  int order = 2;              ///< N of the formula
  int steps = 0;
  /// The node spacing [m] (cells of degree x h), the band's cell layers.
  double h = 2.5;
  int layers() const { return (2 * order + degree - 1) / degree; }
};

struct BoxResult
{
  double peak = 0.0;     ///< max |u| over the run
  double surface = 0.0;  ///< max |u(top) - record| / A (flat top, wave)
  double residual = 0.0; ///< max |u| at the end / peak
  double stable_dt = 0.0;
  double half = 0.0; ///< max |u| at the run's half
};

/// Adds F at the node at p to every component of f (collective).
void add_point_force(const dolfinx::fem::FunctionSpace& V, Vec f,
                     const Point& p, double F)
{
  const std::int32_t n = V.dofmap()->index_map->size_local();
  const std::int64_t first = V.dofmap()->index_map->local_range()[0];
  const std::vector<double> X = V.tabulate_dof_coordinates(false);
  for (std::int32_t i = 0; i < n; ++i)
    if (std::hypot(X[3 * i] - p[0], X[3 * i + 1] - p[1], X[3 * i + 2] - p[2]) <
        1e-9)
      for (int c = 0; c < 3; ++c)
        VecSetValue(f, 3 * (first + i) + c, F, ADD_VALUES);
  VecAssemblyBegin(f);
  VecAssemblyEnd(f);
}

BoxResult run_box(const BoxCase& b)
{
  const double h = b.h * b.degree; // cell size
  const double H = b.H, A = 0.01, dt = b.dt, w = b.layers() * h;
  const std::size_t nx = std::size_t(W / h + 0.5),
                    nz = std::size_t(H / h + 0.5);
  Model model = box_model(MPI_COMM_WORLD, {0, 0, -H}, {W, W, 0}, {nx, nx, nz},
                          [&](const Point& p)
                          {
                            if (p[2] < -H + 1e-9)
                              return bottom;
                            if (p[0] < 1e-9 || p[0] > W - 1e-9 || p[1] < 1e-9 ||
                                p[1] > W - 1e-9)
                              return sides;
                            return -1;
                          });
  // The notch along y: the top at z_s(x) = -d (1 - cos(pi r)) / 2, r = 1 -
  // |x - W/2| / (W/4), between the side bands; the mesh above the bottom
  // band (and a margin) stretched vertically to it.
  auto surface = [&](double x)
  {
    const double r = std::max(0.0, 1 - std::abs(x - W / 2) / (W / 4));
    return -b.notch * (1 - std::cos(std::numbers::pi * r)) / 2;
  };
  {
    std::span<double> x = model.mesh->geometry().x();
    const double zb = -H + w + 2 * h;
    for (std::size_t i = 0; i < x.size() / 3; ++i)
      if (x[3 * i + 2] > zb)
        x[3 * i + 2] =
            zb + (x[3 * i + 2] - zb) * (surface(x[3 * i]) - zb) / (0 - zb);
  }
  // The band: the cells within four layers of the bottom and the sides.
  const std::vector<std::int32_t> band =
      tag_band(model, band_region,
               [&](const Point& mid)
               {
                 return mid[0] < w || mid[0] > W - w || mid[1] < w ||
                        mid[1] > W - w || mid[2] < -H + w;
               });
  const boundary::Rock rock{20e9, 0.25, 2600.0};
  const damseis::fem::Material m{rock.E, rock.nu, rock.rho};
  damseis::fem::ElasticModel fe(model, b.degree,
                                {{tags::dam, m}, {band_region, m}});
  damseis::fem::ElasticModel::Partitioned p = fe.assemble_partitioned(
      b.implicit_band ? std::vector<int>{} : std::vector<int>{band_region},
      nullptr);
  PMat K = own(p.K), K_i = own(p.K_implicit), M = own(p.M);
  PVec lumped = own(p.M_explicit);
  PMat K_e = own(linalg::duplicate_matrix(K.mat(), MAT_COPY_VALUES));
  MatAXPY(K_e.mat(), -1.0, K_i.mat(), SUBSET_NONZERO_PATTERN);

  const dynamics::RayleighDamping rayleigh{2.0, 2e-4};
  std::array<std::vector<double>, 3> outcrop;
  for (auto& o : outcrop)
    o.assign(b.steps + 1, 0.0);
  if (!b.point)
    outcrop[b.component] = pulse_acceleration(A, b.T, dt, b.steps);
  const geometry::GroundSurface ground(model, {}, {bottom, sides});
  auto field = std::make_shared<boundary::VerticalFreeField>(
      boundary::VerticalFreeField::from_outcrop(rock, 3, -H, 0, outcrop, dt));
  auto mtf = std::make_shared<damseis::fem::MtfBoundary>(
      *fe.V(), *model.facet_tags, std::vector<int>{bottom, sides}, band,
      damseis::fem::MtfSettings{b.order, b.drift, b.h, rock.cp(), rock.cs(),
                                dt},
      analysis::separated_field(field, ground, dt));
  // The nodes of the bottom (17 x 17) and of the sides above it (4 x 16 x
  // 20): each node once.
  EXPECT_EQ(mtf->node_counts()[1], 17 * 17);
  EXPECT_EQ(mtf->node_counts()[0],
            17 * 17 + 4 * 16 * std::int64_t(b.degree * nz));

  const double omega = dynamics::highest_explicit_frequency(
      K.mat(), K_i.mat(), lumped.vec(), mtf->rows());
  const double b_e = omega > 0 ? 2 * b.xi_band / omega : 0.0;
  BoxResult r;
  r.stable_dt = dynamics::explicit_stable_step(omega, {rayleigh.a_mass, b_e});
  EXPECT_LT(dt, r.stable_dt);
  analysis::FreeFieldLoad load(fe, nullptr, ground, field, M.mat(), K_i.mat(),
                               rayleigh, dt);
  load.add_stiffness_damping(K_e.mat(), b_e);
  dynamics::PartitionedNewmark newmark(M.mat(), K.mat(), K_i.mat(), rayleigh,
                                       dt, linalg::Factorization::automatic,
                                       mtf, b_e);
  PVec f = linalg::column_vector(K.mat());
  PVec zero = linalg::column_vector(K.mat());
  load.assemble(0, f.vec());
  newmark.set_state(zero.vec(), zero.vec(), zero.vec(), f.vec(), {}, 0);
  const Point source = {W / 2, W / 2, surface(W / 2)};
  const double delay = H / (b.component == 2 ? rock.cp() : rock.cs());
  const NodeProbe top(*fe.V(), source);
  for (int k = 1; k <= b.steps; ++k)
  {
    load.assemble(k, f.vec());
    if (b.point)
      add_point_force(*fe.V(), f.vec(), source, 1e9 * pulse(1.0, b.T, k * dt));
    newmark.step(f.vec());
    double umax = 0.0;
    VecNorm(newmark.u(), NORM_INFINITY, &umax);
    r.peak = std::max(r.peak, umax);
    if (k == b.steps / 2)
      r.half = umax;
    if (!b.point && b.notch == 0.0)
      r.surface = std::max(r.surface, std::abs(top(newmark.u(), b.component) -
                                               pulse(A, b.T, k * dt - delay)) /
                                          A);
    if (!(umax < 1e3 * r.peak + 1.0)) // grown without bound: stop
      break;
  }
  double umax = 0.0;
  VecNorm(newmark.u(), NORM_INFINITY, &umax);
  r.residual = umax / r.peak;
  return r;
}

/// The notched box (a notch 5 m deep, 30 m of rock) and a point-force
/// pulse of `T` at the notch's bottom, drift control 0.01 (the pulse's net
/// impulse would otherwise leave the box drifting: the formula is exact
/// for a uniform motion at gamma_d = 0).
BoxCase notched_box(double T, int steps)
{
  BoxCase b;
  b.H = 30.0;
  b.notch = 5.0;
  b.point = true;
  b.T = T;
  b.drift = 0.01;
  b.steps = steps;
  return b;
}
} // namespace

// Flat top, S pulse in x (normal on two sides, tangential on the other
// two), the band damped 5 % at its highest frequency (3.5e-3 at 40 Hz,
// the pulse's band). Measured: surface error 4.9e-4 of the peak, residual
// 1.7e-4 at 0.3 s (the 2D column, same cells and step: 6.1e-4 and
// 1.2e-4). Asserted: the surface within 8e-4 of the peak (the 2D
// column's discretisation error, 6.1e-4, with a margin; without the band
// damping's term in the free-field load, b_E K_E v_ff, it is 1.1e-3), the
// residual within 5e-4 (as the 2D column).
TEST(MtfBox, FlatTopSPulseLeavesThroughBottomAndSides)
{
  BoxCase b;
  b.steps = 1500;
  const BoxResult r = run_box(b);
  print_metric(fmt("MTF 3D box, S: surface error ", r.surface,
                   " of the peak, residual ", r.residual, ", stable dt ",
                   r.stable_dt));
  EXPECT_LT(r.surface, 8e-4);
  EXPECT_LT(r.residual, 5e-4);
}

// The notched box, a 10 ms pulse. Measured without the band's damping (xi_band
// = 0): the displacement at 0.3, 0.6 and 0.9 s is 3.2e-6, 3.2e-4 and 0.19 of
// the peak (a hundredfold per 0.3 s); with 5 %: 1.3e-10 of the peak at 0.6 s.
// Asserted at 0.6 s: below 1e-6 of the peak.
TEST(MtfBox, NotchedTopIsStableWithTheBandsDamping)
{
  const BoxResult r = run_box(notched_box(0.01, 3000));
  print_metric(fmt("MTF 3D box, notch, point force: residual ", r.residual,
                   " of the peak, stable dt ", r.stable_dt));
  EXPECT_LT(r.residual, 1e-6);
}

// P2 tetrahedra (5 m cells, the same 2.5 m node spacing), order 1 (order 2
// drifts on P2's lumped lattice: test_mtf_boundary.cpp), the band two
// cell layers. The stencil's points between the layers are not all
// nodes where the band's cells are sheared (the notch below): the
// boundary interpolates them in the band's cells. Flat top, S pulse in x.
// Measured: surface error 6.8e-3 of the peak, residual 1.1e-3 at 0.3 s.
// Asserted: the 2D column's P2 order-1 error (1.6e-3 at half this node
// spacing, test_mtf_boundary.cpp) scaled by the spacing squared, 6.4e-3,
// with a margin: 1e-2; the residual within the 2D column's bound, 5e-3.
TEST(MtfBox, P2OrderOneFlatTopSPulseLeaves)
{
  BoxCase b;
  b.steps = 1500;
  b.degree = 2;
  b.order = 1;
  const BoxResult r = run_box(b);
  print_metric(fmt("MTF 3D box P2 order 1, S: surface error ", r.surface,
                   " of the peak, residual ", r.residual, ", stable dt ",
                   r.stable_dt));
  EXPECT_LT(r.surface, 1e-2);
  EXPECT_LT(r.residual, 5e-3);
}

// The notched box of NotchedTopIsStableWithTheBandsDamping on P2, order
// 1: the walls' sheared band cells put the stencil's midway points off
// the nodes. Measured: with the band damped 5 % at its highest frequency
// it grows about sixfold per 0.05 s from 0.15 s (0.49 of the peak at 0.6
// s); with 10 % (the P2 default of foundation.band_damping) it comes to
// rest: 5.5e-18 of the peak at 0.6 s. Asserted: below
// 1e-6 of the peak.
TEST(MtfBox, P2NotchedTopIsStableWithTheBandsDamping)
{
  BoxCase b = notched_box(0.01, 3000);
  b.degree = 2;
  b.order = 1;
  b.xi_band = 0.1;
  const BoxResult r = run_box(b);
  print_metric(fmt("MTF 3D box P2, notch, point force: residual ", r.residual,
                   " of the peak, stable dt ", r.stable_dt));
  EXPECT_LT(r.residual, 1e-6);
}

// The band implicit (consistent mass, Newmark's average acceleration with
// the rest: foundation.band_integration = "implicit"): no stable step of
// its own, the step bounded by s = c_p dt / dx <= 1 alone; here s = 0.97
// (dt 0.8 ms, four times the explicit band's tests' step and above its
// stable step, 0.54 ms), no band damping.
// Measured: surface error 2.5e-4 of the peak, residual 4.9e-5 at 1 s.
// Asserted: the explicit band's bounds (FlatTopSPulseLeavesThroughBottom-
// AndSides: 8e-4, 5e-4).
TEST(MtfBox, ImplicitBandFlatTopSPulseLeavesAtCourantNearOne)
{
  BoxCase b;
  b.implicit_band = true;
  b.xi_band = 0.0;
  b.dt = 8e-4;
  b.steps = 1250;
  const BoxResult r = run_box(b);
  print_metric(fmt("MTF 3D box, implicit band, s = 0.97, S: surface error ",
                   r.surface, " of the peak, residual ", r.residual));
  EXPECT_LT(r.surface, 8e-4);
  EXPECT_LT(r.residual, 5e-4);
}

// The notched box with the band implicit, no band damping, s = 0.97, a
// 30 ms point-force pulse: the waves leave (the explicit band grows here
// without its damping). Measured: 3.6e-2 of the peak at 0.5 s, 1.7e-3 at
// 1 s. Asserted: at 1 s below a tenth of the value at 0.5 s.
TEST(MtfBox, ImplicitBandNotchedTopComesToRest)
{
  BoxCase b = notched_box(0.03, 1250);
  b.implicit_band = true;
  b.xi_band = 0.0;
  b.dt = 8e-4;
  const BoxResult r = run_box(b);
  print_metric(
      fmt("MTF 3D box, implicit band, notch, point force: ", r.half / r.peak,
          " of the peak at 0.5 s, ", r.residual, " at 1 s"));
  EXPECT_LT(r.residual * r.peak, 0.1 * r.half);
}
