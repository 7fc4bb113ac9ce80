#pragma once

#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature.h>
#include <deal.II/fe/fe.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/grid/tria.h>

#include <hemicontact/input/parameters.h>

#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace hemicontact
{
  using namespace dealii;

  /**
   * The spatial discretisation: the mesh, the P1/Q1 vector element, its
   * mapping and quadratures. 'hypercube' gives FE_Q(1)^d on a p4est
   * parallel::distributed::Triangulation; 'simplex' gives FE_SimplexP(1)^d
   * on a parallel::fullydistributed::Triangulation (each rank stores its
   * cells and one layer of ghosts). The rest of the program sees only the
   * base classes, so it is not tied to either.
   */
  template <int dim>
  class Discretization
  {
  public:
    Discretization(const GeometryParameters &geometry, MPI_Comm comm);

    /**
     * Build the mesh: the coarse mesh refined globally (hypercubes: the
     * p4est forest; simplices: built whole on every rank, partitioned, and
     * each rank keeps its part). A Gmsh file is checked first
     * (read_checked_gmsh()); 'global refinements' whose mesh would not fit
     * into the machine's memory are refused (InputError).
     */
    void
    make_mesh(const GeometryParameters &geometry, const bool refine = true);

    /**
     * Check that every boundary id named in @p boundary exists on the mesh
     * (InputError otherwise).
     */
    void
    check_boundary_ids(const BoundaryParameters &boundary) const;

    /**
     * The rule of the one above for any entries: each id of each entry
     * (its name, its ids) of the subsection @p subsection exists on the
     * mesh; else an InputError naming the entry, the id and the mesh's ids.
     */
    void
    check_boundary_ids(
      const std::string &subsection,
      const std::vector<std::pair<std::string, std::vector<unsigned int>>>
        &entries) const;

    bool
    is_simplex() const
    {
      return simplex;
    }

    /** A quadrature of @p n_points per direction (Gauss / Gauss simplex). */
    Quadrature<dim>
    cell_quadrature(const unsigned int n_points) const;

    /** The same on faces. */
    Quadrature<dim - 1>
    face_quadrature(const unsigned int n_points) const;

    MPI_Comm                            mpi_communicator;
    std::unique_ptr<Triangulation<dim>> triangulation;
    std::unique_ptr<FiniteElement<dim>> fe;
    std::unique_ptr<Mapping<dim>>       mapping;

  private:
    /** The rectangle/box or the Gmsh mesh of @p geometry in @p mesh. */
    void
    build_mesh(Triangulation<dim>       &mesh,
               const GeometryParameters &geometry,
               const bool                refine) const;

    /**
     * Read the Gmsh file of @p geometry into @p mesh after checking it
     * (InputError naming the file): a regular file, one cell type matching
     * 'cell type', in 2D all nodes in z = 0, no duplicated nodes, no
     * self-intersecting or inverted cells.
     */
    void
    read_checked_gmsh(Triangulation<dim>       &mesh,
                      const GeometryParameters &geometry) const;

    bool simplex;
  };
} // namespace hemicontact
