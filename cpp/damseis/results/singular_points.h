// Mesh-objective stress extremes: the points where the elastic stress is
// unbounded (re-entrant corners, the heel and toe where the dam meets a
// rigid base or the rock, and in 3D the lines where the faces meet the
// rock) give extremes that grow with every refinement. Beside the raw
// extremes, damseis reports the extremes over the stress points farther
// than a radius r from every singular point: the stress at a fixed distance
// from a singularity converges with refinement, so these figures are
// mesh-objective (for r several cells wide).
#pragma once

#include "stress_envelope.h"
#include <array>
#include <damseis/geometry/gmsh_mesh.h>
#include <mpi.h>
#include <span>
#include <vector>

namespace damseis::results
{
using Point3 = std::array<double, 3>;

/// The singular corners of a polygon given counterclockwise: its reflex
/// vertices (interior angle above 180 degrees) and the vertices listed in
/// `always` (indices; e.g. the heel and the toe on the base).
std::vector<Point3> reflex_corners(std::span<const Point3> polygon,
                                   std::span<const int> always);

/// The mesh nodes where a facet with one of `face_tags` meets a facet with
/// `interface_tag` (3D: the lines where the dam faces meet the rock),
/// gathered on every rank (collective).
std::vector<Point3> meeting_points(const geometry::Model& model,
                                   std::span<const int> face_tags,
                                   int interface_tag);

/// Distance from x to the nearest of `points` (infinity if none).
double distance_to(const Point3& x, std::span<const Point3> points);

/// The points among `candidates` (owned points of the envelope) farther
/// than `radius` from every singular point.
std::vector<std::int32_t>
points_away_from(const StressEnvelope& env,
                 std::span<const std::int32_t> candidates,
                 std::span<const Point3> singular, double radius);
} // namespace damseis::results
