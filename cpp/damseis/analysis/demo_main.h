// The common body of the demo executables: PETSc set-up, command line, case
// file, output folder, error handling and exit codes (0 done, 1 internal
// error, 2 bad input, 3 stopped with a checkpoint, 4 a nonlinear step that
// could not be solved).
#pragma once

#include "linear_seismic.h"
#include <cstdio>
#include <damseis/dynamics/nonlinear_newmark.h>
#include <damseis/engine/stop_signals.h>
#include <damseis/input/command_line.h>
#include <damseis/joint/condensed_contact.h>
#include <damseis/results/output_folder.h>
#include <damseis/results/progress.h>
#include <filesystem>
#include <optional>
#include <petscsys.h>
#include <string>

namespace damseis::analysis
{
/// Stops the process after an error that is not the user's (a bug, a
/// library failure): one line on stderr, exit code 1, no core dump. On
/// several ranks the others may be waiting in a collective call, so the
/// run is aborted through MPI.
[[noreturn]] void stop_on_internal_error(const std::string& program,
                                         const std::string& what);

/// Installs a PETSc error handler that reports the first PETSc error of a
/// call as one line and stops (stop_on_internal_error).
void stop_on_petsc_errors(const std::string& program);

/// Before a run in `out_dir`, collective: with `restart`, checks that a
/// checkpoint is there (input::InputError otherwise); else applies the
/// output.overwrite policy to an earlier run's files (rank 0 deletes) and
/// prints what it did.
void prepare_run_folder(MPI_Comm comm, const std::filesystem::path& out_dir,
                        bool restart, results::Overwrite policy);

/// After a run (rank 0): lists the run's files in the folder's manifest
/// and warns about files it did not write.
void finish_run_folder(MPI_Comm comm, const std::filesystem::path& out_dir,
                       std::filesystem::file_time_type start, bool restart);

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
  stop_on_petsc_errors(name);
  int rank = 0, status = 0;
  MPI_Comm comm = PETSC_COMM_WORLD;
  MPI_Comm_rank(comm, &rank);
  const auto start = std::filesystem::file_time_type::clock::now();
  std::optional<std::filesystem::path> folder;
  bool restart = false;
  try
  {
    const input::Schema keys = schema();
    const auto cl =
        input::parse_command_line(argc, argv, name, default_case, keys);
    if (cl)
    {
      const auto c = input::Case::load(keys, cl->case_file, cl->overrides);
      const auto config = read(c);
      results::check_output_folder(cl->out_dir);
      restart = c.boolean("run.restart");
      prepare_run_folder(
          comm, cl->out_dir, restart,
          results::parse_overwrite(c.string("output.overwrite")));
      folder = cl->out_dir;
      if (c.keys_in_file() == 0)
      {
        results::warn(comm, c.file().string() +
                                " gives no keys: every value is a default "
                                "or a --set override");
      }
      run(comm, config, cl->out_dir, c.to_toml());
    }
  }
  catch (const input::InputError& e)
  {
    if (rank == 0)
      std::fprintf(stderr, "%s: error: %s\n", name.c_str(), e.what());
    status = 2;
  }
  catch (const engine::Interrupted& e)
  {
    if (rank == 0)
      std::fprintf(stderr, "%s: %s\n", name.c_str(), e.what());
    status = 3;
  }
  catch (const joint::ContactFailure& e)
  {
    // The contact of the joints failed (the run stops rather than accept
    // the step).
    if (rank == 0)
      std::fprintf(stderr, "%s: error: %s%s\n", name.c_str(), e.what(),
                   std::string(e.what()).find("static stage") ==
                           std::string::npos
                       ? "; try a smaller time.dt or time.hht_alpha = -0.1"
                       : "");
    status = 4;
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
  catch (const std::exception& e)
  {
    stop_on_internal_error(name, e.what());
  }
  catch (const std::string& e) // gmsh throws strings
  {
    stop_on_internal_error(name, e);
  }
  catch (...)
  {
    stop_on_internal_error(name, "unknown exception");
  }
  if (folder)
    finish_run_folder(comm, *folder, start, restart);
  PetscFinalize();
  return status;
}
} // namespace damseis::analysis
