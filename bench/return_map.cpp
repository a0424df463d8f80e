// Throughput of the concrete return map (HtcConcrete::integrate), points per
// second on one core, for elastic, plastic and viscoplastic points and a
// "typical" dam mix (90% elastic steps, 10% on the surface).
//   bench_return_map [points] [elastic|plastic|viscoplastic] [repeats]
// (a mode and repeats > 1 single out one mode's timed loops for a profiler)
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <damseis/material/concrete.h>
#include <random>
#include <string>
#include <vector>

using namespace damseis::material;

namespace
{
struct Item
{
  State old;
  Vector6 de;
};

double run(const HtcConcrete& m, const std::vector<Item>& items, double dt,
           int repeats, long& plastic, long& failed)
{
  double sink = 0;
  const auto t0 = std::chrono::steady_clock::now();
  for (int r = 0; r < repeats; ++r)
  {
    plastic = failed = 0;
    for (const auto& it : items)
    {
      const Update u = m.integrate(it.old, it.de, dt);
      sink += u.state.stress[0] + u.tangent[7];
      plastic += u.active != 0;
      failed += !u.converged;
    }
  }
  const double s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0)
          .count();
  if (sink == 12345.678)
    std::printf(" ");
  return repeats * items.size() / s;
}
} // namespace

int main(int argc, char** argv)
{
  const int n = argc > 1 ? std::atoi(argv[1]) : 200000;
  const std::string only = argc > 2 ? argv[2] : "";
  const int repeats = argc > 3 ? std::max(1, std::atoi(argv[3])) : 1;
  const double dt = 0.01;
  std::mt19937 g(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  // Items: old states on a seismic path (uniaxial tension then small
  // multiaxial increments). "elastic": well inside the surface; "on
  // surface": old state at the tensile strength or in compression at the
  // peak, loaded further. Two kinds of on-surface items: "rate jump", the
  // old state reached in one step and loaded by small increments (the
  // strain rate drops ~40x between the steps: the viscoplastic return
  // starts far from its rate), and "steady rate", the old state reached in
  // 12 equal steps and loaded by a 13th at the same rate (+-5%), as along a
  // time history.
  enum class Kind
  {
    elastic,
    rate_jump,
    steady_rate
  };
  auto make = [&](const HtcConcrete& m, Kind kind)
  {
    std::vector<Item> v(n);
    const double E = m.derived().E;
    const bool on_surface = kind != Kind::elastic;
    for (int k = 0; k < n; ++k)
    {
      Item& it = v[k];
      Vector6 pre{};
      const bool tension = k % 2 == 0;
      const double eps0 = tension ? (on_surface ? 1.2 : 0.5) * 2.5e6 / E
                                  : (on_surface ? -1.1 : -0.5) * 30e6 / E;
      pre = {eps0, -0.17 * eps0, -0.17 * eps0, 0, 0, 0};
      for (int i = 0; i < 6; ++i)
        pre[i] += 0.02 * std::abs(eps0) * u(g);
      if (kind == Kind::steady_rate)
      {
        constexpr int steps = 12;
        Vector6 d;
        for (int i = 0; i < 6; ++i)
          d[i] = pre[i] / steps;
        State s;
        for (int j = 0; j < steps; ++j)
          s = m.integrate(s, d, dt).state;
        it.old = s;
        for (int i = 0; i < 6; ++i)
          it.de[i] = d[i] * (1.0 + 0.05 * u(g));
        continue;
      }
      it.old = m.integrate(State{}, pre, dt).state;
      for (int i = 0; i < 6; ++i)
        it.de[i] = 1e-6 * u(g) + (i == 0 ? (tension ? 2e-6 : -4e-6) : 0.0);
    }
    return v;
  };
  std::printf("| mode | points | elastic pts/s | on-surface, rate jump "
              "pts/s (plastic share) | on-surface, steady rate pts/s "
              "(plastic share) | failures | typical mix (90/10, rate jump) "
              "pts/s |\n");
  std::printf("|---|---|---|---|---|---|---|\n");
  for (Mode mode : {Mode::elastic, Mode::plastic, Mode::viscoplastic})
  {
    const char* name = mode == Mode::elastic   ? "elastic"
                       : mode == Mode::plastic ? "plastic"
                                               : "viscoplastic";
    if (!only.empty() && only != name)
      continue;
    ConcreteParameters p;
    p.mode = mode;
    const HtcConcrete m(p);
    const auto el = make(m, Kind::elastic), pl = make(m, Kind::rate_jump),
               st = make(m, Kind::steady_rate);
    long np = 0, nf = 0, np2 = 0, nf2 = 0, np3 = 0, nf3 = 0;
    const double re = run(m, el, dt, repeats, np, nf);
    const double rp = run(m, pl, dt, repeats, np2, nf2);
    const double rs = run(m, st, dt, repeats, np3, nf3);
    const double mix = 1.0 / (0.9 / re + 0.1 / rp);
    std::printf("| %s | %d | %.3g | %.3g (%.2f) | %.3g (%.2f) | %ld | %.3g "
                "|\n",
                name, n, re, rp, double(np2) / n, rs, double(np3) / n,
                nf + nf2 + nf3, mix);
  }
  return 0;
}
