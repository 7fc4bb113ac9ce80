// NodalHdf5Writer writes the nodal fields in double precision: on a 2D
// quadrilateral mesh with hanging nodes (p4est) and a 3D tetrahedral mesh
// (fully distributed), fields whose values are not floats (1/3 + pi x, ...)
// are written, the files read back with deal.II's HDF5 interface, and every
// value must equal the vector's entry bit for bit at the node of the same
// position; every cell row must be a cell of the mesh with its vertices in
// XDMF order; x + u must be the sum of both; the XDMF collection must name
// the datasets of every step written and drop the steps after a resume; a
// missing directory is named.
#include <deal.II/base/function.h>
#include <deal.II/base/hdf5.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/lac/trilinos_vector.h>
#include <deal.II/numerics/vector_tools.h>

#include <hemicontact/base/exceptions.h>
#include <hemicontact/mesh/discretization.h>
#include <hemicontact/output/nodal_hdf5_writer.h>

#include <array>
#include <cmath>
#include <cstring>
#include <fstream>
#include <map>
#include <sstream>

#include "tests.h"

using namespace hemicontact;

namespace
{
  /** Component c of a field: 1/3 + pi x + c sqrt(2) y - e z / (s + 1). */
  template <int dim>
  class FieldValues : public Function<dim>
  {
  public:
    explicit FieldValues(const double s)
      : Function<dim>(dim)
      , s(s)
    {}

    double
    value(const Point<dim> &p, const unsigned int c) const override
    {
      return 1. / 3 + numbers::PI * p[0] + c * std::sqrt(2.) * p[1] -
             (dim == 3 ? std::exp(1.) * p[dim - 1] / (s + 1) : 0.) + s / 7;
    }

  private:
    const double s;
  };

  bool
  same_bits(const double a, const double b)
  {
    return std::memcmp(&a, &b, sizeof(double)) == 0;
  }

  template <int dim>
  using Key = std::array<double, dim>;

  template <int dim>
  Key<dim>
  key(const Point<dim> &p)
  {
    Key<dim> k;
    for (unsigned int d = 0; d < dim; ++d)
      k[d] = p[d];
    return k;
  }

  /** Count what differs between the file @p h5 and the vectors. */
  template <int dim>
  void
  check(const DoFHandler<dim>                                   &dof_handler,
        const std::string                                       &h5,
        const std::vector<typename NodalHdf5Writer<dim>::Field> &fields)
  {
    const MPI_Comm            comm       = MPI_COMM_WORLD;
    const auto               &fe         = dof_handler.get_fe();
    const unsigned int        n_vertices = fe.reference_cell().n_vertices();
    std::vector<unsigned int> order(n_vertices);
    for (unsigned int v = 0; v < n_vertices; ++v)
      order[v] = v;
    if (fe.reference_cell() == ReferenceCells::Quadrilateral)
      order = {0, 1, 3, 2};

    // the owned nodes by position, and the owned cells by their vertices
    std::map<Key<dim>, std::array<types::global_dof_index, dim>> nodes;
    std::map<std::vector<double>, unsigned int>                  cells;
    std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (!cell->is_artificial())
        {
          cell->get_dof_indices(dofs);
          for (unsigned int v = 0; v < n_vertices; ++v)
            if (dof_handler.locally_owned_dofs().is_element(
                  dofs[fe.component_to_system_index(0, v)]))
              for (unsigned int c = 0; c < dim; ++c)
                nodes[key(cell->vertex(v))][c] =
                  dofs[fe.component_to_system_index(c, v)];
          if (cell->is_locally_owned())
            {
              std::vector<double> corners;
              for (const unsigned int v : order)
                for (unsigned int d = 0; d < dim; ++d)
                  corners.push_back(cell->vertex(v)[d]);
              ++cells[corners];
            }
        }

    // every rank reads the whole file (collectively) and checks what it owns
    HDF5::File file(h5, HDF5::File::FileAccessMode::open, comm);
    const auto positions =
      file.open_dataset("nodes").template read<std::vector<double>>();
    const auto connectivity =
      file.open_dataset("cells").template read<std::vector<unsigned int>>();
    const auto         n_nodes       = positions.size() / dim;
    unsigned long long matched_nodes = 0, matched_cells = 0, differing = 0,
                       not_float = 0, n_values = 0;
    std::vector<std::vector<double>> values;
    for (const auto &field : fields)
      values.push_back(
        file.open_dataset(field.name).template read<std::vector<double>>());
    const auto displaced =
      file.open_dataset("displaced_nodes").template read<std::vector<double>>();
    for (unsigned int n = 0; n < n_nodes; ++n)
      {
        Key<dim> k;
        for (unsigned int d = 0; d < dim; ++d)
          k[d] = positions[n * dim + d];
        const auto node = nodes.find(k);
        if (node == nodes.end())
          continue;
        ++matched_nodes;
        for (unsigned int f = 0; f < fields.size(); ++f)
          for (unsigned int c = 0; c < dim; ++c)
            {
              const double expected = (*fields[f].values)[node->second[c]];
              const double read     = values[f][n * dim + c];
              differing += !same_bits(read, expected);
              not_float +=
                (static_cast<double>(static_cast<float>(expected)) != expected);
              ++n_values;
              if (fields[f].name == "displacement")
                differing +=
                  !same_bits(displaced[n * dim + c], k[c] + expected);
            }
      }
    for (unsigned int i = 0; i < connectivity.size() / n_vertices; ++i)
      {
        std::vector<double> corners;
        for (unsigned int v = 0; v < n_vertices; ++v)
          for (unsigned int d = 0; d < dim; ++d)
            corners.push_back(
              connectivity[i * n_vertices + v] < n_nodes ?
                positions[connectivity[i * n_vertices + v] * dim + d] :
                -1e300);
        matched_cells += cells.count(corners);
      }
    const auto sum = [comm](const unsigned long long v) {
      return Utilities::MPI::sum(v, comm);
    };
    const auto &tria = dof_handler.get_triangulation();
    out() << "  " << h5 << ": " << n_nodes << " nodes (degrees of freedom / "
          << dim << ": " << dof_handler.n_dofs() / dim << "), "
          << connectivity.size() / n_vertices
          << " cells (active cells: " << tria.n_global_active_cells() << ")\n"
          << "  rows matching an owned node: " << sum(matched_nodes)
          << ", a cell of the mesh: " << sum(matched_cells) << "\n"
          << "  values compared: " << sum(n_values)
          << ", not representable as float: "
          << (sum(not_float) > sum(n_values) / 2 ? "most" : "few")
          << ", differing bits: " << sum(differing) << "\n";
  }

  void
  check_xdmf(const std::string &file, const std::vector<std::string> &names)
  {
    std::ifstream      in(file);
    std::ostringstream text;
    text << in.rdbuf();
    const std::string xdmf  = text.str();
    unsigned int      grids = 0;
    for (std::size_t p = xdmf.find("GridType=\"Uniform\"");
         p != std::string::npos;
         p = xdmf.find("GridType=\"Uniform\"", p + 1))
      ++grids;
    out() << "  " << file << ": " << grids << " grids, temporal: "
          << (xdmf.find("CollectionType=\"Temporal\"") != std::string::npos)
          << ", names";
    for (const std::string &name : names)
      out() << " " << name << ": "
            << (xdmf.find(name) != std::string::npos ? "yes" : "no");
    out() << "\n";
  }

  template <int dim>
  void
  test(const CellType cell_type, const std::string &stem)
  {
    GeometryParameters geometry;
    geometry.mesh_type          = MeshType::rectangle;
    geometry.cell_type          = cell_type;
    geometry.lower_left         = std::vector<double>(dim, 0.);
    geometry.upper_right        = std::vector<double>(dim, 1.);
    geometry.upper_right[0]     = 2;
    geometry.subdivisions       = std::vector<unsigned int>(dim, 2);
    geometry.subdivisions[0]    = 4;
    geometry.global_refinements = cell_type == CellType::simplex ? 0 : 2;
    Discretization<dim> discretization(geometry, MPI_COMM_WORLD);
    discretization.make_mesh(geometry);
    Triangulation<dim> &tria = *discretization.triangulation;
    if (cell_type == CellType::hypercube)
      {
        // hanging nodes: the cells left of x = 0.6 once more
        for (const auto &cell : tria.active_cell_iterators())
          if (cell->is_locally_owned() && cell->center()[0] < 0.6)
            cell->set_refine_flag();
        tria.execute_coarsening_and_refinement();
      }
    DoFHandler<dim> dof_handler(tria);
    dof_handler.distribute_dofs(*discretization.fe);

    const IndexSet relevant =
      DoFTools::extract_locally_relevant_dofs(dof_handler);
    std::vector<TrilinosWrappers::MPI::Vector> vectors;
    for (unsigned int f = 0; f < 3; ++f)
      {
        TrilinosWrappers::MPI::Vector v(dof_handler.locally_owned_dofs(),
                                        MPI_COMM_WORLD);
        VectorTools::interpolate(*discretization.mapping,
                                 dof_handler,
                                 FieldValues<dim>(f),
                                 v);
        vectors.emplace_back(dof_handler.locally_owned_dofs(),
                             relevant,
                             MPI_COMM_WORLD);
        vectors.back() = v;
      }
    // the contact traction unghosted, as the writer is given either
    TrilinosWrappers::MPI::Vector traction(dof_handler.locally_owned_dofs(),
                                           MPI_COMM_WORLD);
    traction                                                       = vectors[2];
    const std::vector<typename NodalHdf5Writer<dim>::Field> fields = {
      {"velocity", &vectors[0]},
      {"displacement", &vectors[1]},
      {"contact_traction", &traction}};

    out() << dim << "D "
          << (cell_type == CellType::simplex ? "simplex" : "hypercube")
          << ":\n";
    NodalHdf5Writer<dim> writer(".", stem, MPI_COMM_WORLD);
    for (unsigned int step = 0; step < 3; ++step)
      writer.write(dof_handler, fields, step, 0.1 * step, "displacement");
    check(dof_handler, writer.file_name(2), fields);
    check_xdmf(writer.xdmf_file_name(),
               {stem + "_00000.h5:/nodes",
                stem + "_00002.h5:/cells",
                stem + "_00002.h5:/velocity",
                stem + "_00002.h5:/displacement",
                stem + "_00002.h5:/contact_traction",
                stem + "_00002.h5:/displaced_nodes"});
    // a resume at step 1 that writes step 2 again: three grids, not four
    writer.keep_steps_up_to(1);
    writer.write(dof_handler, fields, 2, 0.2, "displacement");
    check_xdmf(writer.xdmf_file_name(), {stem + "_00001.h5:/nodes"});

    // a directory that is not there: named on every rank
    NodalHdf5Writer<dim> nowhere("missing_directory", stem, MPI_COMM_WORLD);
    try
      {
        nowhere.write(dof_handler, fields, 0, 0.);
        out() << "  missing directory: written\n";
      }
    catch (const OutputError &e)
      {
        out() << "  missing directory: " << e.what() << "\n";
      }

    // the first nodes and cells, the same on any number of ranks where the
    // numbering of the degrees of freedom is (p4est)
    if (cell_type == CellType::hypercube)
      {
        HDF5::File file(writer.file_name(0),
                        HDF5::File::FileAccessMode::open,
                        MPI_COMM_WORLD);
        const auto nodes =
          file.open_dataset("nodes").template read<std::vector<double>>();
        const auto cells =
          file.open_dataset("cells").template read<std::vector<unsigned int>>();
        out() << "  first nodes:";
        for (unsigned int n = 0; n < 6; ++n)
          out() << " (" << nodes[n * dim] << ", " << nodes[n * dim + 1] << ")";
        out() << "\n  first cells:";
        for (unsigned int c = 0; c < 3; ++c)
          out() << " (" << cells[4 * c] << " " << cells[4 * c + 1] << " "
                << cells[4 * c + 2] << " " << cells[4 * c + 3] << ")";
        out() << "\n";
      }
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  test<2>(CellType::hypercube, "quad");
  test<3>(CellType::simplex, "tet");
}
