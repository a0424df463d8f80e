#include "initialize_slepc.h"
#include <slepcsys.h>

namespace damseis::linalg
{
void initialize_slepc()
{
  PetscBool initialized = PETSC_FALSE;
  SlepcInitialized(&initialized);
  if (!initialized)
    SlepcInitialize(nullptr, nullptr, nullptr, nullptr);
}
} // namespace damseis::linalg
