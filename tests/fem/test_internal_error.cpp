// An internal error (a library failure, a bug) ends the run with one line
// naming the stage it happened in, and exit code 1 (issue 16).
#include <damseis/analysis/demo_main.h>
#include <damseis/results/progress.h>
#include <gtest/gtest.h>
#include <mpi.h>

TEST(InternalError, OneLineNamingTheStageAndExitCode1)
{
  int size = 1;
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  if (size > 1)
    GTEST_SKIP() << "a death test forks: serial only";
  GTEST_FLAG_SET(death_test_style, "fast");
  damseis::results::set_stage("time history");
  EXPECT_EXIT(damseis::analysis::stop_on_internal_error(
                  "koyna", "PETSc error 55 (Out of memory)\nin MatLUFactor"),
              ::testing::ExitedWithCode(1),
              "^koyna: internal error during time history: PETSc error 55 "
              "\\(Out of memory\\) in MatLUFactor\n$");
  damseis::results::set_stage("");
}
