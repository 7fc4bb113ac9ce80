#include <deal.II/base/exceptions.h>
#include <deal.II/base/hdf5.h>
#include <deal.II/base/index_set.h>
#include <deal.II/base/utilities.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe.h>

#include <hemicontact/output/nodal_hdf5_writer.h>
#include <hemicontact/output/output_file.h>

#include <algorithm>
#include <array>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iterator>
#include <map>
#include <regex>
#include <sstream>

namespace hemicontact
{
  namespace
  {
    /** The sum of @p value over the ranks before this one, and the total. */
    std::pair<unsigned long long, unsigned long long>
    offset_and_total(const unsigned long long value, MPI_Comm comm)
    {
      unsigned long long offset = 0, total = 0;
      MPI_Exscan(&value, &offset, 1, MPI_UNSIGNED_LONG_LONG, MPI_SUM, comm);
      if (Utilities::MPI::this_mpi_process(comm) == 0)
        offset = 0; // MPI_Exscan leaves it undefined on rank 0
      MPI_Allreduce(&value, &total, 1, MPI_UNSIGNED_LONG_LONG, MPI_SUM, comm);
      return {offset, total};
    }

    /**
     * Create the dataset @p name of @p n_rows x @p n_columns in @p file and
     * write this rank's @p data (rows from @p row_offset on), collectively.
     */
    template <typename number>
    void
    write_rows(HDF5::File                &file,
               const std::string         &name,
               const std::vector<number> &data,
               const hsize_t              n_columns,
               const hsize_t              row_offset,
               const hsize_t              n_rows)
    {
      HDF5::DataSet dataset =
        file.create_dataset<number>(name, {n_rows, n_columns});
      const hsize_t n_local_rows = data.size() / n_columns;
      if (n_local_rows > 0)
        dataset.write_hyperslab(data,
                                {row_offset, 0},
                                {n_local_rows, n_columns});
      else
        dataset.write_none<number>();
    }

    /** An XDMF DataItem naming the dataset @p name of the file @p h5. */
    std::string
    data_item(const std::string       &h5,
              const std::string       &name,
              const unsigned long long n_rows,
              const unsigned int       n_columns,
              const bool               floating)
    {
      std::ostringstream item;
      item << "<DataItem Dimensions=\"" << n_rows << " " << n_columns
           << "\" NumberType=\"" << (floating ? "Float" : "UInt")
           << "\" Precision=\"" << (floating ? 8 : 4) << "\" Format=\"HDF\">"
           << h5 << ":/" << name << "</DataItem>";
      return item.str();
    }
  } // namespace



  template <int dim>
  NodalHdf5Writer<dim>::NodalHdf5Writer(const std::string &directory,
                                        const std::string &stem,
                                        MPI_Comm           mpi_communicator)
    : directory(directory)
    , stem(stem)
    , mpi_communicator(mpi_communicator)
  {}



  template <int dim>
  std::string
  NodalHdf5Writer<dim>::file_name(const unsigned int step) const
  {
    return stem + "_" + Utilities::int_to_string(step, 5) + ".h5";
  }



  template <int dim>
  std::string
  NodalHdf5Writer<dim>::xdmf_file_name() const
  {
    return stem + ".xdmf";
  }



  template <int dim>
  void
  NodalHdf5Writer<dim>::keep_steps_up_to(const unsigned int step)
  {
    entries.erase(std::remove_if(entries.begin(),
                                 entries.end(),
                                 [step](const Entry &entry) {
                                   return entry.step > step;
                                 }),
                  entries.end());
  }



  template <int dim>
  void
  NodalHdf5Writer<dim>::read_collection()
  {
    // the collection as xdmf_content() writes it: one grid a step, whose
    // first data item names the step's file STEM_NNNNN.h5
    entries.clear();
    std::ifstream file(directory + "/" + xdmf_file_name());
    if (!file)
      return;
    const std::string text((std::istreambuf_iterator<char>(file)),
                           std::istreambuf_iterator<char>());
    const std::string begin =
      "      <Grid Name=\"" + stem + "\" GridType=\"Uniform\">";
    const std::string end = "      </Grid>\n";
    const std::regex  time("<Time Value=\"([^\"]+)\"");
    const std::regex  step(stem + "_([0-9]+)\\.h5");
    for (std::size_t start = text.find(begin); start != std::string::npos;
         start             = text.find(begin, start))
      {
                    const std::size_t stop = text.find(end, start);
                    if (stop == std::string::npos)
          break;
        const std::string grid = text.substr(start, stop + end.size() - start);
                    std::smatch       t, s;
                    if (std::regex_search(grid, t, time) &&
            std::regex_search(grid, s, step))
          entries.push_back({static_cast<unsigned int>(std::stoul(s[1])),
                                         std::stod(t[1]),
                                         grid});
        start = stop;
      }
  }

  template <int dim>
  std::string
  NodalHdf5Writer<dim>::xdmf_content() const
  {
    std::ostringstream xdmf;
    xdmf << "<?xml version=\"1.0\" ?>\n"
         << "<!DOCTYPE Xdmf SYSTEM \"Xdmf.dtd\" []>\n"
         << "<Xdmf Version=\"2.0\">\n"
         << "  <Domain>\n"
         << "    <Grid Name=\"" << stem
         << "\" GridType=\"Collection\" CollectionType=\"Temporal\">\n";
    for (const Entry &entry : entries)
      xdmf << entry.grid;
    xdmf << "    </Grid>\n  </Domain>\n</Xdmf>\n";
    return xdmf.str();
  }



  template <int dim>
  std::string
  NodalHdf5Writer<dim>::write(const DoFHandler<dim>    &dof_handler,
                              const std::vector<Field> &fields,
                              const unsigned int        step,
                              const double              time,
                              const std::string        &displacement)
  {
    // a P1/Q1 vector element: dim copies of one element with one degree of
    // freedom per vertex and none elsewhere
    const FiniteElement<dim> &fe = dof_handler.get_fe();
    AssertThrow(fe.n_components() == dim && fe.n_base_elements() == 1 &&
                  fe.element_multiplicity(0) == dim,
                ExcMessage("NodalHdf5Writer needs an FESystem of dim copies "
                           "of one scalar element."));
    const ReferenceCell reference_cell = fe.reference_cell();
    const unsigned int  n_vertices     = reference_cell.n_vertices();
    const unsigned int  n_columns      = n_vertices;
    AssertThrow(fe.base_element(0).n_dofs_per_vertex() == 1 &&
                  fe.base_element(0).n_dofs_per_cell() == n_vertices,
                ExcMessage("NodalHdf5Writer needs a P1/Q1 element."));
    AssertThrow(!dof_handler.has_hp_capabilities(),
                ExcMessage("NodalHdf5Writer needs one finite element."));

    // the cell's vertices in XDMF/VTK order, and the XDMF topology
    std::vector<unsigned int> vertex_order(n_vertices);
    for (unsigned int v = 0; v < n_vertices; ++v)
      vertex_order[v] = v;
    std::string topology;
    if (reference_cell == ReferenceCells::Quadrilateral)
      vertex_order = {0, 1, 3, 2}, topology = "Quadrilateral";
    else if (reference_cell == ReferenceCells::Hexahedron)
      vertex_order = {0, 1, 3, 2, 4, 5, 7, 6}, topology = "Hexahedron";
    else if (reference_cell == ReferenceCells::Triangle)
      topology = "Triangle";
    else if (reference_cell == ReferenceCells::Tetrahedron)
      topology = "Tetrahedron";
    else
      AssertThrow(false, ExcMessage("NodalHdf5Writer: unsupported cell type."));

    // the fields: distinct names that are not those of the mesh datasets
    const Field *displacement_field = nullptr;
    for (const Field &field : fields)
      {
        AssertThrow(field.values != nullptr &&
                      field.values->size() == dof_handler.n_dofs(),
                    ExcMessage("NodalHdf5Writer: the field '" + field.name +
                               "' is not a vector on the DoFHandler."));
        AssertThrow(!field.name.empty() &&
                      field.name.find_first_of("/:<>\"& ") ==
                        std::string::npos &&
                      field.name != "nodes" && field.name != "cells" &&
                      field.name != "displaced_nodes" &&
                      std::count_if(fields.begin(),
                                    fields.end(),
                                    [&field](const Field &other) {
                                      return other.name == field.name;
                                    }) == 1,
                    ExcMessage("NodalHdf5Writer: the field name '" +
                               field.name + "' is not usable."));
        if (field.name == displacement)
          displacement_field = &field;
      }
    AssertThrow(displacement.empty() || displacement_field != nullptr,
                ExcMessage("NodalHdf5Writer: no field named '" + displacement +
                           "'."));

    // the nodes this rank owns, by the degree of freedom of their first
    // component: their position and their dim degrees of freedom
    const IndexSet &owned = dof_handler.locally_owned_dofs();
    std::map<types::global_dof_index,
             std::pair<Point<dim>, std::array<types::global_dof_index, dim>>>
                                         owned_nodes;
    std::vector<types::global_dof_index> cell_dofs(fe.n_dofs_per_cell());
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (!cell->is_artificial())
        {
          cell->get_dof_indices(cell_dofs);
          for (unsigned int v = 0; v < n_vertices; ++v)
            {
              std::array<types::global_dof_index, dim> dofs;
              for (unsigned int c = 0; c < dim; ++c)
                dofs[c] = cell_dofs[fe.component_to_system_index(c, v)];
              if (owned.is_element(dofs[0]))
                owned_nodes.emplace(dofs[0],
                                    std::make_pair(cell->vertex(v), dofs));
            }
        }
    AssertThrow(owned_nodes.size() * dim == owned.n_elements(),
                ExcMessage("NodalHdf5Writer: the degrees of freedom this "
                           "rank owns are not those of whole nodes."));

    const auto [node_offset, n_nodes] =
      offset_and_total(owned_nodes.size(), mpi_communicator);
    AssertThrow(n_nodes < (1ULL << 32),
                ExcMessage("NodalHdf5Writer: more nodes than 32-bit "
                           "indices number."));

    // the index of every node a locally owned cell touches, from its owner
    const IndexSet relevant =
      DoFTools::extract_locally_relevant_dofs(dof_handler);
    TrilinosWrappers::MPI::Vector node_index(owned, mpi_communicator);
    {
      unsigned long long n = node_offset;
      for (const auto &node : owned_nodes)
        node_index[node.first] = n++;
      node_index.compress(VectorOperation::insert);
    }
    TrilinosWrappers::MPI::Vector ghosted_index(owned,
                                                relevant,
                                                mpi_communicator);
    ghosted_index = node_index;

    std::vector<unsigned int> cells;
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          cell->get_dof_indices(cell_dofs);
          for (const unsigned int v : vertex_order)
            cells.push_back(static_cast<unsigned int>(
              ghosted_index[cell_dofs[fe.component_to_system_index(0, v)]]));
        }
    const auto [cell_offset, n_cells] =
      offset_and_total(cells.size() / n_columns, mpi_communicator);

    // the rows of this rank, in double precision
    std::vector<double> positions;
    positions.reserve(owned_nodes.size() * dim);
    for (const auto &node : owned_nodes)
      for (unsigned int d = 0; d < dim; ++d)
        positions.push_back(node.second.first[d]);
    const auto rows = [&owned_nodes](const TrilinosWrappers::MPI::Vector &v) {
      std::vector<double> values;
      values.reserve(owned_nodes.size() * dim);
      for (const auto &node : owned_nodes)
        for (unsigned int c = 0; c < dim; ++c)
          values.push_back(v[node.second.second[c]]);
      return values;
    };

    // the file, written by all ranks; deal.II's HDF5 classes check the
    // library's return codes in debug mode only, so the root checks the
    // directory and its free space before and the file's size after
    const std::string h5   = file_name(step);
    const std::string path = directory + "/" + h5;
    const bool root = Utilities::MPI::this_mpi_process(mpi_communicator) == 0;
    const std::uintmax_t payload =
      n_nodes * dim * sizeof(double) *
        (1 + fields.size() + (displacement_field != nullptr ? 1 : 0)) +
      n_cells * n_columns * sizeof(unsigned int);
    const std::string prefix = "cannot write '" + path + "': ";
    std::string       error;
    if (root)
      {
        std::error_code ec;
        if (!std::filesystem::is_directory(directory, ec))
          error = prefix + "'" + directory + "' is not a directory.";
        else
          {
            const std::string shortfall =
              free_space_shortfall(directory, payload + (1 << 16));
            if (!shortfall.empty())
              error = prefix + shortfall + ".";
          }
      }
    throw_if_any(error, mpi_communicator);
    {
      HDF5::File file(path,
                      HDF5::File::FileAccessMode::create,
                      mpi_communicator);
      file.set_attribute("step", step);
      file.set_attribute("time", time);
      write_rows(file, "nodes", positions, dim, node_offset, n_nodes);
      write_rows(file, "cells", cells, n_columns, cell_offset, n_cells);
      for (const Field &field : fields)
        write_rows(
          file, field.name, rows(*field.values), dim, node_offset, n_nodes);
      if (displacement_field != nullptr)
        {
          std::vector<double> displaced = rows(*displacement_field->values);
          for (unsigned int i = 0; i < displaced.size(); ++i)
            displaced[i] += positions[i];
          write_rows(
            file, "displaced_nodes", displaced, dim, node_offset, n_nodes);
        }
    }
    if (root)
      {
        std::error_code      ec;
        const std::uintmax_t size = std::filesystem::file_size(path, ec);
        if (ec || size < payload)
          error = prefix + "the file is missing or shorter than its data.";
      }
    throw_if_any(error, mpi_communicator);

    // its grid in the collection
    std::ostringstream grid;
    grid << std::setprecision(17);
    grid << "      <Grid Name=\"" << stem << "\" GridType=\"Uniform\">\n"
         << "        <Time Value=\"" << time << "\"/>\n"
         << "        <Geometry GeometryType=\"" << (dim == 2 ? "XY" : "XYZ")
         << "\">\n"
         << "          " << data_item(h5, "nodes", n_nodes, dim, true) << "\n"
         << "        </Geometry>\n"
         << "        <Topology TopologyType=\"" << topology
         << "\" NumberOfElements=\"" << n_cells << "\">\n"
         << "          " << data_item(h5, "cells", n_cells, n_columns, false)
         << "\n"
         << "        </Topology>\n";
    // ParaView takes a "Vector" to have 3 components; in 2D the fields are
    // given as 2-component arrays
    const std::string        type = dim == 3 ? "Vector" : "Matrix";
    std::vector<std::string> names;
    for (const Field &field : fields)
      names.push_back(field.name);
    if (displacement_field != nullptr)
      names.emplace_back("displaced_nodes");
    for (const std::string &name : names)
      grid << "        <Attribute Name=\"" << name << "\" AttributeType=\""
           << type << "\" Center=\"Node\">\n"
           << "          " << data_item(h5, name, n_nodes, dim, true) << "\n"
           << "        </Attribute>\n";
    grid << "      </Grid>\n";

    keep_steps_up_to(step);
    if (!entries.empty() && entries.back().step == step)
      entries.pop_back();
    entries.push_back({step, time, grid.str()});

    if (root)
      error =
        write_atomically(directory + "/" + xdmf_file_name(), xdmf_content());
    try
      {
        throw_if_any(error, mpi_communicator);
      }
    catch (...)
      {
        entries.pop_back();
        throw;
      }
    return h5;
  }



  template class NodalHdf5Writer<2>;
  template class NodalHdf5Writer<3>;
} // namespace hemicontact
