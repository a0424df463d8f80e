// The case keys of Liao's multi-transmitting boundary (foundation.mtf_*,
// foundation.band_*), shared by the demos' case readers: their
// declarations, their reading with the checks that need the keys alone,
// and the checks of the time step against the boundary.
#pragma once

#include "wave_foundation.h"
#include <damseis/boundary/viscous_spring.h>
#include <damseis/input/case.h>
#include <string>

namespace damseis::analysis
{
/// Declares the formula's keys: foundation.mtf_order, foundation.mtf_drift,
/// foundation.band_damping and foundation.band_integration.
void add_formula_keys(input::Schema& s);

/// Declares add_formula_keys()'s keys and those of a generated mesh's
/// structured band: foundation.band_layers and foundation.band_size.
/// `where`: the faces the band runs along; `band_size`: the default cell
/// size [m].
void add_transmitting_keys(input::Schema& s, const std::string& where,
                           const std::string& band_size);

/// Reads the formula's keys (order, drift, the band's damping and
/// integration; not its node spacing). With `active` (the boundary is
/// used) it fails (exit 2) on order 2 with P2 elements (the band's lumped
/// lattice alternates vertex and midside masses and the boundary drifts
/// away; tests/fem/test_mtf_boundary.cpp).
Transmitting read_formula_keys(const input::Case& c, int mesh_order,
                               bool active);

/// The structured band a case asks for.
struct BandKeys
{
  int layers = 0;
  double size = 0.0; ///< cell size [m]
};

/// Reads the formula (read_formula_keys(); its node spacing is band_size /
/// mesh_order) and the generated band. With `active` (foundation.boundary
/// = "mtf") it fails (exit 2) also on a band thinner than the stencil (2N
/// node spacings inward of the boundary).
Transmitting read_transmitting_keys(const input::Case& c, int mesh_order,
                                    bool active, BandKeys& band);

/// The time step of a run on the boundary: s = c_p dt / dx <= 1, c_p of
/// `rock`, and time.hht_alpha = 0 unless the band is implicit and the run
/// is in the nonlinear engine (`nonlinear_engine`; the linear engine's
/// partition and an explicit band are Newmark's average acceleration).
/// `coarser`: how the case makes the node spacing larger (the fix named).
void check_transmitting_step(
    const input::Case& c, double hht_alpha, const Transmitting& t,
    bool nonlinear_engine, const boundary::Rock& rock, double dt,
    const std::string& coarser = "a larger foundation.band_size");
} // namespace damseis::analysis
