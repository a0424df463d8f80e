#include "impact.h"

namespace damseis::contact
{
NormalVelocities impact(double m_a, double m_b, NormalVelocities v, double e)
{
  const double rel = v.b - v.a;
  if (rel >= 0.0)
    return v;
  const double m = m_a + m_b;
  return {v.a + (1.0 + e) * m_b / m * rel, v.b - (1.0 + e) * m_a / m * rel};
}
} // namespace damseis::contact
