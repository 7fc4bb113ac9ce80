#pragma once

#include <deal.II/grid/tria.h>

#include <hemicontact/verification/manufactured_solution.h>

#include <mpi.h>

#include <string>

namespace hemicontact
{
  using namespace dealii;

  /**
   * Where a manufactured solution is too rough for its derived data: the
   * body force and the tractions come from symbolic derivatives, which miss
   * the singular part of a derivative that jumps (a kink of abs(), max(),
   * step() inside the body). The data are right when u, w = du/dt and their
   * gradients are continuous in x and t.
   *
   * Along the segments between the vertices of (up to 32 of) the locally
   * owned cells of @p mesh, at t = 0, T/2 and T, and along [0, T] at those
   * vertices, each quarter of the path is bisected 40 times,
   * following the larger increment of each field: a continuous field's
   * increment vanishes with the segment, a jump's does not. Returns, on every
   * rank, a description of the first jump found (field, place, time, relative
   * size), or an empty string.
   */
  template <int dim>
  std::string
  find_manufactured_jump(const ManufacturedSolution<dim> &exact,
                         const Triangulation<dim>        &mesh,
                         const double                     end_time,
                         MPI_Comm                         comm);
} // namespace hemicontact
