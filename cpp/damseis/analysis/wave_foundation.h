// A foundation with mass and a viscous-spring (fem/viscous_boundary) or a
// multi-transmitting boundary (fem/mtf_boundary), the seismic input
// entering as vertically incident waves (the absolute formulation;
// analysis/free_field_load), in place of the
// massless foundation fixed at its far boundary with the base acceleration
// as load (the relative formulation).
#pragma once

#include <array>
#include <damseis/boundary/free_field.h>
#include <damseis/boundary/layered_column.h>
#include <damseis/boundary/viscous_spring.h>
#include <damseis/fem/mtf_boundary.h>
#include <damseis/geometry/ground_surface.h>
#include <memory>
#include <optional>
#include <vector>

namespace damseis::analysis
{
/// The far boundary of a foundation block: fixed (a massless block, the
/// ground motion as base acceleration), or the rock with mass and a
/// viscous-spring or a multi-transmitting boundary (wave input).
enum class FoundationBoundary
{
  fixed,
  viscous_spring,
  transmitting
};

/// Liao's multi-transmitting boundary in place of the viscous-spring one:
/// a structured band of explicit (lumped) elements along the sides and
/// bottom (the Hughes-Liu partition), the formula at the boundary's nodes.
struct Transmitting
{
  int order = 2;      ///< N
  double drift = 0.0; ///< gamma_d
  /// The band's stiffness-proportional damping, its ratio of critical at
  /// the band's highest frequency (dynamics::PartitionedNewmark's b_E).
  double band_damping = 0.0;
  double spacing = 0.0; ///< node spacing of the band along its normals [m]
  /// The band's cell tags: the cells the formula's stencils read (points
  /// between nodes interpolated), the explicit group if `band_explicit`.
  std::vector<int> band_regions;
  /// The band explicit with lumped mass (the Hughes-Liu partition), or
  /// implicit with the rest (consistent mass; no stable step of its own).
  bool band_explicit = true;
};

struct WaveFoundation
{
  /// The facet tags of the truncated foundation's sides and bottom.
  std::vector<int> boundary_tags;
  /// The scattering centre (the middle of the dam base) [m].
  std::array<double, 3> centre = {0, 0, 0};
  boundary::SpringFactors factors;
  /// The rock of the free field (homogeneous half-space) and the heights
  /// of the model's bottom and of the free surface (the foundation top).
  boundary::Rock rock;
  double z_base = 0.0, z_surface = 0.0;
  /// Horizontal layers from z_base up (the last top the free surface),
  /// the free field then computed on a 1D column; empty: the homogeneous
  /// `rock`.
  std::vector<boundary::Layer> layers;
  /// Two rocks side by side: `rock` where x < the split, this one beyond
  /// (each column its own homogeneous free field).
  std::optional<std::pair<double, boundary::Rock>> right;
  /// The multi-transmitting boundary (then `factors` are unused), or the
  /// viscous-spring boundary if empty.
  std::optional<Transmitting> mtf;
};

/// The free field of the foundation's rock under the outcrop record
/// (accelerations per component on the time grid k dt, k = 0..steps).
std::shared_ptr<const boundary::FreeField>
make_free_field(const WaveFoundation& w, int dim,
                const std::array<std::vector<double>, 3>& outcrop, double dt,
                int steps);

/// The known field of a transmitting boundary's wave-field separation
/// (algorithms.md 3.4): the incident wave at the bottom, the free field
/// (each column's ground from `ground`) on the sides. `field` and `ground`
/// must outlive the result's use.
fem::KnownField
separated_field(std::shared_ptr<const boundary::FreeField> field,
                const geometry::GroundSurface& ground, double dt);
} // namespace damseis::analysis
