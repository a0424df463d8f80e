// The common body of the demo executables: PETSc set-up, command line, case
// file, error handling and exit codes (0 done, 2 bad input, 3 stopped with a
// checkpoint, 4 a nonlinear step that could not be solved).
#pragma once

#include <cstdio>
#include <damseis/analysis/linear_seismic.h>
#include <damseis/case/command_line.h>
#include <damseis/dynamics/nonlinear_newmark.h>
#include <damseis/results/progress.h>
#include <filesystem>
#include <petscsys.h>
#include <string>

namespace damseis::analysis
{
/// Runs a demo: `schema()` gives its case keys, `read(case)` the validated
/// configuration (throwing input::InputError on bad input) and
/// `run(comm, config, out_dir, case_text)` the analysis.
template <typename Schema, typename Read, typename Run>
int demo_main(int argc, char** argv, const std::string& name,
              const std::filesystem::path& default_case, Schema schema,
              Read read, Run run)
{
  PetscInitializeNoArguments();
  results::quiet_library_logging();
  // Any PETSc error is a bug here: stop at once instead of going on.
  PetscPushErrorHandler(PetscAbortErrorHandler, nullptr);
  int rank = 0, status = 0;
  MPI_Comm_rank(PETSC_COMM_WORLD, &rank);
  try
  {
    const input::Schema keys = schema();
    const auto cl =
        input::parse_command_line(argc, argv, name, default_case, keys);
    if (cl)
    {
      const auto c = input::Case::load(keys, cl->case_file, cl->overrides);
      const auto config = read(c);
      run(PETSC_COMM_WORLD, config, cl->out_dir, c.to_toml());
    }
  }
  catch (const input::InputError& e)
  {
    if (rank == 0)
      std::fprintf(stderr, "%s: error: %s\n", name.c_str(), e.what());
    status = 2;
  }
  catch (const Interrupted& e)
  {
    if (rank == 0)
      std::fprintf(stderr, "%s: %s\n", name.c_str(), e.what());
    status = 3;
  }
  catch (const dynamics::StepFailure& e)
  {
    // A step the Newton iteration could not solve even with cut steps: the
    // run stops (outputs so far stay) rather than accept it.
    if (rank == 0)
      std::fprintf(stderr,
                   "%s: error: %s; try a smaller time.dt, a larger "
                   "solver.max_cuts or a finer mesh\n",
                   name.c_str(), e.what());
    status = 4;
  }
  PetscFinalize();
  return status;
}
} // namespace damseis::analysis
