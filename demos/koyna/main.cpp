// Koyna dam: linear seismic analysis of a gravity-dam section.
//   build/bin/koyna [--case FILE] [--out DIR] [--set key=value ...]
// With no arguments it runs demos/koyna/koyna.toml; --help lists the keys.
#include <cstdio>
#include <damseis/analysis/gravity_dam_analysis.h>
#include <damseis/analysis/linear_seismic.h>
#include <damseis/case/command_line.h>
#include <damseis/output/progress.h>
#include <petscsys.h>

int main(int argc, char** argv)
{
  PetscInitializeNoArguments();
  damseis::output::quiet_library_logging();
  // Any PETSc error is a bug here: stop at once instead of going on.
  PetscPushErrorHandler(PetscAbortErrorHandler, nullptr);
  int rank = 0, status = 0;
  MPI_Comm_rank(PETSC_COMM_WORLD, &rank);
  try
  {
    using namespace damseis;
    const input::Schema schema = analysis::gravity_dam_schema();
    const auto cl = input::parse_command_line(
        argc, argv, "koyna", DAMSEIS_SOURCE_DIR "/demos/koyna/koyna.toml",
        schema);
    if (cl)
    {
      const auto c = input::Case::load(schema, cl->case_file, cl->overrides);
      const auto config = analysis::read_gravity_dam_config(c);
      analysis::run_gravity_dam_analysis(PETSC_COMM_WORLD, config, cl->out_dir,
                                         c.to_toml());
    }
  }
  catch (const damseis::input::InputError& e)
  {
    if (rank == 0)
      std::fprintf(stderr, "koyna: error: %s\n", e.what());
    status = 2;
  }
  catch (const damseis::analysis::Interrupted& e)
  {
    if (rank == 0)
      std::fprintf(stderr, "koyna: %s\n", e.what());
    status = 3;
  }
  PetscFinalize();
  return status;
}
