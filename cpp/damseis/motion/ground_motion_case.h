/// @file ground_motion_case.h
/// Case keys of design ground motions: the target spectrum ([prefix] of
/// DesignSpectrumSettings) and the generation of artificial records
/// (ArtificialSettings); the schema of the ground_motion demo. The seismic
/// analyses use the same keys under [design] (motion.<comp>.source =
/// "generated").
#pragma once

#include "artificial.h"
#include "design_spectrum.h"
#include "record.h"
#include <damseis/input/case.h>
#include <filesystem>
#include <string>
#include <vector>

namespace damseis::motion
{
/// Keys <prefix>.code, .dam, .site_class, .tg_map, .pga_g, .vertical_ratio,
/// .tg, .beta_max, .damping, .table_period, .table_sa_g.
void add_target_keys(input::Schema& schema, const std::string& prefix);
/// The horizontal (or vertical) target; InputError naming the key.
DesignSpectrum read_target(const input::Case& c, const std::string& prefix,
                           bool vertical);

/// Keys <prefix>.duration, .dt, .seed, .rise, .strong_end, .decay,
/// .tolerance, .max_correlation, .period_min, .period_max, .periods.
void add_generation_keys(input::Schema& schema, const std::string& prefix);
/// The generation settings; the matching damping is the target's
/// (`target` is the prefix of its keys): Eurocode 8's, else 5%. A table
/// target that does not cover the control periods is refused.
ArtificialSettings read_generation(const input::Case& c,
                                   const std::string& prefix,
                                   const std::string& target);

/// The names of the generated components, in order: two horizontal and the
/// vertical.
const std::vector<std::string>& component_names();

/// The ground_motion demo: task, [target], [generate], [records],
/// [spectra], [output].
input::Schema ground_motion_schema();

struct GroundMotionConfig
{
  bool generate = true;                ///< task "generate" (else "spectrum")
  std::vector<DesignSpectrum> targets; ///< h1, h2, v (generate, or to compare)
  bool has_target = true;
  ArtificialSettings generation;
  /// task "spectrum": the records, read (name, file, record in m/s2).
  struct NamedRecord
  {
    std::string name;
    std::filesystem::path file;
    Record record;
  };
  std::vector<NamedRecord> records;
  std::vector<double> damping; ///< spectra written for these ratios
  std::vector<double> periods; ///< task "spectrum": the periods
  bool plots = true;
};
GroundMotionConfig read_ground_motion_config(const input::Case& c);
} // namespace damseis::motion
