// Random joint contact problems for the tests of contact/ncp and
// contact/paper_ncp: n pairs with a coupled symmetric positive definite
// flexibility W (diagonal about 1e-9 m/N, off-diagonal coupling about a
// tenth), free relative displacements uniform in +-1e-3 m (normal) and
// +-tangential (tangential; smaller values make more pairs stick), closed
// joints, the laws' scalings 1 / W_ii.
#pragma once

#include <damseis/contact/ncp.h>
#include <random>

namespace damseis::test
{
inline Eigen::MatrixXd random_flexibility(int n, double c, std::mt19937& gen)
{
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Eigen::MatrixXd R(3 * n, 3 * n);
  for (int i = 0; i < 3 * n; ++i)
    for (int j = 0; j < 3 * n; ++j)
      R(i, j) = u(gen);
  Eigen::MatrixXd W = 0.1 * c * R * R.transpose() / (3 * n);
  W.diagonal().array() += c;
  return W;
}

inline contact::ContactProblem
random_problem(int n, double mu, std::mt19937& gen, double tangential = 1e-3)
{
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  contact::ContactProblem pb;
  pb.W = random_flexibility(n, 1e-9, gen);
  pb.w_free.resize(3 * n);
  pb.wT_old = Eigen::VectorXd::Zero(2 * n);
  pb.g0 = Eigen::VectorXd::Zero(n);
  for (int i = 0; i < 3 * n; ++i)
    pb.w_free[i] = (i % 3 == 0 ? 1e-3 : tangential) * u(gen);
  for (int i = 0; i < n; ++i)
  {
    contact::PairLaw law;
    law.mu = mu;
    law.r_n = 1.0 / pb.W(3 * i, 3 * i);
    law.r_t = 1.0 / pb.W(3 * i + 1, 3 * i + 1);
    pb.laws.push_back(law);
  }
  return pb;
}
} // namespace damseis::test
