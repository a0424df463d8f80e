#include "static_contact.h"
#include <damseis/dynamics/nonlinear_newmark.h>
#include <damseis/linalg/petsc_vectors.h>

namespace damseis::joint
{
StaticContactResult static_contact(Mat K, Mat M, double omega_1, Vec F_dead,
                                   Vec F_all, const PairSet& pairs,
                                   const StaticContactSettings& settings,
                                   contact::NcpSettings ncp)
{
  using dolfinx::la::petsc::Vector;
  CondensedContact c(pairs, ncp);
  StaticContactResult r;
  dolfinx::la::petsc::Matrix K_shifted(nullptr, false);
  try
  {
    c.factorize(K);
  }
  catch (const NotPositiveDefinite&)
  {
    // A block held by its joints alone: its rigid motions are free in K.
    if (settings.cantilever_dead_load)
      throw ContactFailure(
          "static stage: a block has no support but its joints, so it "
          "cannot carry its dead weight alone; use joints.dead_load = "
          "\"joints_active\"");
    r.shift = static_shift_factor * omega_1 * omega_1;
    Mat Ks;
    MatDuplicate(K, MAT_COPY_VALUES, &Ks);
    MatAXPY(Ks, r.shift, M, SUBSET_NONZERO_PATTERN);
    K_shifted = dolfinx::la::petsc::Matrix(Ks, false);
    c = CondensedContact(pairs, ncp);
    c.factorize(K_shifted.mat());
  }
  const std::size_t n = pairs.size();
  r.u = linalg::column_vector(K);
  Vector rhs = linalg::column_vector(K), force = linalg::column_vector(K);

  auto increment = [&](double load_factor, const std::string& what)
  {
    // rhs = F_dead + factor (F_all - F_dead)
    VecCopy(F_dead, rhs.vec());
    VecScale(rhs.vec(), 1.0 - load_factor);
    VecAXPY(rhs.vec(), load_factor, F_all);
    try
    {
      c.solve(rhs.vec(), r.u.vec(), force.vec());
    }
    catch (const ContactFailure& e)
    {
      throw ContactFailure("static stage, " + what + ": " + e.what() +
                           "; try more joints.static_increments");
    }
  };

  if (settings.cantilever_dead_load)
  {
    // The blocks carry their own weight; the joints are closed (grouted)
    // in that state, with no force: the gaps' reference and the slips are
    // measured from it.
    c.solve_free(F_dead, r.u.vec());
    const Eigen::VectorXd w = c.relative_of(r.u.vec());
    Eigen::VectorXd g0(n);
    for (std::size_t i = 0; i < n; ++i)
      g0[i] = -w[3 * i];
    c.set_state(g0, w, Eigen::VectorXd::Zero(3 * n),
                std::vector<contact::PairState>(n, contact::PairState::stick));
  }
  else
    increment(0.0, "dead weight");
  const int m = std::max(settings.increments, 1);
  for (int k = 1; k <= m; ++k)
    increment(static_cast<double>(k) / m,
              "load increment " + std::to_string(k) + "/" + std::to_string(m));
  r.g0 = c.g0();
  r.w = c.relative_displacement();
  r.p = c.forces();
  r.states = c.states();
  r.totals = c.totals();
  return r;
}
} // namespace damseis::joint
