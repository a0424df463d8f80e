// Principal stresses of a stress vector (tension positive).
#pragma once

#include <array>
#include <cmath>

namespace damseis::results
{
/// Largest and smallest principal stress of a 2D (sxx, syy, sxy) or 3D
/// (sxx, syy, szz, sxy, syz, sxz) stress vector; `n` is 3 or 6. In 2D these
/// are the in-plane principal stresses.
std::array<double, 2> principal_extremes(const double* s, int n);
} // namespace damseis::results
