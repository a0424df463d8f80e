// Speed and acceptance of the ground-motion tools (issue 17 targets: a
// 5%-damped spectrum at 300 periods of a 3000-point record in under 20 ms;
// three 20 s components at dt = 0.01 s generated and matched in under 2 s,
// serial). Prints a markdown report; bench/run_ground_motion.sh saves it.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <damseis/motion/artificial.h>
#include <damseis/motion/record.h>
#include <damseis/motion/spectrum.h>
#include <string>
#include <vector>

using namespace damseis::motion;
namespace
{
double seconds_since(std::chrono::steady_clock::time_point t0)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0)
      .count();
}

double median(std::vector<double> v)
{
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

void spectrum_speed(const std::string& record)
{
  const Record r = read_record(record, Units::g);
  // 3000 points: the record at 0.01 s (resampled, 1559 x 2 samples).
  std::vector<double> a = resample(r, 0.01, 29.99);
  const auto periods = log_spaced(0.04, 4.0, 300);
  std::vector<double> times;
  for (int run = 0; run < 11; ++run)
  {
    const auto t0 = std::chrono::steady_clock::now();
    const Spectrum s = response_spectrum(a, 0.01, periods, 0.05);
    times.push_back(seconds_since(t0));
    if (s.psa.empty())
      return;
  }
  std::printf("| spectrum: %zu points, 300 periods 0.04-4 s, 5%% | %.1f ms "
              "(median of 11; min %.1f, max %.1f) | < 20 ms |\n",
              a.size(), 1e3 * median(times),
              1e3 * *std::min_element(times.begin(), times.end()),
              1e3 * *std::max_element(times.begin(), times.end()));
}

void generation(const char* name, DesignSpectrumSettings d, int seeds)
{
  const DesignSpectrum h(d);
  d.vertical = true;
  const DesignSpectrum v(d);
  std::vector<double> times;
  int accepted = 0;
  double worst = 0, correlation = 0, pgv = 0, pgd = 0;
  for (int seed = 1; seed <= seeds; ++seed)
  {
    ArtificialSettings s;
    s.seed = static_cast<std::uint64_t>(seed);
    const auto t0 = std::chrono::steady_clock::now();
    const ArtificialMotion m = generate_motion({h, h, v}, s);
    times.push_back(seconds_since(t0));
    accepted += m.accepted;
    for (const auto& c : m.components)
    {
      worst = std::max(worst, std::abs(c.worst_ratio - 1));
      pgv = std::max(pgv, c.measures.pgv);
      pgd = std::max(pgd, c.measures.pgd);
    }
    for (double r : m.correlations)
      correlation = std::max(correlation, std::abs(r));
  }
  std::printf("| three 20 s components, %s, %d seeds | %.2f s median (max "
              "%.2f s); %d / %d within +-10%% (worst %.3f), max |corr| "
              "%.3f, PGV up to %.2f m/s, PGD up to %.2f m | < 2 s |\n",
              name, seeds, median(times),
              *std::max_element(times.begin(), times.end()), accepted, seeds,
              worst, correlation, pgv, pgd);
}
} // namespace

int main(int argc, char** argv)
{
  const std::string record = argc > 1 ? argv[1]
                                      : DAMSEIS_SOURCE_DIR
                                 "/data/records/elcentro_1940_ns.at2";
  std::printf("| task | measured | target |\n|---|---|---|\n");
  spectrum_speed(record);
  DesignSpectrumSettings nb;
  nb.code = SpectrumCode::nb35047_2015;
  nb.dam = DamType::arch;
  nb.site_class = "I1";
  nb.pga = 0.321 * standard_gravity;
  generation("NB 35047-2015 arch I1 0.321 g", nb, 20);
  DesignSpectrumSettings dl;
  dl.code = SpectrumCode::dl5073_2000;
  dl.dam = DamType::gravity;
  dl.site_class = "II";
  dl.pga = 0.2 * standard_gravity;
  generation("DL 5073-2000 gravity II 0.2 g", dl, 20);
  DesignSpectrumSettings ec;
  ec.code = SpectrumCode::ec8_type1;
  ec.site_class = "C";
  ec.pga = 0.3 * standard_gravity;
  generation("EC8 type 1 ground C 0.3 g", ec, 20);
  return 0;
}
