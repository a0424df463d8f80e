// Case-file keys of the arch-dam geometry (tables [dam], [canyon],
// [foundation] (extent_* keys), [joints], [mesh]).
#pragma once

#include "arch_dam.h"

#include <damseis/input/case.h>

namespace damseis::geometry
{
/// @brief Adds the arch-dam geometry and mesh keys to `schema`, with
/// units, defaults (the paper's 102 m three-centred dam in a V-shaped
/// canyon, see demos/arch_dam/presets/paper_102m_v.toml), bounds and help.
///
/// Keys: dam.height, dam.levels, dam.crown_upstream_y,
/// dam.crown_thickness, dam.abutment_thickness, dam.arch_shape,
/// dam.radius_central, dam.radius_lateral, dam.central_angle,
/// dam.thickening_exponent, dam.interpolation; canyon.shape,
/// canyon.bottom_width, canyon.crest_width, canyon.u_radius,
/// canyon.u_segments, canyon.z, canyon.x_left, canyon.x_right;
/// foundation.extent_upstream, foundation.extent_downstream,
/// foundation.extent_below, foundation.extent_beyond; joints.count,
/// joints.positions, joints.active; mesh.size, mesh.size_far,
/// mesh.grading_distance, mesh.dam_layers, mesh.sections,
/// mesh.arch_points, mesh.optimize.
void arch_dam_schema(input::Schema& schema);

/// @brief Reads the keys of arch_dam_schema from a loaded case and
/// validates the whole geometry (ArchDamGeometry).
/// @throws input::InputError naming the key for impossible input (e.g.
/// "case.toml: dam.crown_thickness: needs one value per level (5), got 4;
/// expected ...").
ArchDamDefinition read_arch_dam(const input::Case& c);
} // namespace damseis::geometry
