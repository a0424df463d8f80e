// Arch dam: linear seismic analysis of a 3D arch dam in its canyon, on a
// massless foundation, with bonded contraction joints.
//   build/bin/arch_dam [--case FILE] [--out DIR] [--set key=value ...]
// With no arguments it runs demos/arch_dam/arch_dam.toml (the paper's 102 m
// dam); presets of other dams are in demos/arch_dam/presets/; --help lists
// the keys.
#include <damseis/analysis/arch_dam_analysis.h>
#include <damseis/analysis/demo_main.h>

int main(int argc, char** argv)
{
  using namespace damseis::analysis;
  return demo_main(argc, argv, "arch_dam",
                   DAMSEIS_SOURCE_DIR "/demos/arch_dam/arch_dam.toml",
                   arch_dam_schema, read_arch_dam_config,
                   run_arch_dam_analysis);
}
