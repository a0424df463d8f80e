// Compares the sparse direct factorisations PETSc offers here on the
// effective Newmark matrix of the Koyna section: factorisation time, time per
// solve (the cost of a linear time step is dominated by it) and accuracy.
//   bench_factorizations [mesh_size] [degree] [solves]
// Prints a Markdown table (rank 0). Serial variants are skipped in parallel.
#include <chrono>
#include <cstdio>
#include <damseis/fem/elastic_model.h>
#include <damseis/geometry/gravity_dam.h>
#include <damseis/geometry/tags.h>
#include <damseis/results/progress.h>
#include <dolfinx/la/petsc.h>
#include <petscksp.h>
#include <string>
#include <vector>

namespace
{
struct Variant
{
  std::string name, mat_type, pc, solver, ordering;
  bool serial_only;
};

double seconds(std::chrono::steady_clock::time_point t0)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0)
      .count();
}
} // namespace

int main(int argc, char** argv)
{
  PetscInitializeNoArguments();
  damseis::results::quiet_library_logging();
  PetscPushErrorHandler(PetscReturnErrorHandler, nullptr);
  const double h = argc > 1 ? std::stod(argv[1]) : 1.0;
  const int degree = argc > 2 ? std::stoi(argv[2]) : 2;
  const int nsolve = argc > 3 ? std::stoi(argv[3]) : 200;
  MPI_Comm comm = PETSC_COMM_WORLD;
  int size = 1, rank = 0;
  MPI_Comm_size(comm, &size);
  MPI_Comm_rank(comm, &rank);
  {
    namespace ds = damseis;
    ds::geometry::GravityDamSection s;
    s.mesh_size = h;
    ds::fem::ElasticModel fe(ds::geometry::build_gravity_dam(comm, s), degree,
                             {{ds::tags::dam, {30e9, 0.2, 2500}}},
                             ds::fem::PlaneMode::plane_stress);
    fe.fix({ds::tags::dam_base});
    ds::fem::Reservoir res;
    res.level = 91.75;
    dolfinx::la::petsc::Matrix K(fe.assemble_stiffness(), false);
    dolfinx::la::petsc::Matrix M(fe.assemble_mass(&res), false);
    // Effective matrix of average acceleration, dt = 0.01 s, 5% Rayleigh.
    const double dt = 0.01, a0 = 4 / (dt * dt), a1 = 2 / dt;
    const double aM = 1.337, bK = 1.185e-3;
    Mat A;
    MatDuplicate(K.mat(), MAT_COPY_VALUES, &A);
    MatScale(A, 1 + a1 * bK);
    MatAXPY(A, a0 + a1 * aM, M.mat(), SUBSET_NONZERO_PATTERN);
    Vec b, x, r;
    MatCreateVecs(A, &x, &b);
    VecDuplicate(b, &r);
    Vec f = fe.assemble_gravity({0, -9.81, 0});
    VecCopy(f, b);
    VecDestroy(&f);
    PetscInt n;
    MatGetSize(A, &n, nullptr);
    if (rank == 0)
    {
      std::printf("# Koyna section, mesh %.2f m, P%d: %d dofs, %d ranks\n\n", h,
                  degree, static_cast<int>(n), size);
      std::printf("| factorisation | matrix | factor [s] | solve [ms] | "
                  "rel. residual |\n|---|---|---|---|---|\n");
    }
    const std::vector<Variant> variants = {
        {"petsc cholesky nd", "aij", "cholesky", "petsc", "nd", true},
        {"petsc cholesky qmd", "aij", "cholesky", "petsc", "qmd", true},
        {"petsc cholesky rcm", "aij", "cholesky", "petsc", "rcm", true},
        {"petsc cholesky amd", "aij", "cholesky", "petsc", "amd", true},
        {"petsc lu nd (2x2 blocks)", "baij", "lu", "petsc", "nd", true},
        {"petsc lu amd (2x2 blocks)", "baij", "lu", "petsc", "amd", true},
        {"cholmod", "aij", "cholesky", "cholmod", "", true},
        {"umfpack lu", "aij", "lu", "umfpack", "", true},
        {"superlu lu", "aij", "lu", "superlu", "", true},
        {"mumps cholesky", "aij", "cholesky", "mumps", "", false},
        {"mumps lu", "aij", "lu", "mumps", "", false},
        {"mumps lu (2x2 blocks)", "baij", "lu", "mumps", "", false},
        {"mumps cholesky (sym. blocks)", "sbaij", "cholesky", "mumps", "",
         false},
        {"superlu_dist lu", "aij", "lu", "superlu_dist", "", false},
    };
    for (const Variant& v : variants)
    {
      if (v.serial_only && size > 1)
        continue;
      Mat B;
      MatConvert(A,
                 size > 1 ? ("mpi" + v.mat_type).c_str()
                          : ("seq" + v.mat_type).c_str(),
                 MAT_INITIAL_MATRIX, &B);
      MatSetOption(B, MAT_SYMMETRIC, PETSC_TRUE);
      MatSetOption(B, MAT_SPD, PETSC_TRUE);
      KSP ksp;
      KSPCreate(comm, &ksp);
      KSPSetType(ksp, KSPPREONLY);
      PC pc;
      KSPGetPC(ksp, &pc);
      PCSetType(pc, v.pc.c_str());
      PCFactorSetMatSolverType(pc, v.solver.c_str());
      if (!v.ordering.empty())
        PCFactorSetMatOrderingType(pc, v.ordering.c_str());
      KSPSetOperators(ksp, B, B);
      auto t0 = std::chrono::steady_clock::now();
      PetscErrorCode ierr = KSPSetUp(ksp);
      const double tf = seconds(t0);
      if (ierr)
      {
        if (rank == 0)
          std::printf("| %s | %s | failed | | |\n", v.name.c_str(),
                      v.mat_type.c_str());
      }
      else
      {
        KSPSolve(ksp, b, x); // warm-up
        t0 = std::chrono::steady_clock::now();
        for (int i = 0; i < nsolve; ++i)
          KSPSolve(ksp, b, x);
        const double ts = seconds(t0) / nsolve;
        MatMult(A, x, r);
        VecAXPY(r, -1.0, b);
        double rn, bn;
        VecNorm(r, NORM_2, &rn);
        VecNorm(b, NORM_2, &bn);
        if (rank == 0)
          std::printf("| %s | %s | %.3f | %.3f | %.1e |\n", v.name.c_str(),
                      v.mat_type.c_str(), tf, 1e3 * ts, rn / bn);
      }
      KSPDestroy(&ksp);
      MatDestroy(&B);
    }
    VecDestroy(&x);
    VecDestroy(&b);
    VecDestroy(&r);
    MatDestroy(&A);
  }
  PetscFinalize();
  return 0;
}
