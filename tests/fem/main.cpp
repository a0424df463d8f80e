// Test runner for the finite element tests: PETSc (and MPI) around GoogleTest.
// Only rank 0 prints results.
#include <damseis/results/progress.h>
#include <gtest/gtest.h>
#include <petscsys.h>

int main(int argc, char** argv)
{
  ::testing::InitGoogleTest(&argc, argv);
  PetscInitialize(&argc, &argv, nullptr, nullptr);
  damseis::results::quiet_library_logging();
  // Any PETSc error is a bug here: stop at once instead of going on.
  PetscPushErrorHandler(PetscAbortErrorHandler, nullptr);
  int rank = 0;
  MPI_Comm_rank(PETSC_COMM_WORLD, &rank);
  if (rank != 0)
  {
    auto& listeners = ::testing::UnitTest::GetInstance()->listeners();
    delete listeners.Release(listeners.default_result_printer());
  }
  int result = RUN_ALL_TESTS();
  // Every rank must agree: a failure on any rank fails the run.
  int global = 0;
  MPI_Allreduce(&result, &global, 1, MPI_INT, MPI_MAX, PETSC_COMM_WORLD);
  PetscFinalize();
  return global;
}
