#include "seismic_system.h"
#include <damseis/fem/tied_dofs.h>
#include <damseis/linalg/petsc_vectors.h>
#include <fstream>

namespace damseis::analysis
{
using dolfinx::la::petsc::Matrix;
using dolfinx::la::petsc::Vector;

namespace
{
/// A full-space vector on the system's unknowns: P^T f, or a copy.
Vector system_vector(Vec f, Mat tie)
{
  if (tie)
  {
    Vector y = linalg::column_vector(tie);
    MatMultTranspose(tie, f, y.vec());
    return y;
  }
  Vec y;
  VecDuplicate(f, &y);
  VecCopy(f, y);
  return Vector(y, false);
}
} // namespace

SeismicSystem assemble_seismic_system(fem::ElasticModel& fe,
                                      const SeismicSettings& s,
                                      const std::vector<Vec>& static_loads,
                                      Mat tie)
{
  SeismicSystem sys;
  const bool wet = s.reservoir.depth() > 0.0;
  sys.added = s.westergaard && wet ? &s.reservoir : nullptr;
  sys.K = Matrix(fe.assemble_stiffness(), false);
  sys.M = Matrix(fe.assemble_mass(sys.added), false);
  if (tie)
  {
    sys.K = Matrix(fem::reduce_to_tied(sys.K.mat(), tie), false);
    sys.M = Matrix(fem::reduce_to_tied(sys.M.mat(), tie), false);
  }
  std::array<double, 3> g = {0, 0, 0};
  g[fe.dim() - 1] = -s.gravity;
  Vector F_g(fe.assemble_gravity(g, s.gravity_regions), false);
  Vector F = system_vector(F_g.vec(), nullptr); // a copy
  if (wet)
  {
    Vector H(fe.assemble_hydrostatic(s.reservoir), false);
    VecAXPY(F.vec(), 1.0, H.vec());
  }
  for (Vec extra : static_loads)
    VecAXPY(F.vec(), 1.0, extra);
  sys.F_g = system_vector(F_g.vec(), tie);
  sys.F_static = system_vector(F.vec(), tie);
  return sys;
}

Matrix dry_mass(fem::ElasticModel& fe, const fem::Reservoir* added, Mat tie)
{
  if (!added)
    return Matrix(nullptr, false);
  Matrix M0(fe.assemble_mass(nullptr), false);
  if (tie)
    M0 = Matrix(fem::reduce_to_tied(M0.mat(), tie), false);
  return M0;
}

void open_run_folder(MPI_Comm comm, const RunFolder& folder)
{
  std::filesystem::create_directories(folder.dir);
  int rank = 0;
  MPI_Comm_rank(comm, &rank);
  if (rank == 0)
    std::ofstream(folder.dir / "case_used.toml") << folder.case_text;
}
} // namespace damseis::analysis
