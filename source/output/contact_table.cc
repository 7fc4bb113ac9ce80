#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>

#include <hemicontact/output/contact_table.h>
#include <hemicontact/output/output_file.h>
#include <hemicontact/problem/contact_problem.h>

#include <algorithm>
#include <iomanip>
#include <sstream>
#include <string>
#include <vector>

namespace hemicontact
{
  namespace
  {
    /**
     * On the root: the gathered rows (@p width values each) of step
     * @p step sorted by coordinates, written atomically to
     * @p directory/contact_NNNNN.csv, the columns of the step's unknown
     * named with @p unknown ("w", or "u" in the static class), the last
     * columns named @p extra (the memory's); returns the reason of a
     * failure.
     */
    template <int dim>
    std::string
    write_sorted_rows(const std::vector<std::vector<double>> &gathered,
                      const unsigned int                      width,
                      const std::string                      &directory,
                      const unsigned int                      step,
                      const std::string                      &unknown,
                      const std::vector<std::string>         &extra)
    {
      std::vector<std::vector<double>> table;
      for (const std::vector<double> &part : gathered)
        for (std::size_t r = 0; r + width <= part.size(); r += width)
          table.emplace_back(part.begin() + r, part.begin() + r + width);
      // sorted by coordinates (x, then y, then z): independent of the partition
      std::sort(table.begin(),
                table.end(),
                [](const std::vector<double> &a, const std::vector<double> &b) {
                  return std::lexicographical_compare(a.begin(),
                                                      a.begin() + dim,
                                                      b.begin(),
                                                      b.begin() + dim);
                });

      std::ostringstream name;
      name << directory << "/contact_" << Utilities::int_to_string(step, 5)
           << ".csv";
      std::ostringstream file;
      const char        *xyz[] = {"x", "y", "z"};
      for (unsigned int d = 0; d < dim; ++d)
        file << xyz[d] << ",";
      for (unsigned int d = 0; d < dim; ++d)
        file << "normal_" << xyz[d] << ",";
      file << "time," << unknown << "_nu," << unknown << "_tau_norm";
      for (unsigned int d = 0; d < dim; ++d)
        file << "," << unknown << "_tau_" << xyz[d];
      file << ",sigma_nu,sigma_tau_norm";
      for (unsigned int d = 0; d < dim; ++d)
        file << ",sigma_tau_" << xyz[d];
      file << ",normal_branch,tangential_branch,mass,friction_bound,"
              "friction_response,wall_pressure";
      for (const std::string &name : extra)
        file << "," << name;
      file << "\n";
      // the two branch columns, integers
      const unsigned int branches = width - extra.size() - 6;

      // small values at the solver tolerance are printed as 0 so that the
      // file does not depend on the number of MPI ranks in the last digits
      const auto clean = [](const double v) {
        return std::abs(v) < 1e-12 ? 0.0 : v;
      };
      file << std::setprecision(10);
      for (const std::vector<double> &row : table)
        {
          for (unsigned int j = 0; j < width; ++j)
            {
              if (j > 0)
                file << ",";
              if (j == branches || j == branches + 1)
                file << static_cast<int>(row[j]);
              else
                file << clean(row[j]);
            }
          file << "\n";
        }
      return write_atomically(name.str(), file.str());
    }
  } // namespace

  template <int dim>
  void
  write_contact_table(const ContactProblem<dim> &problem,
                      const std::string         &directory,
                      MPI_Comm                   mpi_communicator)
  {
    const typename ContactProblem<dim>::State s = problem.state();
    // one row per owned contact node, flattened; columns as in the header
    // below: x, normal, time, w_nu, |w_tau|, w_tau, sigma_nu, |sigma_tau|,
    // sigma_tau, normal_branch, tangential_branch, mass, friction_bound (F_b
    // of the step), friction_response (the force F(|w_tau|) = F_b +
    // r(|w_tau|) that the friction law opposes to the node's slip speed)
    // wall_pressure (the wall's reaction at nodes held there), and with
    // normal memory normal_memory (N_i, doc/theory.md 11.9), with a bound
    // in the accumulated slip s_tau (11.10), with wear the wear depth wear
    // (11.12)
    const bool normal_memory = s.memory.contact_memory().normal_active();
    const bool slip          = s.memory.contact_memory().slip_active();
    const bool wear          = s.memory.contact_memory().wear_active();
    std::vector<std::string> extra;
    if (normal_memory)
      extra.push_back("normal_memory");
    if (slip)
      extra.push_back("s_tau");
    if (wear)
      extra.push_back("wear");
    // the coupled fields' columns, e.g. theta and the contact heat (13.2)
    const std::vector<std::vector<double>> field_values =
      s.coupled_fields.contact_values(mechanical_view(s), s.added_fields);
    for (const std::string &name : s.coupled_fields.contact_columns())
      extra.push_back(name);
    const unsigned int width =
      dim + dim + 1 + 2 + dim + 2 + dim + 3 + 2 + 1 + extra.size();
    std::vector<double> rows;
    for (unsigned int i = 0; i < s.contact_nodes.size(); ++i)
      if (const ContactNode<dim> &node = s.contact_nodes[i]; node.locally_owned)
        {
          Tensor<1, dim> w, traction;
          for (unsigned int c = 0; c < dim; ++c)
            {
              w[c]        = s.velocity[node.dofs[c]];
              traction[c] = s.contact_traction[node.dofs[c]];
            }
          // contact_traction holds -(K w - b)_i / m_i = xi_nu nu + xi_tau,
          // i.e. -sigma nu: the stress vector is its negative
          const Tensor<1, dim> sigma_nu_vector = -traction;
          const double         w_nu            = w * node.normal;
          const Tensor<1, dim> w_tau           = w - w_nu * node.normal;
          const double         sigma_nu        = sigma_nu_vector * node.normal;
          const Tensor<1, dim> sigma_tau =
            sigma_nu_vector - sigma_nu * node.normal;

          for (unsigned int d = 0; d < dim; ++d)
            rows.push_back(node.position[d]);
          for (unsigned int d = 0; d < dim; ++d)
            rows.push_back(node.normal[d]);
          rows.push_back(s.time);
          rows.push_back(w_nu);
          rows.push_back(w_tau.norm());
          for (unsigned int d = 0; d < dim; ++d)
            rows.push_back(w_tau[d]);
          rows.push_back(sigma_nu);
          rows.push_back(sigma_tau.norm());
          for (unsigned int d = 0; d < dim; ++d)
            rows.push_back(sigma_tau[d]);
          rows.push_back(static_cast<int>(node.normal_branch));
          rows.push_back(static_cast<int>(node.tangential_branch));
          rows.push_back(node.mass);
          rows.push_back(node.friction_bound);
          rows.push_back(
            s.friction_law.response(node.friction_bound, w_tau.norm()));
          // N_i, a part of -sigma_nu that is not the wall's
          const double memory_pressure =
            normal_memory ?
              nodal_vector(node, s.memory.contact_memory().pressure()) *
                node.normal :
              0.;
          rows.push_back(nodal::wall_reaction(node,
                                              -sigma_nu - memory_pressure,
                                              s.normal_law));
          if (normal_memory)
            rows.push_back(memory_pressure);
          if (slip)
            rows.push_back(s.memory.contact_memory().slip()[node.dofs[0]]);
          if (wear)
            rows.push_back(s.memory.contact_memory().wear()[node.dofs[0]]);
          rows.insert(rows.end(),
                      field_values[i].begin(),
                      field_values[i].end());
        }

    const std::vector<std::vector<double>> gathered =
      Utilities::MPI::gather(mpi_communicator, rows, 0);
    std::string error;
    if (Utilities::MPI::this_mpi_process(mpi_communicator) == 0)
      error = write_sorted_rows<dim>(gathered,
                                     width,
                                     directory,
                                     s.step_number,
                                     s.scheme.unknown_symbol(),
                                     extra);
    throw_if_any(error, mpi_communicator);
  }

#define HEMICONTACT_INSTANTIATE(dim)                                  \
  template void write_contact_table<dim>(const ContactProblem<dim> &, \
                                         const std::string &,         \
                                         MPI_Comm);

  HEMICONTACT_INSTANTIATE(2)
  HEMICONTACT_INSTANTIATE(3)
#undef HEMICONTACT_INSTANTIATE
} // namespace hemicontact
