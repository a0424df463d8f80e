// XDMF/HDF5 output of displacement and stress fields, and of the stress
// envelopes, readable by ParaView.
#pragma once

#include "stress_envelope.h"
#include <damseis/fem/elastic_model.h>
#include <dolfinx/io/XDMFFile.h>
#include <filesystem>
#include <memory>

namespace damseis::results
{
/// Cell averages (DG0) of the stress-point values of every local cell:
/// returns the tensor (tdim x tdim, row-major) per cell.
std::vector<double> cell_average_tensor(const dolfinx::fem::FunctionSpace& S,
                                        std::span<const double> s,
                                        int num_cells, int tdim);

/// A time series: displacement at the vertices (P1), cell stress tensor,
/// and the cell's largest and smallest principal stresses.
class FieldWriter
{
public:
  FieldWriter(fem::ElasticModel& model, const std::filesystem::path& file);
  ~FieldWriter();
  /// Writes the fields at time t. `s` holds the stress-point values
  /// (owned and ghost, layout of S).
  void write(const dolfinx::fem::Function<double>& u, std::span<const double> s,
             double t);

private:
  fem::ElasticModel& _model;
  std::unique_ptr<dolfinx::io::XDMFFile> _file;
  std::shared_ptr<dolfinx::fem::Function<double>> _u, _sig, _pmax, _pmin;
};

/// Writes the envelopes as cell fields (largest value over the cell's
/// points) and vertex fields (largest over the points at the vertex), plus
/// Values in Pa; NaN outside the envelope's region.
void write_envelopes(fem::ElasticModel& model, const StressEnvelope& env,
                     const std::filesystem::path& file);
} // namespace damseis::results
