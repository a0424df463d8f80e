#include "demo_main.h"
#include <cstdlib>
#include <unistd.h>

namespace damseis::analysis
{
namespace
{
std::string petsc_program = "damseis";

PetscErrorCode petsc_error(MPI_Comm, int line, const char* fun,
                           const char* file, PetscErrorCode n, PetscErrorType p,
                           const char* mess, void*)
{
  if (p != PETSC_ERROR_INITIAL)
    return n;
  const char* text = nullptr;
  PetscErrorMessage(n, &text, nullptr);
  const std::string what = mess ? mess : "";
  // MUMPS' workspace too small (INFOG(1) = -8 or -9): the fix is the user's.
  const bool workspace = what.find("INFOG(1)=-9") != std::string::npos ||
                         what.find("INFOG(1)=-8") != std::string::npos;
  stop_on_internal_error(
      petsc_program,
      std::string("PETSc error ") + std::to_string(n) + " (" +
          (text ? text : "") + ") in " + fun + " (" + file + ":" +
          std::to_string(line) + "): " + what +
          (workspace ? "; MUMPS' workspace was too small: run again with "
                       "PETSC_OPTIONS=\"-mat_mumps_icntl_14 80 "
                       "-st_mat_mumps_icntl_14 80\" (80% above its "
                       "estimate; damseis gives 40%)"
                     : ""));
}

/// True if `dir` or, for a study, one of its runs' folders holds a
/// checkpoint (a run's folder is one or two levels down: <set>, or
/// level_<m>/<model> and ratio_<r>/<model>).
bool has_checkpoint(const std::filesystem::path& dir, int depth = 2)
{
  namespace fs = std::filesystem;
  std::error_code ec;
  if (fs::exists(dir / "checkpoint" / "checkpoint.json", ec))
    return true;
  if (depth == 0)
    return false;
  for (auto it = fs::directory_iterator(dir, ec);
       !ec && it != fs::directory_iterator(); it.increment(ec))
  {
    if (it->is_directory(ec) && it->path().filename() != "checkpoint" &&
        has_checkpoint(it->path(), depth - 1))
      return true;
  }
  return false;
}
} // namespace

void stop_on_internal_error(const std::string& program, const std::string& what)
{
  std::string line = what;
  for (char& c : line)
  {
    if (c == '\n' || c == '\r')
      c = ' ';
  }
  const std::string& stage = results::current_stage();
  std::fprintf(stderr, "%s: internal error%s: %s\n", program.c_str(),
               stage.empty() ? "" : (" during " + stage).c_str(), line.c_str());
  std::fflush(stderr);
  std::fflush(stdout);
  int size = 1, initialized = 0;
  MPI_Initialized(&initialized);
  if (initialized)
    MPI_Comm_size(MPI_COMM_WORLD, &size);
  if (size > 1)
    MPI_Abort(MPI_COMM_WORLD, 1);
  std::_Exit(1);
}

void stop_on_petsc_errors(const std::string& program)
{
  petsc_program = program;
  PetscPushErrorHandler(petsc_error, nullptr);
}

void prepare_run_folder(MPI_Comm comm, const std::filesystem::path& out_dir,
                        bool restart, results::Overwrite policy)
{
  int rank = 0;
  MPI_Comm_rank(comm, &rank);
  if (restart)
  {
    if (!has_checkpoint(out_dir))
    {
      throw input::InputError(
          "run.restart = true, but " + (out_dir / "checkpoint").string() +
          " holds no checkpoint; expected the output folder of a run "
          "stopped with a checkpoint (run.checkpoint_every, "
          "run.stop_at_step or Ctrl-C during the time history), or "
          "run.restart = false to start from the beginning");
    }
    return;
  }
  // Every rank sees the same folder: "refuse" throws on all of them.
  if (policy == results::Overwrite::refuse &&
      results::holds_earlier_run(out_dir))
    results::prepare_output_folder(out_dir, policy);
  std::string line;
  if (rank == 0)
    line = results::prepare_output_folder(out_dir, policy);
  MPI_Barrier(comm);
  if (!line.empty())
    results::print(comm, line);
}

void finish_run_folder(MPI_Comm comm, const std::filesystem::path& out_dir,
                       std::filesystem::file_time_type start, bool restart)
{
  int rank = 0;
  MPI_Comm_rank(comm, &rank);
  if (rank != 0)
    return;
  const auto older = results::write_manifest(out_dir, start, restart);
  if (older.empty())
    return;
  std::string list;
  for (std::size_t i = 0; i < older.size() && i < 5; ++i)
    list += (i ? ", " : "") + older[i];
  if (older.size() > 5)
    list += ", ...";
  std::printf("warning: %zu files in %s were not written by this run (%s)\n",
              older.size(), out_dir.string().c_str(), list.c_str());
}
} // namespace damseis::analysis
