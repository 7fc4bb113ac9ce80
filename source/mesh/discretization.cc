#include <deal.II/base/bounding_box.h>
#include <deal.II/base/geometry_info.h>
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

#include <hemicontact/base/exceptions.h>
#include <hemicontact/mesh/discretization.h>

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iomanip>
#include <map>
#include <set>
#include <sstream>

namespace hemicontact
{
  namespace
  {
    /** Estimated peak memory per degree of freedom (doc/performance.md). */
    double
    bytes_per_dof(const unsigned int dim)
    {
      return dim == 2 ? 2.5e3 : 9.0e3;
    }

    /** "(x, y[, z])" with 12 significant digits. */
    template <int spacedim>
    std::string
    to_text(const Point<spacedim> &p)
    {
      std::ostringstream s;
      s << std::setprecision(12) << '(';
      for (unsigned int d = 0; d < spacedim; ++d)
        s << (d == 0 ? "" : ", ") << p[d];
      s << ')';
      return s.str();
    }

    /** A byte count in MB, GB or TB, e.g. "3.4 GB". */
    std::string
    memory_text(const double bytes)
    {
      std::ostringstream s;
      s << std::setprecision(3);
      if (bytes >= 1e12)
        s << bytes / 1e12 << " TB";
      else if (bytes >= 1e9)
        s << bytes / 1e9 << " GB";
      else
        s << bytes / 1e6 << " MB";
      return s.str();
    }

    /**
     * The physical memory of the machines the ranks of @p comm run on (the
     * sum of each node's total memory).
     */
    double
    machine_memory(const MPI_Comm comm)
    {
      MPI_Comm node;
      MPI_Comm_split_type(comm, MPI_COMM_TYPE_SHARED, 0, MPI_INFO_NULL, &node);
      const bool node_root = Utilities::MPI::this_mpi_process(node) == 0;
      MPI_Comm_free(&node);
      const double local = node_root ?
                             static_cast<double>(sysconf(_SC_PHYS_PAGES)) *
                               static_cast<double>(sysconf(_SC_PAGESIZE)) :
                             0.;
      return Utilities::MPI::sum(local, comm);
    }

    /**
     * Refuse 'global refinements' = @p refinements when the mesh would not
     * fit into the memory of the machines of @p comm; @p n_dofs(r) is the
     * estimated number of degrees of freedom after r refinements.
     */
    template <int dim>
    void
    check_refinement_memory(const std::function<double(unsigned int)> &n_dofs,
                            const unsigned int refinements,
                            const MPI_Comm     comm)
    {
      const double available = machine_memory(comm);
      const auto   needed    = [&](const unsigned int r) {
        return n_dofs(r) * bytes_per_dof(dim);
      };
      if (needed(refinements) <= available)
        return;
      unsigned int fitting = refinements;
      while (fitting > 0 && needed(fitting) > available)
        --fitting;
      std::ostringstream s;
      s << std::setprecision(2)
        << "geometry: 'global refinements' = " << refinements << " gives about "
        << n_dofs(refinements) << " degrees of freedom, which need about "
        << memory_text(needed(refinements)) << " of memory (about "
        << bytes_per_dof(dim) / 1e3 << " kB per degree of freedom in " << dim
        << "D, doc/performance.md), but the machine has "
        << memory_text(available) << ". "
        << (needed(fitting) <= available ?
              "The most that fits is 'global refinements' = " +
                std::to_string(fitting) + "." :
              std::string("Even the coarse mesh does not fit: use fewer "
                          "cells."));
      throw InputError(s.str());
    }

    /** Refuse a mesh file that is missing or not a regular file. */
    void
    require_regular_file(const std::string &name)
    {
      std::error_code             error;
      const std::filesystem::path path(name);
      require(std::filesystem::exists(path, error),
              "geometry: cannot open the mesh file '" + name +
                "' (no such file or not readable).");
      require(std::filesystem::is_regular_file(path, error),
              "geometry: the mesh file '" + name +
                "' is not a regular file (a directory, a device or a pipe); "
                "'mesh file' names a Gmsh .msh file.");
    }

    /**
     * Whether the Gmsh file read by @p file says in its $MeshFormat
     * section that it is binary (file-type 1); rewinds the stream.
     */
    bool
    gmsh_file_is_binary(std::ifstream &file)
    {
      std::string section, version;
      int         file_type = 0;
      file >> std::setw(64) >> section >> std::setw(64) >> version >> file_type;
      const bool binary = section == "$MeshFormat" && file_type == 1;
      file.clear();
      file.seekg(0);
      return binary;
    }

    /**
     * Read the Gmsh file @p name into the empty serial @p mesh; every failure
     * is an InputError naming the file. MSH 2.2 and 4.1 in ASCII: deal.II's
     * own reader, which takes every physical tag (named or not) as the
     * boundary id. Binary files: the Gmsh library's reader (deal.II 9.4
     * assigns it boundary ids of named physical groups only).
     */
    template <int dim, int spacedim>
    void
    read_gmsh(Triangulation<dim, spacedim> &mesh, const std::string &name)
    {
      std::ifstream file(name);
      require(static_cast<bool>(file),
              "geometry: cannot open the mesh file '" + name +
                "' (no such file or not readable).");
      GridIn<dim, spacedim> grid_in;
      grid_in.attach_triangulation(mesh);
      const std::string prefix =
        "geometry: cannot read the Gmsh file '" + name + "': ";
      try
        {
          if (gmsh_file_is_binary(file))
            grid_in.read_msh(name);
          else
            grid_in.read_msh(file);
        }
      catch (const ExceptionBase &e)
        {
          std::ostringstream s;
          e.print_info(s);
          throw InputError(prefix + s.str());
        }
      catch (const std::string &gmsh_message)
        {
          throw InputError(prefix + gmsh_message);
        }
      catch (const std::bad_alloc &)
        {
          throw InputError(prefix + "it needs more memory than there is.");
        }
      catch (const std::exception &e)
        {
          throw InputError(prefix + e.what());
        }
    }

    /** The name of a cell type, e.g. "triangle". */
    std::string
    cell_name(const ReferenceCell &type)
    {
      const std::map<ReferenceCell, std::string> names = {
        {ReferenceCells::Line, "line"},
        {ReferenceCells::Triangle, "triangle"},
        {ReferenceCells::Quadrilateral, "quadrilateral"},
        {ReferenceCells::Tetrahedron, "tetrahedron"},
        {ReferenceCells::Pyramid, "pyramid"},
        {ReferenceCells::Wedge, "wedge"},
        {ReferenceCells::Hexahedron, "hexahedron"}};
      const auto name = names.find(type);
      return name == names.end() ? type.to_string() : name->second;
    }

    /** The plural of cell_name(), e.g. "hexahedra". */
    std::string
    cells_name(const ReferenceCell &type)
    {
      const std::string name = cell_name(type);
      return type == ReferenceCells::Hexahedron  ? "hexahedra" :
             type == ReferenceCells::Tetrahedron ? "tetrahedra" :
                                                   name + "s";
    }

    /**
     * Refuse a mesh whose cells are not all of the type that 'cell type'
     * asks for (quadrilaterals/hexahedra or triangles/tetrahedra), naming
     * the types found.
     */
    template <int dim>
    void
    check_cell_types(const Triangulation<dim> &mesh,
                     const std::string        &name,
                     const CellType            cell_type)
    {
      std::map<ReferenceCell, unsigned int> count;
      for (const auto &cell : mesh.active_cell_iterators())
        ++count[cell->reference_cell()];
      const bool          simplex = cell_type == CellType::simplex;
      const ReferenceCell wanted  = simplex ?
                                      ReferenceCells::get_simplex<dim>() :
                                      ReferenceCells::get_hypercube<dim>();
      if (count.size() == 1 && count.count(wanted) == 1)
        return;
      std::string found;
      for (const auto &[type, n] : count)
        found += (found.empty() ? "" : " and ") + std::to_string(n) + " " +
                 (n == 1 ? cell_name(type) : cells_name(type));
      const ReferenceCell other = simplex ?
                                    ReferenceCells::get_hypercube<dim>() :
                                    ReferenceCells::get_simplex<dim>();
      const bool fits_other     = count.size() == 1 && count.count(other) == 1;
      throw InputError(
        "geometry: the mesh file '" + name + "' holds " + found +
        " but 'geometry/cell type' = " + (simplex ? "simplex" : "hypercube") +
        " reads " + cells_name(wanted) + " only. " +
        (fits_other ? "Set 'cell type = " +
                        std::string(simplex ? "hypercube" : "simplex") +
                        "' in subsection geometry." :
                      "A mesh has one cell type: mesh it with " +
                        cells_name(wanted) + " only."));
    }

    /**
     * Refuse a 2D Gmsh file with a node off the plane z = 0 (a 2D mesh
     * keeps x and y only), naming the first such node.
     */
    void
    check_planar(const std::string &name)
    {
      Triangulation<2, 3> mesh;
      read_gmsh(mesh, name);
      const BoundingBox<3> box = GridTools::compute_bounding_box(mesh);
      const double tolerance = 1e-10 * box.get_boundary_points().first.distance(
                                         box.get_boundary_points().second);
      for (const Point<3> &p : mesh.get_vertices())
        require(std::abs(p[2]) <= tolerance,
                "geometry: the mesh file '" + name + "' has the node " +
                  to_text(p) +
                  " off the plane z = 0; a 2D mesh lies in that plane (its z "
                  "coordinates would be dropped). Mesh the body in z = 0 or "
                  "set 'dimension = 3'.");
    }

    /**
     * Refuse distinct vertices at one place (closer than 1e-10 times the
     * mesh's diameter): the cells on either side do not share them, so the
     * body would be cut along the faces between them. The used vertices are
     * sorted by x and compared with those within the tolerance in x.
     */
    template <int dim>
    void
    check_duplicated_vertices(const Triangulation<dim> &mesh,
                              const std::string        &name)
    {
      const std::vector<Point<dim>> &vertices = mesh.get_vertices();
      std::vector<unsigned int>      order;
      for (unsigned int v = 0; v < vertices.size(); ++v)
        if (mesh.get_used_vertices()[v])
          order.push_back(v);
      std::sort(order.begin(), order.end(), [&](const auto a, const auto b) {
        return vertices[a][0] < vertices[b][0];
      });
      const BoundingBox<dim> box = GridTools::compute_bounding_box(mesh);
      const double tolerance = 1e-10 * box.get_boundary_points().first.distance(
                                         box.get_boundary_points().second);
      for (unsigned int i = 0; i < order.size(); ++i)
        for (unsigned int j = i + 1;
             j < order.size() &&
             vertices[order[j]][0] - vertices[order[i]][0] <= tolerance;
             ++j)
          require(vertices[order[i]].distance(vertices[order[j]]) > tolerance,
                  "geometry: the mesh file '" + name +
                    "' has two distinct nodes at " +
                    to_text(vertices[order[i]]) +
                    ": the cells on either side do not share them, which "
                    "cuts the body along the faces between them (a crack). "
                    "Merge the duplicated nodes (Gmsh: Coherence Mesh).");
    }

    /**
     * Refuse a cell whose map from the reference cell is not one to one: a
     * Jacobian determinant below 1e-9 diameter^dim at a vertex (a
     * self-intersecting, inverted or degenerate cell), naming its vertices.
     */
    template <int dim>
    void
    check_cell_shapes(const Triangulation<dim> &mesh, const std::string &name)
    {
      for (const auto &cell : mesh.active_cell_iterators())
        {
          std::vector<double> determinants;
          if (cell->reference_cell().is_hyper_cube())
            {
              Point<dim> vertices[GeometryInfo<dim>::vertices_per_cell];
              for (const unsigned int v : cell->vertex_indices())
                vertices[v] = cell->vertex(v);
              Tensor<0, dim> forms[GeometryInfo<dim>::vertices_per_cell];
              GeometryInfo<dim>::alternating_form_at_vertices(vertices, forms);
              for (const Tensor<0, dim> &f : forms)
                determinants.push_back(f);
            }
          else
            {
              Tensor<2, dim> jacobian;
              for (unsigned int d = 0; d < dim; ++d)
                for (unsigned int e = 0; e < dim; ++e)
                  jacobian[e][d] = cell->vertex(d + 1)[e] - cell->vertex(0)[e];
              determinants.push_back(determinant(jacobian));
            }
          const double smallest =
            *std::min_element(determinants.begin(), determinants.end());
          if (smallest > 1e-9 * std::pow(cell->diameter(), dim))
            continue;
          // the vertices in the order of a Gmsh element: around each face
          // of a hypercube, not deal.II's lexicographic order
          std::string corners;
          for (const unsigned int v : cell->vertex_indices())
            {
              const unsigned int gmsh_v =
                cell->reference_cell().is_hyper_cube() && v % 4 >= 2 ? v ^ 1 :
                                                                       v;
              corners += (v == 0 ? "" : ", ") + to_text(cell->vertex(gmsh_v));
            }
          throw InputError(
            "geometry: the mesh file '" + name + "' has a " +
            cell_name(cell->reference_cell()) + " with the nodes " + corners +
            " that is self-intersecting, inverted or degenerate (the "
            "Jacobian determinant of its map is not positive at every "
            "vertex). Fix the order of its nodes or the mesh.");
        }
    }
  } // namespace

  template <int dim>
  Discretization<dim>::Discretization(const GeometryParameters &geometry,
                                      MPI_Comm                  comm)
    : mpi_communicator(comm)
    , simplex(geometry.cell_type == CellType::simplex)
  {
    if (simplex)
      {
        triangulation =
          std::make_unique<parallel::fullydistributed::Triangulation<dim>>(
            comm);
        fe      = std::make_unique<FESystem<dim>>(FE_SimplexP<dim>(1), dim);
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
    try
      {
        if (!simplex)
          {
            build_mesh(*triangulation, geometry, refine);
            return;
          }
        // every rank builds the whole mesh, partitions it the same way
        // (METIS) and keeps only its cells and a layer of ghosts
        Triangulation<dim> whole;
        build_mesh(whole, geometry, refine);
        GridTools::partition_triangulation(
          Utilities::MPI::n_mpi_processes(mpi_communicator), whole);
        triangulation->create_triangulation(
          TriangulationDescription::Utilities::
            create_description_from_triangulation(whole, mpi_communicator));
      }
    catch (const std::bad_alloc &)
      {
        throw InputError(
          "geometry: the mesh needs more memory than there is ('global "
          "refinements' = " +
          std::to_string(geometry.global_refinements) +
          (geometry.mesh_type == MeshType::gmsh ?
             " of the mesh file '" + geometry.mesh_file + "'" :
             std::string(" of the rectangle")) +
          "); lower 'geometry/global refinements'.");
      }
  }

  template <int dim>
  void
  Discretization<dim>::build_mesh(Triangulation<dim>       &mesh,
                                  const GeometryParameters &geometry,
                                  const bool                refine) const
  {
    unsigned int refinements = geometry.global_refinements;
    if (geometry.mesh_type == MeshType::rectangle)
      {
        if (refine)
          check_refinement_memory<dim>(
            [&](const unsigned int r) {
              double n_dofs = dim;
              for (unsigned int d = 0; d < dim; ++d)
                n_dofs *= std::ldexp(geometry.subdivisions[d], r) + 1;
              return n_dofs;
            },
            refinements,
            mpi_communicator);
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
                                                    repetitions,
                                                    p0,
                                                    p1,
                                                    /*colorize=*/true);
      }
    else
      {
        read_checked_gmsh(mesh, geometry);
        if (refine)
          {
            // vertices per cell of a uniformly refined mesh: 1 (hypercubes),
            // 1/2 (triangles), about 1/6 (tetrahedra)
            const double vertices_per_cell =
              !simplex ? 1. : (dim == 2 ? 1. / 2 : 1. / 6);
            const double n_cells = mesh.n_active_cells();
            check_refinement_memory<dim>(
              [&](const unsigned int r) {
                return dim * vertices_per_cell * std::ldexp(n_cells, dim * r);
              },
              refinements,
              mpi_communicator);
          }
      }
    if (refine)
      mesh.refine_global(refinements);
  }

  template <int dim>
  void
  Discretization<dim>::read_checked_gmsh(
    Triangulation<dim>       &mesh,
    const GeometryParameters &geometry) const
  {
    const std::string &name = geometry.mesh_file;
    require_regular_file(name);
    // read and check on a serial mesh: a p4est mesh fails on cells other
    // than quadrilaterals/hexahedra before any check could run
    Triangulation<dim> coarse;
    read_gmsh(coarse, name);
    check_cell_types(coarse, name, geometry.cell_type);
    if constexpr (dim == 2)
      check_planar(name);
    check_duplicated_vertices(coarse, name);
    check_cell_shapes(coarse, name);
    const auto [vertices, cells, faces] =
      GridTools::get_coarse_mesh_description(coarse);
    mesh.create_triangulation(vertices, cells, faces);
  }

  template <int dim>
  void
  Discretization<dim>::check_boundary_ids(
    const BoundaryParameters &boundary) const
  {
    check_boundary_ids("boundary",
                       {{"clamped boundary ids", boundary.clamped_ids},
                        {"traction boundary ids", boundary.traction_ids},
                        {"contact boundary ids", boundary.contact_ids}});
  }

  template <int dim>
  void
  Discretization<dim>::check_boundary_ids(
    const std::string &subsection,
    const std::vector<std::pair<std::string, std::vector<unsigned int>>>
      &entries) const
  {
    const std::vector<types::boundary_id> present_ids =
      Utilities::MPI::compute_set_union(triangulation->get_boundary_ids(),
                                        mpi_communicator);
    const std::set<types::boundary_id> present(present_ids.begin(),
                                               present_ids.end());
    std::string                        present_list;
    for (const auto id : present)
      present_list += (present_list.empty() ? "" : ", ") + std::to_string(id);

    for (const auto &[name, ids] : entries)
      for (const unsigned int id : ids)
        require(present.count(id) == 1,
                subsection + ": '" + name + "' names boundary id " +
                  std::to_string(id) +
                  ", which the mesh does not have (its boundary ids are " +
                  present_list + ").");
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
