#include "wave_foundation.h"
#include <cmath>

namespace damseis::analysis
{
std::shared_ptr<const boundary::FreeField>
make_free_field(const WaveFoundation& w, int dim,
                const std::array<std::vector<double>, 3>& outcrop, double dt,
                int steps)
{
  using namespace boundary;
  if (!w.layers.empty())
    return std::make_shared<LayeredColumn>(LayeredColumn::from_outcrop(
        w.z_base, w.layers, dim, outcrop, dt, steps));
  auto homogeneous = [&](const Rock& rock)
  {
    return std::make_shared<VerticalFreeField>(VerticalFreeField::from_outcrop(
        rock, dim, w.z_base, w.z_surface, outcrop, dt));
  };
  if (w.right)
    return std::make_shared<SideBySideFreeField>(
        w.right->first, homogeneous(w.rock), homogeneous(w.right->second));
  return homogeneous(w.rock);
}

fem::KnownField
separated_field(std::shared_ptr<const boundary::FreeField> field,
                const geometry::GroundSurface& ground, double dt)
{
  return [field, &ground, dt](const std::array<double, 3>& x, bool bottom,
                              double t) -> boundary::FreeFieldState
  {
    if (bottom)
      return field->incident(x, t);
    return field->at(x, ground.height(x), static_cast<int>(std::lround(t / dt)),
                     t);
  };
}
} // namespace damseis::analysis
