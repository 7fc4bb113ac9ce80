#include <deal.II/base/quadrature_lib.h>
#include <deal.II/distributed/fully_distributed_tria.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_simplex_p.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping_fe.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_in.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/tria_description.h>

#include <hemicontact/discretization.h>
#include <hemicontact/input_error.h>

#include <fstream>
#include <set>
#include <sstream>

namespace hemicontact
{
  namespace
  {
    /**
     * Whether the Gmsh file read by @p file says in its $MeshFormat
     * section that it is binary (file-type 1); rewinds the stream.
     */
    bool
    gmsh_file_is_binary(std::ifstream &file)
    {
      std::string section, version;
      int         file_type = 0;
      file >> section >> version >> file_type;
      const bool binary = section == "$MeshFormat" && file_type == 1;
      file.clear();
      file.seekg(0);
      return binary;
    }
  } // namespace

  template <int dim>
  Discretization<dim>::Discretization(const GeometryParameters &geometry,
                                      MPI_Comm                  comm)
    : mpi_communicator(comm)
    , simplex(geometry.cell_type == "simplex")
  {
    if (simplex)
      {
        triangulation =
          std::make_unique<parallel::fullydistributed::Triangulation<dim>>(
            comm);
        fe = std::make_unique<FESystem<dim>>(FE_SimplexP<dim>(1), dim);
        mapping = std::make_unique<MappingFE<dim>>(FE_SimplexP<dim>(1));
      }
    else
      {
        // Only the smoothing that p4est's 2:1 (face and corner) balance
        // enforces globally anyway: the other smoothing rules (e.g.
        // eliminate_unrefined_islands) are applied by each rank to its own
        // cells with the flags of one ghost layer, so chains of them stop at
        // partition boundaries and the mesh would depend on the number of
        // ranks (doc/adaptivity.md).
        triangulation =
          std::make_unique<parallel::distributed::Triangulation<dim>>(
            comm, Triangulation<dim>::limit_level_difference_at_vertices);
        fe      = std::make_unique<FESystem<dim>>(FE_Q<dim>(1), dim);
        mapping = std::make_unique<MappingQ<dim>>(1);
      }
  }

  template <int dim>
  void
  Discretization<dim>::make_mesh(const GeometryParameters &geometry,
                                 const bool                refine)
  {
    if (!simplex)
      {
        build_mesh(*triangulation, geometry, refine);
        return;
      }
    // every rank builds the whole mesh, partitions it the same way (METIS)
    // and keeps only its cells and a layer of ghosts
    Triangulation<dim> whole;
    build_mesh(whole, geometry, refine);
    GridTools::partition_triangulation(
      Utilities::MPI::n_mpi_processes(mpi_communicator), whole);
    triangulation->create_triangulation(
      TriangulationDescription::Utilities::create_description_from_triangulation(
        whole, mpi_communicator));
  }

  template <int dim>
  void
  Discretization<dim>::build_mesh(Triangulation<dim> &       mesh,
                                  const GeometryParameters &geometry,
                                  const bool                refine) const
  {
    unsigned int refinements = geometry.global_refinements;
    if (geometry.mesh_type == "rectangle")
      {
        Point<dim>                p0, p1;
        std::vector<unsigned int> repetitions(dim);
        for (unsigned int d = 0; d < dim; ++d)
          {
            p0[d]          = geometry.lower_left[d];
            p1[d]          = geometry.upper_right[d];
            repetitions[d] = geometry.subdivisions[d];
          }
        if (simplex)
          {
            // Refining tetrahedra in deal.II 9.4 degrades their shape (the
            // largest diameter shrinks by ~2/3 per level, not 1/2), so the
            // refined levels of a simplex box are built directly from a
            // 2^r times finer subdivision: a uniform family with fixed
            // shape regularity and h halving per level.
            for (unsigned int &r : repetitions)
              r <<= geometry.global_refinements;
            refinements = 0;
            // deal.II 9.4 does not colorize simplex rectangles: set the ids
            // 2d (lower) and 2d+1 (upper) from the face centres
            GridGenerator::subdivided_hyper_rectangle_with_simplices(
              mesh, repetitions, p0, p1, /*colorize=*/false);
            const double tolerance = 1e-10 * (p1 - p0).norm();
            for (const auto &cell : mesh.active_cell_iterators())
              for (const auto &face : cell->face_iterators())
                if (face->at_boundary())
                  for (unsigned int d = 0; d < dim; ++d)
                    {
                      if (std::abs(face->center()[d] - p0[d]) < tolerance)
                        face->set_boundary_id(2 * d);
                      if (std::abs(face->center()[d] - p1[d]) < tolerance)
                        face->set_boundary_id(2 * d + 1);
                    }
          }
        else
          GridGenerator::subdivided_hyper_rectangle(mesh,
                                                    repetitions, p0, p1,
                                                    /*colorize=*/true);
      }
    else
      {
        std::ifstream file(geometry.mesh_file);
        require(static_cast<bool>(file),
                "geometry: cannot open the mesh file '" + geometry.mesh_file +
                  "' (no such file or not readable).");
        GridIn<dim> grid_in;
        grid_in.attach_triangulation(mesh);
        try
          {
            // MSH 2.2 and 4.1 in ASCII: deal.II's own reader, which takes
            // every physical tag (named or not) as the boundary id. Binary
            // files: the Gmsh library's reader (deal.II 9.4 assigns it
            // boundary ids of named physical groups only).
            if (gmsh_file_is_binary(file))
              grid_in.read_msh(geometry.mesh_file);
            else
              grid_in.read_msh(file);
          }
        catch (const ExceptionBase &e)
          {
            std::ostringstream s;
            e.print_info(s);
            throw InputError("geometry: cannot read the Gmsh file '" +
                             geometry.mesh_file + "': " + s.str());
          }
        catch (const std::string &gmsh_message)
          {
            throw InputError("geometry: cannot read the Gmsh file '" +
                             geometry.mesh_file + "': " + gmsh_message);
          }
        const bool all_hypercubes =
          mesh.all_reference_cells_are_hyper_cube();
        require(all_hypercubes != simplex,
                "geometry: the mesh file '" + geometry.mesh_file +
                  "' holds " +
                  (all_hypercubes ? std::string("quadrilaterals/hexahedra") :
                                    std::string("triangles/tetrahedra")) +
                  " but 'cell type' = " + geometry.cell_type + ".");
      }
    if (refine)
      mesh.refine_global(refinements);
  }

  template <int dim>
  void
  Discretization<dim>::check_boundary_ids(
    const BoundaryParameters &boundary) const
  {
    const std::vector<types::boundary_id> present_ids =
      Utilities::MPI::compute_set_union(triangulation->get_boundary_ids(),
                                        mpi_communicator);
    const std::set<types::boundary_id> present(present_ids.begin(),
                                               present_ids.end());
    std::string present_list;
    for (const auto id : present)
      present_list += (present_list.empty() ? "" : ", ") + std::to_string(id);

    const auto check = [&](const std::vector<unsigned int> &ids,
                           const std::string &           name) {
      for (const unsigned int id : ids)
        require(present.count(id) == 1,
                "boundary: '" + name + "' names boundary id " +
                  std::to_string(id) +
                  ", which the mesh does not have (its boundary ids are " +
                  present_list + ").");
    };
    check(boundary.clamped_ids, "clamped boundary ids");
    check(boundary.traction_ids, "traction boundary ids");
    check(boundary.contact_ids, "contact boundary ids");
  }

  template <int dim>
  Quadrature<dim>
  Discretization<dim>::cell_quadrature(const unsigned int n_points) const
  {
    if (simplex)
      return QGaussSimplex<dim>(n_points);
    return QGauss<dim>(n_points);
  }

  template <int dim>
  Quadrature<dim - 1>
  Discretization<dim>::face_quadrature(const unsigned int n_points) const
  {
    if (simplex)
      return QGaussSimplex<dim - 1>(n_points);
    return QGauss<dim - 1>(n_points);
  }

  template class Discretization<2>;
  template class Discretization<3>;
} // namespace hemicontact
