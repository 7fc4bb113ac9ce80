#include <deal.II/base/convergence_table.h>
#include <deal.II/base/quadrature.h>
#include <deal.II/base/timer.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/grid/reference_cell.h>

#include <hemicontact/contact_problem.h>
#include <hemicontact/convergence_study.h>
#include <hemicontact/input_error.h>
#include <hemicontact/manufactured_solution.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>

namespace hemicontact
{
  namespace
  {
    /** Squared norms of w(t) - w_h and u(t) - u_h at one time. */
    struct StepErrors
    {
      double w_L2 = 0, w_V = 0, w_H1 = 0, u_V = 0, u_H1 = 0;
    };

    /** @p relevant: the locally relevant dofs of the problem's mesh. */
    template <int dim>
    StepErrors
    step_errors(const ContactProblem<dim> &          problem,
                const ManufacturedSolution<dim> &    exact,
                const double                         t,
                const IndexSet &                     relevant,
                MPI_Comm                             comm)
    {
      const DoFHandler<dim> &dof_handler = problem.get_dof_handler();
      TrilinosWrappers::MPI::Vector w(dof_handler.locally_owned_dofs(),
                                      relevant, comm);
      TrilinosWrappers::MPI::Vector u(w);
      w = problem.get_velocity();
      u = problem.get_displacement();

      // of higher order than the elements (exact for degree 5)
      const Quadrature<dim> quadrature =
        dof_handler.get_fe().reference_cell().template get_gauss_type_quadrature<dim>(3);
      FEValues<dim> fe_values(problem.get_mapping(), dof_handler.get_fe(),
                              quadrature,
                              update_values | update_gradients |
                                update_quadrature_points | update_JxW_values);
      const FEValuesExtractors::Vector v(0);
      std::vector<Tensor<1, dim>>      w_h(quadrature.size());
      std::vector<Tensor<2, dim>>      grad_w_h(quadrature.size()),
        grad_u_h(quadrature.size());

      StepErrors e;
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            fe_values.reinit(cell);
            fe_values[v].get_function_values(w, w_h);
            fe_values[v].get_function_gradients(w, grad_w_h);
            fe_values[v].get_function_gradients(u, grad_u_h);
            for (const unsigned int q : fe_values.quadrature_point_indices())
              {
                const auto ex =
                  exact.evaluate_fields(fe_values.quadrature_point(q), t);
                const Tensor<2, dim> gw = ex.grad_w - grad_w_h[q];
                const Tensor<2, dim> gu = ex.grad_u - grad_u_h[q];
                const double         JxW = fe_values.JxW(q);
                e.w_L2 += (ex.w - w_h[q]).norm_square() * JxW;
                e.w_V += symmetrize(gw) * symmetrize(gw) * JxW;
                e.w_H1 += gw.norm_square() * JxW;
                e.u_V += symmetrize(gu) * symmetrize(gu) * JxW;
                e.u_H1 += gu.norm_square() * JxW;
              }
          }
      e.w_L2 = Utilities::MPI::sum(e.w_L2, comm);
      e.w_V  = Utilities::MPI::sum(e.w_V, comm);
      e.w_H1 = Utilities::MPI::sum(e.w_H1, comm);
      e.u_V  = Utilities::MPI::sum(e.u_V, comm);
      e.u_H1 = Utilities::MPI::sum(e.u_H1, comm);
      return e;
    }

    /** The largest cell diameter of the mesh. */
    template <int dim>
    double
    mesh_size(const DoFHandler<dim> &dof_handler, MPI_Comm comm)
    {
      double h = 0;
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
          h = std::max(h, cell->diameter());
      return Utilities::MPI::max(h, comm);
    }
  } // namespace

  template <int dim>
  std::vector<LevelResult>
  run_convergence_study(const Parameters &parameters, ParameterHandler &prm,
                        MPI_Comm comm)
  {
    std::vector<LevelResult> results;
    const bool root = Utilities::MPI::this_mpi_process(comm) == 0;
    const std::string &type     = parameters.study.type;
    const unsigned int n_levels = type == "single" ? 1 : parameters.study.n_levels;

    std::ofstream csv;
    if (root)
      {
        std::filesystem::create_directories(parameters.output.directory);
        csv.open(parameters.output.directory + "/convergence.csv");
        require(static_cast<bool>(csv),
                "output: cannot write convergence.csv in '" +
                  parameters.output.directory + "'.");
        csv << "level,h,k,n_dofs,n_steps,E_H,E_V,E_u,E_V_H1,E_u_H1,"
               "mean_newton_iterations,max_newton_iterations,wall_seconds,"
               "share_separating,share_normal_stick,share_damped,"
               "share_stick,share_slip\n";
      }

    ConvergenceTable table;
    for (unsigned int level = 0; level < n_levels; ++level)
      {
        Parameters p = parameters;
        p.output.terminal = "quiet";
        if (type == "h" || type == "coupled")
          p.geometry.global_refinements += level;
        if (type == "k" || type == "coupled")
          p.time.time_step /= std::pow(2., level);

        Timer                           wall;
        const std::unique_ptr<NormalLaw> law = create_normal_law(prm);
        const ManufacturedSolution<dim>  exact(p, *law);
        ContactProblem<dim> problem(p, create_normal_law(prm),
                                    exact.make_problem_data(), comm);
        problem.setup();
        IndexSet relevant;
        DoFTools::extract_locally_relevant_dofs(problem.get_dof_handler(),
                                                relevant);

        ErrorNorms   errors;
        double       sum_V = 0, sum_V_H1 = 0;
        unsigned int newton = 0, max_newton = 0, n_steps = 0;
        double       branch[5] = {0, 0, 0, 0, 0};
        while (!problem.finished())
          {
            const StepStatistics s = problem.advance();
            const StepErrors     e =
              step_errors(problem, exact, s.time, relevant, comm);
            errors.E_H = std::max(errors.E_H, std::sqrt(e.w_L2));
            errors.E_u = std::max(errors.E_u, std::sqrt(e.u_V));
            errors.E_u_H1 = std::max(errors.E_u_H1, std::sqrt(e.u_H1));
            sum_V += problem.get_time_step() * e.w_V;
            sum_V_H1 += problem.get_time_step() * e.w_H1;
            newton += s.newton_iterations;
            max_newton = std::max(max_newton, s.newton_iterations);
            ++n_steps;
            const unsigned int counts[5] = {s.n_separating, s.n_normal_stick,
                                            s.n_damped, s.n_stick, s.n_slip};
            for (unsigned int b = 0; b < 5; ++b)
              branch[b] += counts[b];
          }
        errors.E_V    = std::sqrt(sum_V);
        errors.E_V_H1 = std::sqrt(sum_V_H1);
        const double n_pairs_normal  = branch[0] + branch[1] + branch[2];
        const double seconds         = wall.wall_time();
        const double h = mesh_size(problem.get_dof_handler(), comm);
        const double k = problem.get_time_step();

        LevelResult result;
        result.h                      = h;
        result.k                      = k;
        result.n_dofs                 = problem.get_dof_handler().n_dofs();
        result.n_steps                = n_steps;
        result.errors                 = errors;
        result.mean_newton_iterations = double(newton) / n_steps;
        for (unsigned int b = 0; b < 5; ++b)
          result.branch_share[b] = branch[b] / n_pairs_normal;
        results.push_back(result);

        table.add_value("level", level);
        table.add_value("h", h);
        table.add_value("k", k);
        table.add_value("dofs", problem.get_dof_handler().n_dofs());
        table.add_value("steps", n_steps);
        table.add_value("E_H", errors.E_H);
        table.add_value("E_V", errors.E_V);
        table.add_value("E_u", errors.E_u);
        table.add_value("E_V(H1)", errors.E_V_H1);
        table.add_value("E_u(H1)", errors.E_u_H1);
        table.add_value("newton", double(newton) / n_steps);
        if (root)
          {
            csv << std::setprecision(10) << level << "," << h << "," << k
                << "," << problem.get_dof_handler().n_dofs() << "," << n_steps
                << "," << errors.E_H << "," << errors.E_V << "," << errors.E_u
                << "," << errors.E_V_H1 << "," << errors.E_u_H1 << ","
                << double(newton) / n_steps << "," << max_newton << ","
                << seconds;
            for (unsigned int b = 0; b < 5; ++b)
              csv << "," << branch[b] / n_pairs_normal;
            csv << "\n";
            csv.flush();
            if (parameters.output.terminal != "quiet")
              std::cout << "level " << level << ": " << n_steps
                        << " steps, share of (node, step) pairs: separating "
                        << std::fixed << std::setprecision(3)
                        << branch[0] / n_pairs_normal << ", normal stick "
                        << branch[1] / n_pairs_normal << ", damped "
                        << branch[2] / n_pairs_normal << ", stick "
                        << branch[3] / n_pairs_normal << ", slip "
                        << branch[4] / n_pairs_normal
                        << std::defaultfloat << std::endl;
          }
      }

    for (const char *column : {"E_H", "E_V", "E_u", "E_V(H1)", "E_u(H1)"})
      {
        table.set_scientific(column, true);
        table.set_precision(column, 3);
        if (n_levels > 1)
          table.evaluate_convergence_rates(column,
                                           ConvergenceTable::reduction_rate_log2);
      }
    table.set_scientific("h", true);
    table.set_scientific("k", true);
    table.set_precision("h", 3);
    table.set_precision("k", 3);
    table.set_precision("newton", 2);
    if (root && parameters.output.terminal != "quiet")
      {
        std::cout << "convergence study '" << type << "' (orders: log2 of the "
                  << "error ratio between levels)\n";
        table.write_text(std::cout, TableHandler::org_mode_table);
      }
    return results;
  }

  template std::vector<LevelResult>
  run_convergence_study<2>(const Parameters &, ParameterHandler &, MPI_Comm);
  template std::vector<LevelResult>
  run_convergence_study<3>(const Parameters &, ParameterHandler &, MPI_Comm);
} // namespace hemicontact
