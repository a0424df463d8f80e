#include "modal_stage.h"
#include "run_outputs.h"
#include <damseis/linalg/petsc_vectors.h>
#include <damseis/results/progress.h>
#include <damseis/results/xdmf_writer.h>
#include <dolfinx/mesh/Mesh.h>

namespace damseis::analysis
{
using dolfinx::la::petsc::Vector;

ModalResult modal_and_damping(Mat K, Mat M, Mat M_dry, const SeismicSettings& s,
                              const std::function<void(KSP)>& with_K_factors)
{
  const auto t0 = std::chrono::steady_clock::now();
  ModalResult r;
  auto timed = [&](KSP ksp)
  {
    const auto t1 = std::chrono::steady_clock::now();
    with_K_factors(ksp);
    r.with_K_factors_seconds += seconds_since(t1);
  };
  std::function<void(KSP)> callback;
  if (with_K_factors)
    callback = timed;
  if (M_dry)
  {
    std::vector<linalg::Modes> both =
        linalg::solve_modes(K, {M, M_dry}, s.modes, callback);
    r.modes = std::move(both[0]);
    r.dry_hz = both[1].frequencies_hz;
  }
  else
  {
    r.modes = std::move(linalg::solve_modes(K, {M}, s.modes, callback)[0]);
    r.dry_hz = r.modes.frequencies_hz;
  }
  r.seconds = seconds_since(t0) - r.with_K_factors_seconds;
  if (s.damping_frequencies_hz.size() == 2)
  {
    r.f1 = s.damping_frequencies_hz[0];
    r.f2 = s.damping_frequencies_hz[1];
  }
  else
  {
    r.f1 = r.modes.frequencies_hz[s.damping_modes[0] - 1];
    r.f2 = r.modes.frequencies_hz[s.damping_modes[1] - 1];
  }
  r.damping =
      dynamics::RayleighDamping::from_ratio(s.damping_ratio, r.f1, r.f2);
  std::ostringstream freqs;
  for (double f : r.modes.frequencies_hz)
    freqs << " " << std::round(f * 1000) / 1000;
  results::print(PetscObjectComm(reinterpret_cast<PetscObject>(K)),
                 "natural frequencies [Hz]:" + freqs.str());
  return r;
}

void write_modes(fem::ElasticModel& fe, const linalg::Modes& modes,
                 const std::function<Vec(Vec)>& full,
                 const std::filesystem::path& file)
{
  dolfinx::fem::Function<double> u(fe.V()), u1(fe.output_space("u_vertex"));
  results::XdmfWriter xdmf(fe.mesh(), file, false);
  for (std::size_t i = 0; i < modes.shapes.size(); ++i)
  {
    linalg::to_function(full(modes.shapes[i]), u);
    u1.interpolate(u);
    char name[64];
    std::snprintf(name, sizeof name, "mode_%02zu_%.4g_Hz", i + 1,
                  modes.frequencies_hz[i]);
    xdmf.point_field(name, u1);
  }
  xdmf.write();
}
} // namespace damseis::analysis
