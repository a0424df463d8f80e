// A foundation with mass and a viscous-spring boundary, the seismic input
// entering as vertically incident waves (the absolute formulation;
// fem/viscous_boundary, analysis/free_field_load), in place of the
// massless foundation fixed at its far boundary with the base acceleration
// as load (the relative formulation).
#pragma once

#include <array>
#include <damseis/boundary/free_field.h>
#include <damseis/boundary/layered_column.h>
#include <damseis/boundary/viscous_spring.h>
#include <memory>
#include <optional>
#include <vector>

namespace damseis::analysis
{
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
};

/// The free field of the foundation's rock under the outcrop record
/// (accelerations per component on the time grid k dt, k = 0..steps).
std::shared_ptr<const boundary::FreeField>
make_free_field(const WaveFoundation& w, int dim,
                const std::array<std::vector<double>, 3>& outcrop, double dt,
                int steps);
} // namespace damseis::analysis
