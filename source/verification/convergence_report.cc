#include <deal.II/base/mpi.h>

#include <hemicontact/base/exceptions.h>
#include <hemicontact/output/output_file.h>
#include <hemicontact/verification/convergence_report.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <vector>

namespace hemicontact
{
  namespace convergence_report
  {
    void
    require_writable_csv(const Parameters &parameters, MPI_Comm comm)
    {
      require_usable_output_directory(parameters.output.directory, comm);
      std::string error;
      if (Utilities::MPI::this_mpi_process(comm) == 0)
        {
          const std::string probe =
            parameters.output.directory + "/convergence.csv.tmp";
          std::error_code ec;
          std::filesystem::create_directories(parameters.output.directory, ec);
          if (ec || !std::ofstream(probe))
            error = "output: cannot write convergence.csv in '" +
                    parameters.output.directory + "'.";
          std::filesystem::remove(probe, ec);
        }
      error = Utilities::MPI::broadcast(comm, error, 0);
      require(error.empty(), error);
    }

    std::string
    csv_header()
    {
      // new columns go at the end: readers select columns by name or position
      return "level,h,k,n_dofs,n_steps,E_H,E_V,E_u,E_V_H1,E_u_H1,"
             "mean_newton_iterations,max_newton_iterations,wall_seconds,"
             "share_separating,share_normal_stick,share_damped,"
             "share_stick,share_slip,mean_dofs,max_dofs,step_wall_seconds,"
             "E_energy,estimate,effectivity,estimate_interior,estimate_jumps,"
             "estimate_neumann,estimate_contact,estimate_time,"
             "effectivity_total,E_theta,E_theta_H1\n";
    }

    std::string
    csv_row(const unsigned int level, const LevelResult &r)
    {
      const ErrorNorms  &e = r.errors;
      std::ostringstream csv;
      csv << std::setprecision(10) << level << "," << r.h << "," << r.k << ","
          << r.n_dofs << "," << r.n_steps << "," << e.E_H << "," << e.E_V << ","
          << e.E_u << "," << e.E_V_H1 << "," << e.E_u_H1 << ","
          << r.mean_newton_iterations << "," << r.max_newton_iterations << ","
          << r.wall_seconds;
      for (const double share : r.branch_share)
        csv << "," << share;
      csv << "," << r.mean_dofs << "," << r.max_dofs << ","
          << r.step_wall_seconds << "," << e.E_energy;
      // the estimate's columns are empty without 'output/error estimate'
      if (r.estimated)
        {
          csv << "," << r.estimate << "," << r.effectivity;
          for (const double term : r.estimate_terms)
            csv << "," << term;
        }
      else
        csv << ",,,,,,";
      // the time indicator's columns: velocity classes only
      if (r.time_estimated)
        csv << "," << r.estimate_time << "," << r.effectivity_total;
      else
        csv << ",,";
      // the temperature's: with a manufactured temperature only
      if (r.with_temperature)
        csv << "," << e.E_theta << "," << e.E_theta_H1;
      else
        csv << ",,";
      csv << "\n";
      return csv.str();
    }

    void
    print_branch_shares(const unsigned int level, const LevelResult &r)
    {
      const double *share = r.branch_share;
      std::cout << "level " << level << ": " << r.n_steps
                << " steps, share of (node, step) pairs: separating "
                << std::fixed << std::setprecision(3) << share[0]
                << ", normal stick " << share[1] << ", damped " << share[2];
      if (r.breakpoint_share > 0 || r.wall_share > 0)
        std::cout << ", at a breakpoint " << r.breakpoint_share
                  << ", at the wall " << r.wall_share;
      std::cout << ", stick " << share[3] << ", slip " << share[4]
                << std::defaultfloat << std::endl;
    }

    void
    add_table_row(ConvergenceTable  &table,
                  const unsigned int level,
                  const LevelResult &r,
                  const bool         adaptive)
    {
      table.add_value("level", level);
      table.add_value("h", r.h);
      table.add_value("k", r.k);
      if (adaptive)
        {
          table.add_value("mean dofs",
                          static_cast<unsigned int>(std::round(r.mean_dofs)));
          table.add_value("max dofs", r.max_dofs);
        }
      else
        table.add_value("dofs", r.n_dofs);
      table.add_value("steps", r.n_steps);
      table.add_value("E_H", r.errors.E_H);
      table.add_value("E_V", r.errors.E_V);
      table.add_value("E_u", r.errors.E_u);
      table.add_value("E_V(H1)", r.errors.E_V_H1);
      table.add_value("E_u(H1)", r.errors.E_u_H1);
      if (r.with_temperature)
        {
          table.add_value("E_theta", r.errors.E_theta);
          table.add_value("E_theta(H1)", r.errors.E_theta_H1);
        }
      table.add_value("newton", r.mean_newton_iterations);
      if (r.estimated)
        {
          table.add_value("E_energy", r.errors.E_energy);
          table.add_value("estimate", r.estimate);
          table.add_value("effectivity", r.effectivity);
        }
      if (r.time_estimated)
        {
          table.add_value("estimate_time", r.estimate_time);
          table.add_value("effectivity_total", r.effectivity_total);
        }
    }

    void
    format_table(ConvergenceTable  &table,
                 const unsigned int n_levels,
                 const bool         against_dofs,
                 const bool         with_estimate,
                 const bool         with_time_estimate,
                 const bool         with_temperature)
    {
      std::vector<const char *> columns = {
        "E_H", "E_V", "E_u", "E_V(H1)", "E_u(H1)"};
      if (with_temperature)
        columns.insert(columns.end(), {"E_theta", "E_theta(H1)"});
      for (const char *column : columns)
        {
          table.set_scientific(column, true);
          table.set_precision(column, 3);
          if (n_levels > 1 && against_dofs)
            table.evaluate_convergence_rates(
              column, "mean dofs", ConvergenceTable::reduction_rate_log2, 1);
          else if (n_levels > 1)
            table.evaluate_convergence_rates(
              column, ConvergenceTable::reduction_rate_log2);
        }
      table.set_scientific("h", true);
      table.set_scientific("k", true);
      table.set_precision("h", 3);
      table.set_precision("k", 3);
      table.set_precision("newton", 2);
      if (with_estimate)
        {
          for (const char *column : {"E_energy", "estimate"})
            {
              table.set_scientific(column, true);
              table.set_precision(column, 3);
            }
          table.set_precision("effectivity", 2);
        }
      if (with_time_estimate)
        {
          table.set_scientific("estimate_time", true);
          table.set_precision("estimate_time", 3);
          table.set_precision("effectivity_total", 2);
        }
    }
  } // namespace convergence_report
} // namespace hemicontact
