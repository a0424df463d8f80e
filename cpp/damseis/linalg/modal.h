// Natural frequencies and mode shapes: K phi = omega^2 M phi (SLEPc).
#pragma once

#include <functional>
#include <petscksp.h>
#include <petscmat.h>
#include <vector>

namespace damseis::linalg
{
/// Result of a modal analysis; the mode vectors are owned by this object.
struct Modes
{
  std::vector<double> frequencies_hz; ///< ascending
  std::vector<Vec> shapes;            ///< M-normalised mode shapes
  Modes() = default;
  Modes(Modes&& other) noexcept;
  Modes& operator=(Modes&& other) noexcept;
  Modes(const Modes&) = delete;
  Modes& operator=(const Modes&) = delete;
  ~Modes();
};

/// The `count` lowest modes of K phi = omega^2 M phi by shift-and-invert
/// around 0 (Krylov-Schur). Fixed dofs (identity rows of K, zero rows of M)
/// and massless parts give infinite eigenvalues, which are never returned.
/// Collective. Throws std::runtime_error if fewer than `count` converge.
Modes solve_modes(Mat K, Mat M, int count);

/// The same for several mass matrices with one stiffness (e.g. with and
/// without the reservoir's added mass): K is factorised once and the
/// factors serve every problem (at the paper's arch dam scale one MUMPS
/// factorisation is ~25 s of the ~80 s modal analysis). Returns the modes
/// of each M in order. Collective.
/// `with_K_factors`, if given, is called once, after the first problem,
/// with a KSP that solves K x = b by those factors (KSPSolve; e.g. the
/// static load case, so that K is factorised once for both).
std::vector<Modes>
solve_modes(Mat K, const std::vector<Mat>& Ms, int count,
            const std::function<void(KSP)>& with_K_factors = {});
} // namespace damseis::linalg
