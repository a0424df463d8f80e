#include "xdmf_writer.h"
#include <algorithm>
#include <cmath>
#include <dolfinx/common/IndexMap.h>
#include <dolfinx/fem/DofMap.h>
#include <dolfinx/io/HDF5Interface.h>
#include <dolfinx/la/Vector.h>
#include <fstream>
#include <iomanip>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace damseis::results
{
namespace
{
using dolfinx::io::HDF5Interface;

/// Escapes a text for an XML attribute value.
std::string xml_text(const std::string& s)
{
  std::string out;
  for (char c : s)
  {
    switch (c)
    {
    case '&':
      out += "&amp;";
      break;
    case '<':
      out += "&lt;";
      break;
    case '>':
      out += "&gt;";
      break;
    case '"':
      out += "&quot;";
      break;
    default:
      out += c;
    }
  }
  return out;
}

std::string attribute_type(int ncomp)
{
  return ncomp == 1 ? "Scalar" : ncomp == 3 ? "Vector" : "Matrix";
}
} // namespace

XdmfWriter::XdmfWriter(std::shared_ptr<const dolfinx::mesh::Mesh> mesh,
                       const std::filesystem::path& file, bool series)
    : _mesh(std::move(mesh)), _xdmf(file), _series(series)
{
  const int tdim = _mesh->topology().dim();
  _cells.resize(_mesh->topology().index_map(tdim)->size_local());
  for (std::size_t c = 0; c < _cells.size(); ++c)
    _cells[c] = static_cast<std::int32_t>(c);
  write_mesh();
}

XdmfWriter::XdmfWriter(std::shared_ptr<const dolfinx::mesh::Mesh> mesh,
                       const std::filesystem::path& file,
                       std::span<const std::int32_t> cells, bool series)
    : _mesh(std::move(mesh)), _xdmf(file), _series(series)
{
  const int tdim = _mesh->topology().dim();
  const std::int32_t owned_cells =
      _mesh->topology().index_map(tdim)->size_local();
  for (std::int32_t c : cells)
  {
    if (c < owned_cells)
      _cells.push_back(c);
  }
  std::sort(_cells.begin(), _cells.end());
  _cells.erase(std::unique(_cells.begin(), _cells.end()), _cells.end());
  write_mesh();
}

void XdmfWriter::write_mesh()
{
  MPI_Comm comm = _mesh->comm();
  int size = 1;
  MPI_Comm_rank(comm, &_rank);
  MPI_Comm_size(comm, &size);
  _mpi_io = size > 1;
  _h5 = _xdmf;
  _h5.replace_extension(".h5");
  const int tdim = _mesh->topology().dim();

  // Nodes used by the written cells: marked where used, summed at their
  // owners, numbered by the owners, numbers sent back to the ghosts.
  const auto& geometry = _mesh->geometry();
  const auto& x_dofmap = geometry.dofmap();
  auto x_map = geometry.index_map();
  const std::int32_t owned_nodes = x_map->size_local();
  dolfinx::la::Vector<double> mark(x_map, 1);
  std::fill(mark.mutable_array().begin(), mark.mutable_array().end(), 0.0);
  for (std::int32_t c : _cells)
  {
    for (std::int32_t n : x_dofmap.links(c))
      mark.mutable_array()[n] = 1.0;
  }
  mark.scatter_rev(std::plus<double>());
  for (std::int32_t n = 0; n < owned_nodes; ++n)
  {
    if (mark.array()[n] > 0.0)
      _nodes.push_back(n);
  }
  std::int64_t local_nodes = static_cast<std::int64_t>(_nodes.size());
  MPI_Exscan(&local_nodes, &_node_offset, 1, MPI_INT64_T, MPI_SUM, comm);
  if (_rank == 0)
    _node_offset = 0;
  MPI_Allreduce(&local_nodes, &_num_nodes, 1, MPI_INT64_T, MPI_SUM, comm);
  dolfinx::la::Vector<double> number(x_map, 1);
  std::fill(number.mutable_array().begin(), number.mutable_array().end(), -1.0);
  for (std::size_t i = 0; i < _nodes.size(); ++i)
    number.mutable_array()[_nodes[i]] =
        static_cast<double>(_node_offset + static_cast<std::int64_t>(i));
  number.scatter_fwd();

  std::int64_t local_cells = static_cast<std::int64_t>(_cells.size());
  MPI_Exscan(&local_cells, &_cell_offset, 1, MPI_INT64_T, MPI_SUM, comm);
  if (_rank == 0)
    _cell_offset = 0;
  MPI_Allreduce(&local_cells, &_num_cells, 1, MPI_INT64_T, MPI_SUM, comm);

  // The mesh datasets.
  const int npc = _mesh->geometry().cmap().dim();
  std::vector<std::int64_t> topology;
  topology.reserve(_cells.size() * npc);
  for (std::int32_t c : _cells)
  {
    for (std::int32_t n : x_dofmap.links(c))
      topology.push_back(static_cast<std::int64_t>(number.array()[n]));
  }
  const int gdim = geometry.dim();
  std::vector<double> xyz;
  xyz.reserve(_nodes.size() * gdim);
  for (std::int32_t n : _nodes)
  {
    for (int j = 0; j < gdim; ++j)
      xyz.push_back(geometry.x()[3 * n + j]);
  }
  _hid = HDF5Interface::open_file(comm, _h5, "w", _mpi_io);
  HDF5Interface::write_dataset(_hid, "/mesh/topology", topology.data(),
                               {_cell_offset, _cell_offset + local_cells},
                               {_num_cells, npc}, _mpi_io, false);
  HDF5Interface::write_dataset(_hid, "/mesh/geometry", xyz.data(),
                               {_node_offset, _node_offset + local_nodes},
                               {_num_nodes, gdim}, _mpi_io, false);
  HDF5Interface::flush_file(_hid);

  const std::string h5 = _h5.filename().string();
  std::ostringstream m;
  m << "      <Topology TopologyType=\""
    << (tdim == 2 ? "Triangle" : "Tetrahedron") << "\" NumberOfElements=\""
    << _num_cells << "\" NodesPerElement=\"" << npc << "\">\n"
    << "        <DataItem Dimensions=\"" << _num_cells << " " << npc
    << "\" NumberType=\"Int\" Precision=\"8\" Format=\"HDF\">" << h5
    << ":/mesh/topology</DataItem>\n      </Topology>\n"
    << "      <Geometry GeometryType=\"" << (gdim == 2 ? "XY" : "XYZ")
    << "\">\n        <DataItem Dimensions=\"" << _num_nodes << " " << gdim
    << "\" NumberType=\"Float\" Precision=\"8\" Format=\"HDF\">" << h5
    << ":/mesh/geometry</DataItem>\n      </Geometry>\n";
  _mesh_xml = m.str();
}

XdmfWriter::~XdmfWriter()
{
  if (_hid >= 0)
    HDF5Interface::close_file(_hid);
}

std::vector<double> XdmfWriter::node_values(std::span<const double> values,
                                            int ncomp, int padded) const
{
  std::vector<double> out(_nodes.size() * padded, 0.0);
  for (std::size_t i = 0; i < _nodes.size(); ++i)
  {
    for (int j = 0; j < ncomp; ++j)
      out[i * padded + j] = values[_nodes[i] * ncomp + j];
  }
  return out;
}

void XdmfWriter::point_field(const std::string& name,
                             std::span<const double> values, int ncomp,
                             bool vector)
{
  const int padded = vector && ncomp < 3 ? 3 : ncomp;
  _pending.push_back({name, false, padded, node_values(values, ncomp, padded)});
}

void XdmfWriter::point_field(const std::string& name,
                             const dolfinx::fem::Function<double>& u)
{
  // P1 dofs to geometry nodes, cell by cell (the same local ordering; every
  // owned node lies in a local cell).
  const auto& dofmap = *u.function_space()->dofmap();
  const int bs = dofmap.bs();
  const auto& x_dofmap = _mesh->geometry().dofmap();
  const std::size_t num_nodes = _mesh->geometry().x().size() / 3;
  if (dofmap.element_dof_layout().num_dofs() != _mesh->geometry().cmap().dim())
    throw std::invalid_argument("XdmfWriter: " + name +
                                " is not a P1 function of the mesh");
  std::vector<double> at_nodes(num_nodes * bs, 0.0);
  const std::span<const double> a = u.x()->array();
  const int tdim = _mesh->topology().dim();
  const auto cmap = _mesh->topology().index_map(tdim);
  const std::int32_t num_cells = cmap->size_local() + cmap->num_ghosts();
  for (std::int32_t c = 0; c < num_cells; ++c)
  {
    auto dofs = dofmap.cell_dofs(c);
    auto nodes = x_dofmap.links(c);
    for (std::size_t i = 0; i < dofs.size(); ++i)
    {
      for (int j = 0; j < bs; ++j)
        at_nodes[nodes[i] * bs + j] = a[dofs[i] * bs + j];
    }
  }
  point_field(name, at_nodes, bs, bs > 1);
}

void XdmfWriter::cell_field(const std::string& name,
                            std::span<const double> values, int ncomp)
{
  std::vector<double> out(_cells.size() * ncomp);
  for (std::size_t i = 0; i < _cells.size(); ++i)
  {
    for (int j = 0; j < ncomp; ++j)
      out[i * ncomp + j] = values[_cells[i] * ncomp + j];
  }
  _pending.push_back({name, true, ncomp, std::move(out)});
}

void XdmfWriter::write(double t)
{
  if (!_series && _grids > 0)
    throw std::logic_error("XdmfWriter: a file without time has one grid");
  const std::string group =
      _series ? "/step" + std::to_string(_grids) : std::string("/fields");
  for (Field& f : _pending)
  {
    // No NaN or infinity reaches a file (collective decision).
    int finite = std::all_of(f.values.begin(), f.values.end(),
                             [](double v) { return std::isfinite(v); });
    MPI_Allreduce(MPI_IN_PLACE, &finite, 1, MPI_INT, MPI_MIN, _mesh->comm());
    if (!finite)
      throw std::runtime_error("XdmfWriter: field " + f.name + " of " +
                               _xdmf.string() + " has a non-finite value");
    const std::int64_t n = f.on_cells
                               ? static_cast<std::int64_t>(_cells.size())
                               : static_cast<std::int64_t>(_nodes.size());
    const std::int64_t offset = f.on_cells ? _cell_offset : _node_offset;
    const std::int64_t total = f.on_cells ? _num_cells : _num_nodes;
    HDF5Interface::write_dataset(_hid, group + "/" + f.name, f.values.data(),
                                 {offset, offset + n}, {total, f.ncomp},
                                 _mpi_io, false);
  }
  HDF5Interface::flush_file(_hid);
  if (_rank == 0)
    _written.push_back(grid_xml(t, group, _pending));
  _pending.clear();
  ++_grids;
  if (_rank == 0)
    write_xml();
}

std::string XdmfWriter::grid_xml(double t, const std::string& group,
                                 const std::vector<Field>& fields) const
{
  const std::string h5 = _h5.filename().string();
  std::ostringstream x;
  x.precision(17);
  x << "    <Grid Name=\"" << xml_text(_xdmf.stem().string())
    << "\" GridType=\"Uniform\">\n";
  if (_series)
    x << "      <Time Value=\"" << std::setprecision(12) << t
      << std::setprecision(17) << "\"/>\n";
  x << _mesh_xml;
  for (const Field& f : fields)
  {
    const std::int64_t n = f.on_cells ? _num_cells : _num_nodes;
    x << "      <Attribute Name=\"" << xml_text(f.name) << "\" AttributeType=\""
      << attribute_type(f.ncomp) << "\" Center=\""
      << (f.on_cells ? "Cell" : "Node") << "\">\n"
      << "        <DataItem Dimensions=\"" << n << " " << f.ncomp
      << "\" NumberType=\"Float\" Precision=\"8\" Format=\"HDF\">" << h5 << ":"
      << group << "/" << xml_text(f.name)
      << "</DataItem>\n      </Attribute>\n";
  }
  x << "    </Grid>\n";
  return x.str();
}

void XdmfWriter::write_xml() const
{
  std::ostringstream x;
  x << "<?xml version=\"1.0\"?>\n"
    << "<Xdmf Version=\"3.0\">\n  <Domain>\n";
  if (_series)
  {
    x << "    <Grid Name=\"" << xml_text(_xdmf.stem().string())
      << "\" GridType=\"Collection\" CollectionType=\"Temporal\">\n";
  }
  for (const std::string& g : _written)
    x << g;
  if (_series)
    x << "    </Grid>\n";
  x << "  </Domain>\n</Xdmf>\n";
  // Written aside and renamed: a reader never sees half a file.
  const std::filesystem::path tmp = _xdmf.string() + ".tmp";
  std::ofstream(tmp) << x.str();
  std::filesystem::rename(tmp, _xdmf);
}
} // namespace damseis::results
