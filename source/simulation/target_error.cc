/**
 * Solving a load value of the static class to a tolerance: refine by the
 * indicator and solve again until the error estimate falls below
 * 'adaptivity/target error' times the energy norm of the solution
 * (doc/adaptivity.md, "Solving to a tolerance").
 */
#include <deal.II/base/geometry_info.h>
#include <deal.II/base/utilities.h>

#include <hemicontact/base/exceptions.h>
#include <hemicontact/output/run_output.h>
#include <hemicontact/simulation/simulation.h>

#include <cmath>
#include <iomanip>
#include <sstream>

namespace hemicontact
{
  template <int dim>
  StepStatistics
  Simulation<dim>::advance_to_target_error(RunOutput<dim> &output)
  {
    const AdaptivityParameters &settings = parameters.adaptivity;
    StepStatistics              stats    = problem.advance();
    unsigned int                newton   = 0;
    unsigned int                linear   = 0;
    // the stored energy before the first adaptation and after the last
    double elastic_before = 0, elastic_after = 0;
    for (unsigned int refinements = 0;; ++refinements)
      {
        // the static class's stored energy is 1/2 a_B(u_h, u_h)
        const double norm =
          std::sqrt(2 * std::max(problem.state().energy.elastic, 0.));
        const double                   target = settings.target_error * norm;
        const types::global_cell_index cells  = stats.n_cells;
        const types::global_dof_index  dofs   = stats.n_dofs;
        if (stats.estimate <= target)
          {
            pcout << std::scientific << std::setprecision(4)
                  << "  target error reached: estimate " << stats.estimate
                  << " <= " << std::defaultfloat << settings.target_error
                  << std::scientific << " x " << norm << " with " << cells
                  << " cells, " << dofs << " dofs after " << refinements
                  << " refinements" << std::defaultfloat << std::endl;
            stats.newton_iterations += newton;
            stats.linear_iterations += linear;
            if (refinements > 0)
              {
                stats.adapted                   = true;
                stats.elastic_before_adaptation = elastic_before;
                stats.elastic_after_adaptation  = elastic_after;
              }
            return stats;
          }

        // refine, unless the limits stop it: a mesh that does not grow
        // cannot lower the estimate; at 'max cells' when refining one more
        // cell (2^dim - 1 new ones) would exceed it
        const bool at_max_cells =
          settings.max_cells > 0 &&
          cells + GeometryInfo<dim>::max_children_per_cell - 1 >
            settings.max_cells;
        if (!at_max_cells)
          {
            output.finish_solution_output(); // its job reads the mesh
            StepStatistics adaptation;
            problem.adapt_mesh(adaptation);
            if (refinements == 0)
              elastic_before = adaptation.elastic_before_adaptation;
            elastic_after = adaptation.elastic_after_adaptation;
            output.mesh_changed(problem);
          }
        if (at_max_cells || problem.state().dof_handler.n_dofs() <= dofs)
          {
            std::ostringstream message;
            message << "at load value " << problem.state().step_number
                    << " (t = " << stats.time << ") the error estimate "
                    << stats.estimate
                    << " is above 'adaptivity/target error' = "
                    << settings.target_error
                    << " times a_B(u_h, u_h)^(1/2) = " << norm << ", i.e. "
                    << target << ", with " << cells << " cells and " << dofs
                    << " dofs, and the mesh cannot grow: "
                    << (at_max_cells ?
                          "'adaptivity/max cells' = " +
                            std::to_string(settings.max_cells) +
                            " leaves no room to refine a cell" :
                          "no cell can be refined below 'adaptivity/max "
                          "level' = " +
                            std::to_string(settings.max_level))
                    << ". Raise the limit, or the target error. The load "
                       "value's last solution was written to '"
                    << parameters.output.directory << "'.";
            if (!at_max_cells)
              {
                // back to a solution on the mesh that stopped growing
                stats = problem.solve_again();
              }
            // the load value as far as it got, in every output file
            output.write_probes(problem);
            output.write_solution(problem);
            output.write_step(stats, problem);
            output.finish_solution_output();
            throw TargetErrorNotReached(message.str());
          }

        // solve the same load value again on the new mesh, from the
        // transferred solution
        newton += stats.newton_iterations;
        linear += stats.linear_iterations;
        stats = problem.solve_again();
      }
  }

  template StepStatistics
  Simulation<2>::advance_to_target_error(RunOutput<2> &);
  template StepStatistics
  Simulation<3>::advance_to_target_error(RunOutput<3> &);
} // namespace hemicontact
