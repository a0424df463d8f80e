/// @file path.h
/// Single-point driver: runs a HtcConcrete along a prescribed path with mixed
/// strain/stress control. Each of the six components is either
/// strain-controlled or stress-controlled in a segment; the free strains of
/// the stress-controlled components are found by a small Newton iteration
/// with the consistent tangent (a failing step is retried with 2, 4, ...
/// sub-steps).
#pragma once

#include "concrete.h"

#include <iosfwd>
#include <string>
#include <vector>

namespace damseis::material
{

enum class Control
{
  strain,
  stress
};

/// One segment: every component goes linearly in time from its value at the
/// start of the segment to `target` (a strain, engineering shear, or a
/// stress [Pa], according to `control`).
struct Segment
{
  double duration = 1.0; ///< [s] (> 0)
  int steps = 1;
  std::array<Control, 6> control{};
  Vector6 target{};
  /// tie[i] = j >= 0: the strain increment of component i equals that of
  /// component j (axisymmetric paths: tie 33 to 22). A tied component's own
  /// control/target are ignored. Needed on the compressive meridian: there
  /// the HTC edge leaves the split of the flow between its two faces free
  /// under stress control, and an untied lateral pair drifts apart.
  std::array<int, 6> tie{-1, -1, -1, -1, -1, -1};
};

/// The state after one step.
struct PathPoint
{
  double time = 0;
  Vector6 strain{};      ///< total strain (engineering shear)
  Vector6 strain_rate{}; ///< of the step
  State state;
  unsigned active = 0;
  int local_iterations = 0; ///< of the last integration of the step
  int outer_iterations = 0; ///< mixed-control Newton iterations
};

struct PathResult
{
  std::vector<PathPoint> points; ///< the initial state first
  bool completed = true;
  std::string message; ///< why the run stopped early
};

/// Runs the path. The outer Newton converges when the stress-controlled
/// components are within `stress_tolerance` x fc0 of their targets.
PathResult run_path(const HtcConcrete& model,
                    const std::vector<Segment>& segments,
                    const State& initial = {}, double stress_tolerance = 1e-9);

/// Writes the points as CSV (header line, one row per point).
void write_csv(std::ostream& out, const PathResult& result);

/// Convenience: uniaxial stress path along 11 (other stresses zero) to
/// strain `eps_end` at constant strain rate `rate` [1/s] in `steps` steps.
std::vector<Segment> uniaxial_path(double eps_end, double rate, int steps);

} // namespace damseis::material
