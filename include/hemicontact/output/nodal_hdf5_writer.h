#pragma once

#include <deal.II/base/mpi.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/lac/trilinos_vector.h>

#include <string>
#include <vector>

namespace hemicontact
{
  using namespace dealii;

  /**
   * The nodal fields of a run in double precision (doc/outputs.md,
   * "Double-precision nodal files"): for each output time one HDF5 file
   * STEM_NNNNN.h5, written by all ranks at once (parallel HDF5), holding
   * - `nodes`: the reference position of every node, N x dim doubles;
   * - `cells`: the node indices of every active cell, M x 4 (quadrilaterals),
   *   8 (hexahedra), 3 (triangles) or 4 (tetrahedra), in VTK/XDMF order;
   * - one N x dim double dataset per named field, bit for bit the entries of
   *   its vector;
   * - `displaced_nodes`: x + u, if a displacement field is named;
   * - the attributes `step` and `time` of the file;
   * and the temporal collection STEM.xdmf over the files written so far,
   * rewritten atomically after each file, which ParaView opens.
   *
   * A node is a vertex of the mesh with its dim degrees of freedom (P1/Q1
   * FESystem, one base element with dim components); a hanging node is a
   * node like any other, its values those of the vector. Nodes are numbered
   * in the order of their first component's degree of freedom; each rank
   * writes the rows of the nodes it owns, and the rows of its locally owned
   * cells in the order of the triangulation. Neither depends on the number
   * of ranks where the DoFHandler's numbering and the cell order do not
   * (p4est meshes).
   */
  template <int dim>
  class NodalHdf5Writer
  {
  public:
    /** A named nodal field: a vector on the DoFHandler given to write(). */
    struct Field
    {
      std::string                          name;
      const TrilinosWrappers::MPI::Vector *values;
    };

    /**
     * Write into @p directory the files STEM_NNNNN.h5 and STEM.xdmf with
     * STEM = @p stem, on the ranks of @p mpi_communicator.
     */
    NodalHdf5Writer(const std::string &directory,
                    const std::string &stem,
                    MPI_Comm           mpi_communicator);

    /**
     * Write the file of @p step at @p time with the mesh of @p dof_handler
     * and @p fields, and rewrite the XDMF collection with it. Collective.
     * With @p displacement the name of one of @p fields, the displaced
     * positions x + u are written as well. Throws an OutputError on every
     * rank, naming the file, if the directory is missing, has too little
     * free space, or a file is not written completely (the collection then
     * stays as it was). Returns the name of the HDF5 file (without the
     * directory).
     */
    std::string
    write(const DoFHandler<dim>    &dof_handler,
          const std::vector<Field> &fields,
          unsigned int              step,
          double                    time,
          const std::string        &displacement = "");

    /** The name of the HDF5 file of @p step: STEM_NNNNN.h5. */
    std::string
    file_name(unsigned int step) const;

    /** The name of the XDMF collection: STEM.xdmf. */
    std::string
    xdmf_file_name() const;

    /**
     * Forget the files of steps after @p step (a run resumed at @p step):
     * the next write() lists only the files up to it and its own.
     */
    void
    keep_steps_up_to(unsigned int step);

    /**
     * Take the files listed by the XDMF collection in the directory (a
     * resumed run continues it); nothing if there is none.
     */
    void
    read_collection();

    /** The XDMF collection as write() writes it. */
    std::string
    xdmf_content() const;

  private:
    /** One file of the collection: its step, time and XDMF grid. */
    struct Entry
    {
      unsigned int step;
      double       time;
      std::string  grid;
    };

    std::string        directory;
    std::string        stem;
    MPI_Comm           mpi_communicator;
    std::vector<Entry> entries;
  };
} // namespace hemicontact
