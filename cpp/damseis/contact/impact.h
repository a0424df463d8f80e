// Impact correction of a joint pair that closes during a step
// (algorithms.md 2.7, the paper: "momentum and kinetic energy conserved"):
// the normal velocities of the two nodes are changed so that the normal
// momentum is kept and the relative normal velocity becomes -e times its
// value before (e = 1: kinetic energy kept; e = 0: the nodes move together).
#pragma once

namespace damseis::contact
{
struct NormalVelocities
{
  double a = 0.0, b = 0.0; ///< side 1 and side 2, along the pair normal
};

/// The velocities after the impact of nodes of (lumped) masses m_a, m_b
/// (> 0) approaching with relative velocity v.b - v.a < 0; unchanged if
/// they separate (v.b - v.a >= 0). 0 <= e <= 1.
NormalVelocities impact(double m_a, double m_b, NormalVelocities v, double e);
} // namespace damseis::contact
