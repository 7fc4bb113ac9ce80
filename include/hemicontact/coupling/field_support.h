#pragma once

#include <deal.II/base/index_set.h>
#include <deal.II/base/mpi.h>
#include <deal.II/lac/trilinos_vector.h>

#include <hemicontact/base/exceptions.h>

#include <string>

namespace hemicontact
{
  using namespace dealii;

  /** A copy of @p v with the ghost entries of @p relevant. */
  inline TrilinosWrappers::MPI::Vector
  ghosted(const TrilinosWrappers::MPI::Vector &v,
          const IndexSet                      &owned,
          const IndexSet                      &relevant,
          MPI_Comm                             comm)
  {
    TrilinosWrappers::MPI::Vector g(owned, relevant, comm);
    g = v;
    return g;
  }

  /** The first non-empty @p error of any rank, thrown as an InputError on
   *  every rank (a coupled field's data checks). */
  inline void
  throw_first_error(const std::string &error, MPI_Comm comm)
  {
    for (const std::string &message : Utilities::MPI::all_gather(comm, error))
      if (!message.empty())
        throw InputError(message);
  }
} // namespace hemicontact
