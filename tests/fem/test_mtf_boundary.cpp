// Liao's multi-transmitting boundary on a finite element mesh
// (fem/MtfBoundary) with the Hughes-Liu partition
// (dynamics/PartitionedNewmark) and wave-field separation: a soil column
// 100 m deep, 20 m wide (P2, structured 2.5 m cells), its band of two
// cell layers along the bottom and the sides explicit with lumped mass,
// the formula (order 2) on the bottom (the incident wave subtracted) and
// the sides (the free field subtracted), a free top surface; vertically
// incident S and P pulses given as the outcrop motion.
//
// Closed form (a homogeneous half-space, algorithms.md 3.6): the free
// field solves the truncated model, so the surface moves with the outcrop
// record, delayed by the S travel time; once the pulse reflected at the
// surface has left through the bottom, the column is at rest. The
// tolerances come from the formula's own theory: its reflection
// coefficient (boundary::MultiTransmittingFormula::reflection, tested in
// core/test_mtf.cpp) at normal incidence for the pulse's band.
// Under mpirun -n 2 the column is split across the ranks and the stencils
// cross the partition.
#include "fem_test_support.h"
#include "soil_column.h"
#include <damseis/analysis/free_field_load.h>
#include <damseis/analysis/wave_foundation.h>
#include <damseis/boundary/free_field.h>
#include <damseis/dynamics/partitioned_newmark.h>
#include <damseis/fem/mtf_boundary.h>
#include <damseis/geometry/ground_surface.h>
#include <numbers>

using namespace damseis;
using namespace damseis::test;

namespace
{
constexpr int bottom = 5, sides = 6, band_region = tags::foundation_band;

struct ColumnResult
{
  double surface_error = 0.0; ///< max |u - u_s(t - delay)| / peak
  double residual = 0.0;      ///< max |u| in the column at the end / peak
  double stable_dt = 0.0;     ///< the band's stable step
  /// max |a - exact| at the bottom's middle node / the exact peak, over
  /// the run and over its last 0.05 s (the surface's reflections gone)
  double bottom_acceleration = 0.0, bottom_acceleration_end = 0.0;
};

/// The outcrop motion: the pulse d = A sin^4(pi t / T), from rest to rest,
/// or (abrupt) d = A (1 - cos(2 pi t / T)) / 2, whose acceleration jumps
/// from 0 to A (2 pi / T)^2 / 2 at t = 0 and back at T, as a record that
/// starts and ends on a nonzero sample.
struct Outcrop
{
  double A, T;
  bool abrupt = false;
  double displacement(double t) const
  {
    if (!abrupt)
      return pulse(A, T, t);
    return t <= 0 || t >= T
               ? 0.0
               : 0.5 * A * (1 - std::cos(2 * std::numbers::pi * t / T));
  }
  double acceleration(double t) const
  {
    if (!abrupt)
      return pulse_acceleration(A, T, t);
    const double w = 2 * std::numbers::pi / T;
    return t < 0 || t >= T ? 0.0 : 0.5 * A * w * w * std::cos(w * t);
  }
};

/// The column [0, 40] x [-100, 0] of P1 or P2 triangles on 2.5 m squares
/// under a pulse of duration T in component c (0: S, 1: P), the band
/// `layers` cells thick, the formula of order `order` on the band's node
/// spacing (2.5 m / degree).
ColumnResult run_column(int c, double T, int degree, int order, int layers,
                        double drift, bool abrupt = false)
{
  const double W = 40, H = 100, A = 0.01, h = 2.5, dt = 2e-4;
  Model model = rectangle_model(MPI_COMM_WORLD, {0, -H}, {W, 0}, {16, 40},
                                [&](const Point& p)
                                {
                                  if (p[1] < -H + 1e-9)
                                    return bottom;
                                  if (p[0] < 1e-9 || p[0] > W - 1e-9)
                                    return sides;
                                  return -1;
                                });
  // The band: the cells within `layers` layers of the bottom and the sides.
  const double w = layers * h;
  const std::vector<std::int32_t> band =
      tag_band(model, band_region,
               [&](const Point& mid)
               { return mid[0] < w || mid[0] > W - w || mid[1] < -H + w; });
  const boundary::Rock rock{20e9, 0.25, 2600.0};
  const damseis::fem::Material m{rock.E, rock.nu, rock.rho};
  damseis::fem::ElasticModel fe(model, degree,
                                {{tags::dam, m}, {band_region, m}});
  damseis::fem::ElasticModel::Partitioned p =
      fe.assemble_partitioned({band_region}, nullptr);
  PMat K = own(p.K), K_i = own(p.K_implicit), M = own(p.M);
  PVec lumped = own(p.M_explicit);

  const dynamics::RayleighDamping rayleigh{2.0, 2e-4};
  const double delay_s = H / rock.cs();
  const double duration = delay_s + T + 2 * H / rock.cs() + 0.05;
  const int steps = static_cast<int>(duration / dt);
  const Outcrop motion{A, T, abrupt};
  std::array<std::vector<double>, 3> outcrop;
  outcrop[c].resize(steps + 1);
  for (int k = 0; k <= steps; ++k)
    outcrop[c][k] = motion.acceleration(k * dt);
  const geometry::GroundSurface ground(model, {}, {bottom, sides});
  auto field = std::make_shared<boundary::VerticalFreeField>(
      boundary::VerticalFreeField::from_outcrop(rock, 2, -H, 0, outcrop, dt));
  auto mtf = std::make_shared<damseis::fem::MtfBoundary>(
      *fe.V(), *model.facet_tags, std::vector<int>{bottom, sides}, band,
      damseis::fem::MtfSettings{order, drift, h / degree, rock.cp(), rock.cs(),
                                dt},
      analysis::separated_field(field, ground, dt));
  // The bottom's nodes (16 degree + 1), the sides' (40 degree each, the
  // corners the bottom's).
  EXPECT_EQ(mtf->node_counts()[0], 16 * degree + 1 + 2 * 40 * degree);
  EXPECT_EQ(mtf->node_counts()[1], 16 * degree + 1);

  ColumnResult r;
  {
    const double omega = dynamics::highest_explicit_frequency(
        K.mat(), K_i.mat(), lumped.vec(), mtf->rows());
    r.stable_dt = dynamics::explicit_stable_step(omega, {rayleigh.a_mass, 0});
  }
  EXPECT_LT(dt, r.stable_dt);

  const analysis::FreeFieldLoad load(fe, nullptr, ground, field, M.mat(),
                                     K_i.mat(), rayleigh, dt);
  dynamics::PartitionedNewmark newmark(M.mat(), K.mat(), K_i.mat(), rayleigh,
                                       dt, linalg::Factorization::automatic,
                                       mtf);
  PVec f = linalg::column_vector(K.mat());
  PVec zero = linalg::column_vector(K.mat());
  load.assemble(0, f.vec());
  newmark.set_state(zero.vec(), zero.vec(), zero.vec(), f.vec(), {}, 0);
  // At the bottom (z = -H) the free field is the incident wave, half the
  // outcrop motion delayed by H (1/c_s - 1/c), and its reflection from
  // the surface 2 H / c later (algorithms.md 3.6).
  const double speed = c == 0 ? rock.cs() : rock.cp();
  const double lag = H * (1 / rock.cs() - 1 / speed);
  // The abrupt record is baseline corrected (its piecewise-linear samples
  // do not end at rest): its reference is the free field's own closed
  // form (verified in test_free_field.cpp).
  auto bottom_exact = [&](int k)
  {
    if (abrupt)
      return field->at({W / 2, -H, 0}, 0.0, k, k * dt).a[c];
    const double t = k * dt - lag;
    return 0.5 *
           (motion.acceleration(t) + motion.acceleration(t - 2 * H / speed));
  };
  const NodeProbe base(*fe.V(), {W / 2, -H, 0});
  double a_error = 0.0, a_error_end = 0.0, a_peak = 0.0;
  const ColumnErrors e = march_column(
      *fe.V(), newmark.u(), {W / 2, 0, 0}, c, steps, A,
      [&](int k)
      {
        load.assemble(k, f.vec());
        newmark.step(f.vec());
      },
      [&](int k)
      {
        return abrupt ? field->at({W / 2, 0, 0}, 0.0, k, k * dt).u[c]
                      : motion.displacement(k * dt - delay_s);
      },
      [&](int k)
      {
        const double error = std::abs(base(newmark.a(), c) - bottom_exact(k));
        a_error = std::max(a_error, error);
        if (k * dt > duration - 0.05)
          a_error_end = std::max(a_error_end, error);
        a_peak = std::max(a_peak, std::abs(bottom_exact(k)));
      });
  r.surface_error = e.surface;
  r.residual = e.residual;
  r.bottom_acceleration = a_error / a_peak;
  r.bottom_acceleration_end = a_error_end / a_peak;
  return r;
}
} // namespace

// Order 2 on P1 (the formula's lattice: nodes at uniform spacing, the
// band's lumped mass at every node), the default drift control 1e-4, c_p
// for the normal part and c_s for the tangential one. Theory
// (MultiTransmittingFormula::reflection, dx = 2.5 m, dt = 2e-4 s, normal
// incidence): |R| <= 3e-4 from 5 to 40 Hz (the pulse's band) for the
// matching speed, 1.6e-3 at 1 Hz (the drift factor fixes the boundary at
// zero frequency). Measured (S, P): surface error 6.1e-4, 2.1e-4 of the
// peak, at rest after the pulse within 1.2e-4, 2.1e-4. Asserted: the
// surface within 2e-3 of the peak (Newmark's phase error, 2e-4 per period
// at 40 Hz, and the mesh's dispersion, 17 P1 cells per S wavelength at 40
// Hz, bound it; with c_s for the P wave's normal part it was 4.7e-2, and
// with the free field alone prescribed on the bottom the reflected pulse
// returns in full), the residual within 5e-4 (the low-frequency |R|).
// The bottom's acceleration (the formula on a) is the free field's within
// 1.7e-3, 5.3e-4 of the peak: asserted 5e-3.
TEST(MtfColumn, P1OrderTwoSWaveLeavesThroughTheBottom)
{
  const ColumnResult r = run_column(0, 0.1, 1, 2, 4, 1e-4);
  print_metric(fmt("MTF P1 order 2, S: surface error ", r.surface_error,
                   " of the peak, residual ", r.residual, ", stable dt ",
                   r.stable_dt, ", bottom acceleration error ",
                   r.bottom_acceleration));
  EXPECT_LT(r.surface_error, 2e-3);
  EXPECT_LT(r.residual, 5e-4);
  EXPECT_LT(r.bottom_acceleration, 5e-3);
}

TEST(MtfColumn, P1OrderTwoPWaveLeavesThroughTheBottom)
{
  const ColumnResult r = run_column(1, 0.1, 1, 2, 4, 1e-4);
  print_metric(fmt("MTF P1 order 2, P: surface error ", r.surface_error,
                   " of the peak, residual ", r.residual, ", stable dt ",
                   r.stable_dt, ", bottom acceleration error ",
                   r.bottom_acceleration));
  EXPECT_LT(r.surface_error, 2e-3);
  EXPECT_LT(r.residual, 5e-4);
  EXPECT_LT(r.bottom_acceleration, 5e-3);
}

// On P2 the band's lumped lattice alternates vertex and midside masses
// (HRZ: 6 : 32); there order 1 transmits, while order 2 drifts away (the
// boundary's offset grew to the pulse's size within 0.04 s without drift
// control, 8 % of it with gamma_d = 0.01; on P1 it does not): the case
// files refuse order 2 on P2. Theory for order 1 (dx = 1.25 m, s = 0.28 for
// c_s): |R| <= 4e-3 from 10 to 40 Hz, 8e-3 at 5 Hz, 4e-2 at 1 Hz.
// Measured: surface error 1.6e-3, residual 1.0e-3. Asserted: 5e-3 both;
// the bottom's acceleration within 9.9e-3 of the peak, asserted 2e-2.
TEST(MtfColumn, P2OrderOneSWaveLeavesThroughTheBottom)
{
  const ColumnResult r = run_column(0, 0.1, 2, 1, 2, 1e-4);
  print_metric(fmt("MTF P2 order 1, S: surface error ", r.surface_error,
                   " of the peak, residual ", r.residual, ", stable dt ",
                   r.stable_dt, ", bottom acceleration error ",
                   r.bottom_acceleration));
  EXPECT_LT(r.surface_error, 5e-3);
  EXPECT_LT(r.residual, 5e-3);
  EXPECT_LT(r.bottom_acceleration, 2e-2);
}

// The boundary's velocity and acceleration (fem/MtfBoundary: the formula
// on v and a; dynamics::PrescribedMotion), under a record that starts and
// ends with a jump of its acceleration, as recorded accelerograms do (its
// sampled motion is baseline corrected, so the reference is the free
// field's closed form, boundary::VerticalFreeField). Before, the
// boundary's velocity and acceleration came from Newmark's relations on
// its displacements, whose undamped alternating mode the jumps excite: the
// bottom's acceleration grew to 411 (S) and 1012 (P) times the peak by
// the end of this run (627 on P2). Now the jumps leave a transient of a
// few steps at the boundary (up to 0.50 of the peak, the finite elements
// cannot follow a jump), and once the surface's reflections have gone
// the bottom's acceleration is the free field's within 8.1e-4 (S), 4.0e-4
// (P) and 4.0e-4 (P2) of the peak. Asserted: 5e-3 (the smooth pulse's
// bound over its whole run, above), and the surface's displacement within
// 2e-2 (the jumps' dispersion: 5.7e-4, 1.6e-4, 1.2e-3 measured).
TEST(MtfColumn, AbruptRecordLeavesTheBoundaryAccelerationBounded)
{
  for (int c : {0, 1})
  {
    const ColumnResult r = run_column(c, 0.1, 1, 2, 4, 1e-4, true);
    print_metric(fmt("MTF P1 order 2, abrupt record, component ", c,
                     ": surface error ", r.surface_error,
                     ", bottom acceleration error ", r.bottom_acceleration,
                     ", over the last 0.05 s ", r.bottom_acceleration_end));
    EXPECT_LT(r.surface_error, 2e-2);
    EXPECT_LT(r.bottom_acceleration_end, 5e-3);
  }
  const ColumnResult r = run_column(0, 0.1, 2, 1, 2, 1e-4, true);
  print_metric(fmt("MTF P2 order 1, abrupt record: surface error ",
                   r.surface_error, ", bottom acceleration error ",
                   r.bottom_acceleration, ", over the last 0.05 s ",
                   r.bottom_acceleration_end));
  EXPECT_LT(r.surface_error, 2e-2);
  EXPECT_LT(r.bottom_acceleration_end, 5e-3);
}
