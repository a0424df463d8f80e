// 190 m roller-compacted concrete gravity dam on a massless foundation:
// dead weight, reservoir, silt and uplift, two-component ground motion at
// 0.2 g; rate-independent vs rate-dependent concrete (the paper's Figs. 7-9).
//   build/bin/rcc_gravity [--case FILE] [--out DIR] [--set key=value ...]
// Same keys as koyna (--help); default case demos/rcc_gravity/rcc_gravity.toml.
#include <damseis/analysis/demo_main.h>
#include <damseis/analysis/gravity_dam_analysis.h>

int main(int argc, char** argv)
{
  using namespace damseis::analysis;
  return demo_main(argc, argv, "rcc_gravity",
                   DAMSEIS_SOURCE_DIR "/demos/rcc_gravity/rcc_gravity.toml",
                   gravity_dam_schema, read_gravity_dam_config,
                   run_gravity_dam_analysis);
}
