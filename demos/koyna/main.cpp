// Koyna dam: linear seismic analysis of a gravity-dam section.
//   build/bin/koyna [--case FILE] [--out DIR] [--set key=value ...]
// With no arguments it runs demos/koyna/koyna.toml; --help lists the keys.
#include <damseis/analysis/demo_main.h>
#include <damseis/analysis/gravity_dam_analysis.h>

int main(int argc, char** argv)
{
  using namespace damseis::analysis;
  return demo_main(
      argc, argv, "koyna", DAMSEIS_SOURCE_DIR "/demos/koyna/koyna.toml",
      gravity_dam_schema, read_gravity_dam_config, run_gravity_dam_analysis);
}
