// geometry/GmshSession: an abort inside gmsh (an assertion of its mesher)
// ends the process with one line and exit code 1, not a backtrace and a
// core (the guide: no core dump). The abort is raised directly: the
// mesher's assertions that once fired (tetgen's boundary recovery on a
// band of 3.4 m strips against 80 m cells) depend on gmsh's version.
#include <damseis/geometry/gmsh_session.h>

#include <csignal>
#include <cstdlib>
#include <gtest/gtest.h>
#include <mpi.h>

TEST(GmshSession, AnAbortInsideGmshIsOneLineAndExitCodeOne)
{
  int size = 1;
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  if (size > 1)
    GTEST_SKIP() << "a death test forks: serial only";
  GTEST_FLAG_SET(death_test_style, "threadsafe");
  EXPECT_EXIT(
      {
        damseis::geometry::GmshSession session(false);
        std::abort();
      },
      ::testing::ExitedWithCode(1),
      "^damseis: internal error during meshing: gmsh aborted");
}

TEST(GmshSession, TheHandlerIsRestoredWhenTheSessionEnds)
{
  void (*before)(int) = std::signal(SIGABRT, SIG_DFL);
  std::signal(SIGABRT, before);
  {
    damseis::geometry::GmshSession session(false);
    void (*during)(int) = std::signal(SIGABRT, SIG_DFL);
    std::signal(SIGABRT, during);
    EXPECT_NE(during, before);
  }
  void (*after)(int) = std::signal(SIGABRT, SIG_DFL);
  std::signal(SIGABRT, after);
  EXPECT_EQ(after, before);
}
