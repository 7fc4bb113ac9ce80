#pragma once

#include <mpi.h>

#include <string>

namespace hemicontact
{
  template <int dim>
  class ContactProblem;

  /**
   * Write @p directory/contact_NNNNN.csv of the current step of @p problem
   * (doc/outputs.md): one row per contact node (all ranks, sorted by
   * coordinates) with w_nu, w_tau, sigma_nu, sigma_tau, the branches, the
   * nodal mass m_i, the friction bound and the friction response.
   * Collective; an OutputError on every rank if the file cannot be written.
   */
  template <int dim>
  void
  write_contact_table(const ContactProblem<dim> &problem,
                      const std::string         &directory,
                      MPI_Comm                   mpi_communicator);
} // namespace hemicontact
