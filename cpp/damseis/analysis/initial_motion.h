// The initial state of a run that starts with a velocity: v0 on the
// system's unknowns and the acceleration that balances it.
#pragma once

#include <damseis/dynamics/newmark.h>
#include <damseis/engine/parts.h>
#include <damseis/linalg/direct_solver.h>
#include <dolfinx/la/petsc.h>

namespace damseis::analysis
{
struct InitialMotion
{
  dolfinx::la::petsc::Vector v0{nullptr, false}, a0{nullptr, false};
};

/// v0: `v0_full` restricted to the tied unknowns (`tie`, may be null); a0
/// from M a0 = f(0) - C v0 - f_int(u0) at rest under the load, i.e.
/// a0 = a_load(0) - M^-1 C v0 with C = a_M M + b_K K, where M has mass;
/// rows without mass (fixed dofs, massless regions) keep the load's a0.
/// M and K on the system's unknowns. Collective.
InitialMotion initial_motion(MPI_Comm comm, Mat M, Mat K,
                             const dynamics::RayleighDamping& damping,
                             const engine::DynamicLoad& load, Vec v0_full,
                             Mat tie, linalg::Factorization factorization);
} // namespace damseis::analysis
