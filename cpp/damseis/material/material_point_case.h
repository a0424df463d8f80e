/// @file material_point_case.h
/// Case-file keys of the concrete model ([material]) and of the single-point
/// driver ([path]); used by demos/material_point.
#pragma once

#include "path.h"
#include <damseis/input/case.h>

#include <string>
#include <vector>

namespace damseis::material
{

/// Declares the [prefix] keys of ConcreteParameters (E, nu, fc0, ..., mode).
void add_concrete_keys(input::Schema& schema,
                       const std::string& prefix = "material");
/// Reads them; inconsistent values -> InputError (one line).
ConcreteParameters
read_concrete_parameters(const input::Case& c,
                         const std::string& prefix = "material");

/// The schema of the material_point demo: [material], [path], [output].
input::Schema material_point_schema();

struct MaterialPointConfig
{
  ConcreteParameters material;
  std::vector<Segment> segments;
  std::string csv_name;
  bool plots = true; ///< PNG of the curve (scripts/plot_material_point.py)
};

/// Builds the path segments from [path]; bad combinations -> InputError.
MaterialPointConfig read_material_point_config(const input::Case& c);

} // namespace damseis::material
