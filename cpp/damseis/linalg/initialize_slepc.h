#pragma once

namespace damseis::linalg
{
/// Initialises SLEPc once, on top of the running PETSc (its eigensolvers
/// need it); later calls do nothing. Collective on the first call.
void initialize_slepc();
} // namespace damseis::linalg
