// Replays joint contact problems dumped by a run (DAMSEIS_DUMP_NCP=<prefix>
// writes <prefix>_<k>.bin at every contact solve) through the NCP solver:
// iterations, line-search steps, residual and time per problem.
//   bench_ncp_replay FILE... [--paper] [--stick-start] [--max-iterations N]
// (--paper: formulation A, the paper's polar unknowns).
#include <chrono>
#include <cstdio>
#include <cstring>
#include <damseis/contact/ncp.h>
#include <string>
#include <vector>

int main(int argc, char** argv)
{
  damseis::contact::NcpSettings s;
  std::vector<std::string> files;
  bool stick_start = false;
  for (int i = 1; i < argc; ++i)
  {
    if (std::strcmp(argv[i], "--stick-start") == 0)
      stick_start = true;
    else if (std::strcmp(argv[i], "--paper") == 0)
      s.formulation = damseis::contact::Formulation::paper;
    else if (std::strcmp(argv[i], "--max-iterations") == 0 && i + 1 < argc)
      s.max_iterations = std::stoi(argv[++i]);
    else
      files.push_back(argv[i]);
  }
  std::printf(
      "| problem | pairs | converged | iterations | line-search steps | "
      "gradient steps | reduced rows | open | slip | residual | "
      "Alart-Curnier residual | seconds "
      "|\n|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  for (const auto& f : files)
  {
    Eigen::VectorXd p0;
    const auto c = damseis::contact::read_problem(f, p0);
    if (stick_start)
    {
      // Every pair stuck and closed: W p = w_target - w_free.
      const Eigen::Index n = static_cast<Eigen::Index>(c.laws.size());
      Eigen::VectorXd target(3 * n);
      for (Eigen::Index i = 0; i < n; ++i)
        target.segment<3>(3 * i) << -c.g0[i], c.wT_old.segment<2>(2 * i);
      p0 = c.W_inv * (target - c.w_free);
    }
    const auto t0 = std::chrono::steady_clock::now();
    const auto r = damseis::contact::solve_ncp(c, p0, s);
    const double sec =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0)
            .count();
    // The same yardstick for both formulations: the Cartesian residual of
    // the forces found, over the force scale.
    Eigen::VectorXd w;
    std::vector<damseis::contact::PairState> st;
    const double ac = damseis::contact::contact_residual(c, r.p, w, st).norm() /
                      damseis::contact::force_scale(c, p0);
    int open = 0, slip = 0;
    for (auto state : r.states)
    {
      open += state == damseis::contact::PairState::open;
      slip += state == damseis::contact::PairState::slip;
    }
    std::printf(
        "| %s | %zu | %s | %d | %d | %d | %d | %d | %d | %.2e | %.2e | %.3f "
        "|\n",
        f.c_str(), c.laws.size(), r.converged ? "yes" : "no", r.iterations,
        r.line_search_steps, r.gradient_steps, r.reduced_rows, open, slip,
        r.residual, ac, sec);
  }
}
