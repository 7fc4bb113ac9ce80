#include <deal.II/base/convergence_table.h>
#include <deal.II/base/quadrature.h>
#include <deal.II/base/timer.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/grid/reference_cell.h>

#include <hemicontact/base/exceptions.h>
#include <hemicontact/output/output_file.h>
#include <hemicontact/problem/contact_problem.h>
#include <hemicontact/thermal/heat_model.h>
#include <hemicontact/verification/convergence_report.h>
#include <hemicontact/verification/convergence_study.h>
#include <hemicontact/verification/manufactured_smoothness.h>
#include <hemicontact/verification/manufactured_solution.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <limits>
#include <memory>
#include <sstream>

namespace hemicontact
{
  namespace
  {
    /** Squared norms of w(t) - w_h and u(t) - u_h at one time. */
    struct StepErrors
    {
      double w_L2 = 0, w_V = 0, w_H1 = 0, u_V = 0, u_H1 = 0;
      /** |||e|||^2 of the step's unknown (doc/theory.md 12.1) */
      double energy = 0;
      /** theta(t) - theta_h in L2 and in the H1 seminorm (with a
       *  manufactured temperature, doc/theory.md 13.6) */
      bool   with_temperature = false;
      double theta_L2 = 0, theta_H1 = 0;

      /** The sums over the processes of the locally owned cells' parts. */
      StepErrors
      sum(MPI_Comm comm) const
      {
        StepErrors e;
        e.w_L2             = Utilities::MPI::sum(w_L2, comm);
        e.w_V              = Utilities::MPI::sum(w_V, comm);
        e.w_H1             = Utilities::MPI::sum(w_H1, comm);
        e.u_V              = Utilities::MPI::sum(u_V, comm);
        e.u_H1             = Utilities::MPI::sum(u_H1, comm);
        e.energy           = Utilities::MPI::sum(energy, comm);
        e.with_temperature = with_temperature;
        e.theta_L2         = Utilities::MPI::sum(theta_L2, comm);
        e.theta_H1         = Utilities::MPI::sum(theta_H1, comm);
        return e;
      }
    };

    /**
     * The density of |||v|||^2 = c_A a_A(v, v) + c_B a_B(v, v) with the
     * step matrix's coefficients, of the error in the step's unknown (u:
     * static class, w otherwise).
     */
    template <int dim>
    class ErrorEnergy
    {
    public:
      explicit ErrorEnergy(const ContactProblem<dim> &problem)
        : material(problem.state().material)
        , c(problem.state().scheme.step_matrix(problem.state().time_step))
        , on_u(problem.state().scheme.is_static())
      {}

      /** At a point with error gradients @p grad_u and @p grad_w. */
      double
      operator()(const Tensor<2, dim> &grad_u,
                 const Tensor<2, dim> &grad_w) const
      {
        const SymmetricTensor<2, dim> eps = symmetrize(on_u ? grad_u : grad_w);
        return (c.viscous * material.viscous_stress(eps) +
                c.elastic * material.elastic_stress(eps)) *
               eps;
      }

    private:
      const KelvinVoigtMaterial<dim> &material;
      const StepMatrixCoefficients    c;
      const bool                      on_u;
    };

    /** The squared L2 and H1-seminorm errors of theta_h at time @p t
     *  into @p e (owned cells; the quadrature of step_errors()). */
    template <int dim>
    void
    add_temperature_errors(const ContactProblem<dim>       &problem,
                           const ManufacturedSolution<dim> &exact,
                           const double                     t,
                           MPI_Comm                         comm,
                           StepErrors                      &e)
    {
      const char            *name  = HeatModel<dim>::field_name;
      const FieldSpace<dim> &space = problem.state().added_fields.space(name);
      TrilinosWrappers::MPI::Vector theta(*space.owned, *space.relevant, comm);
      theta                        = problem.state().added_fields.vector(name);
      const FiniteElement<dim> &fe = space.dof_handler->get_fe();
      const Quadrature<dim>     quadrature =
        fe.reference_cell().template get_gauss_type_quadrature<dim>(3);
      FEValues<dim>       fe_values(*problem.state().discretization.mapping,
                              fe,
                              quadrature,
                              update_values | update_gradients |
                                update_quadrature_points | update_JxW_values);
      std::vector<double> theta_h(quadrature.size());
      std::vector<Tensor<1, dim>> grad_theta_h(quadrature.size());
      e.with_temperature = true;
      for (const auto &cell : space.dof_handler->active_cell_iterators())
        if (cell->is_locally_owned())
          {
            fe_values.reinit(cell);
            fe_values.get_function_values(theta, theta_h);
            fe_values.get_function_gradients(theta, grad_theta_h);
            const auto ex =
              exact.temperature_values(fe_values.get_quadrature_points(), t);
            for (const unsigned int q : fe_values.quadrature_point_indices())
              {
                e.theta_L2 +=
                  std::pow(ex[q].theta - theta_h[q], 2) * fe_values.JxW(q);
                e.theta_H1 +=
                  (ex[q].grad_theta - grad_theta_h[q]).norm_square() *
                  fe_values.JxW(q);
              }
          }
    }

    /** @p relevant: the locally relevant dofs of the problem's mesh;
     *  @p cache: the exact fields' spatial part at its quadrature points. */
    template <int dim>
    StepErrors
    step_errors(const ContactProblem<dim>       &problem,
                const ManufacturedSolution<dim> &exact,
                const double                     t,
                const IndexSet                  &relevant,
                SpatialCache                    &cache,
                MPI_Comm                         comm)
    {
      const DoFHandler<dim>        &dof_handler = problem.state().dof_handler;
      TrilinosWrappers::MPI::Vector w(dof_handler.locally_owned_dofs(),
                                      relevant,
                                      comm);
      TrilinosWrappers::MPI::Vector u(w);
      w = problem.state().velocity;
      u = problem.state().displacement;

      // of higher order than the elements (exact for degree 5)
      const Quadrature<dim> quadrature =
        dof_handler.get_fe()
          .reference_cell()
          .template get_gauss_type_quadrature<dim>(3);
      FEValues<dim> fe_values(*problem.state().discretization.mapping,
                              dof_handler.get_fe(),
                              quadrature,
                              update_values | update_gradients |
                                update_quadrature_points | update_JxW_values);
      const FEValuesExtractors::Vector v(0);
      std::vector<Tensor<1, dim>>      w_h(quadrature.size());
      std::vector<Tensor<2, dim>>      grad_w_h(quadrature.size()),
        grad_u_h(quadrature.size());

      const ErrorEnergy<dim> energy(problem);
      StepErrors             e;
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            fe_values.reinit(cell);
            fe_values[v].get_function_values(w, w_h);
            fe_values[v].get_function_gradients(w, grad_w_h);
            fe_values[v].get_function_gradients(u, grad_u_h);
            const auto exact_values =
              exact.evaluate_fields(fe_values.get_quadrature_points(),
                                    t,
                                    &cache);
            for (const unsigned int q : fe_values.quadrature_point_indices())
              {
                const auto          &ex  = exact_values[q];
                const Tensor<2, dim> gw  = ex.grad_w - grad_w_h[q];
                const Tensor<2, dim> gu  = ex.grad_u - grad_u_h[q];
                const double         JxW = fe_values.JxW(q);
                e.w_L2 += (ex.w - w_h[q]).norm_square() * JxW;
                e.w_V += symmetrize(gw) * symmetrize(gw) * JxW;
                e.w_H1 += gw.norm_square() * JxW;
                e.u_V += symmetrize(gu) * symmetrize(gu) * JxW;
                e.u_H1 += gu.norm_square() * JxW;
                e.energy += energy(gu, gw) * JxW;
              }
          }
      if (exact.has_temperature())
        add_temperature_errors(problem, exact, t, comm, e);
      return e.sum(comm);
    }

    /**
     * The run with 'convergence study/reference time step' on the mesh of
     * a 'k' study: u and w at the times j k_f, j = 1, 2, ..., of the finest
     * level's step k_f (entry j - 1; owned entries).
     */
    struct ReferenceRun
    {
      double                                     finest_step = 0;
      std::vector<TrilinosWrappers::MPI::Vector> u, w;

      /** The index of the entry at time @p t (a multiple of finest_step). */
      unsigned int
      index(const double t) const
      {
        const double j = t / finest_step;
        AssertThrow(std::abs(j - std::round(j)) < 1e-6 && std::round(j) >= 1 &&
                      std::round(j) <= w.size(),
                    ExcMessage("no reference step at this time"));
        return static_cast<unsigned int>(std::round(j)) - 1;
      }
    };

    /** The squared norms of w_ref - w_h and u_ref - u_h at time @p t. */
    template <int dim>
    StepErrors
    reference_step_errors(const ContactProblem<dim> &problem,
                          const ReferenceRun        &reference,
                          const double               t,
                          const IndexSet            &relevant,
                          MPI_Comm                   comm)
    {
      const DoFHandler<dim> &dof_handler = problem.state().dof_handler;
      const unsigned int     j           = reference.index(t);
      AssertThrow(reference.w[j].size() == problem.state().velocity.size(),
                  ExcMessage("the reference ran on another mesh"));
      TrilinosWrappers::MPI::Vector difference(reference.w[j]);
      difference -= problem.state().velocity;
      TrilinosWrappers::MPI::Vector d_w(dof_handler.locally_owned_dofs(),
                                        relevant,
                                        comm);
      TrilinosWrappers::MPI::Vector d_u(d_w);
      d_w        = difference;
      difference = reference.u[j];
      difference -= problem.state().displacement;
      d_u = difference;

      // both fields are finite element functions: Gauss of order 2 is exact
      const Quadrature<dim> quadrature =
        dof_handler.get_fe()
          .reference_cell()
          .template get_gauss_type_quadrature<dim>(2);
      FEValues<dim> fe_values(*problem.state().discretization.mapping,
                              dof_handler.get_fe(),
                              quadrature,
                              update_values | update_gradients |
                                update_JxW_values);
      const FEValuesExtractors::Vector v(0);
      std::vector<Tensor<1, dim>>      w_values(quadrature.size());
      std::vector<Tensor<2, dim>> gw(quadrature.size()), gu(quadrature.size());
      const ErrorEnergy<dim>      energy(problem);
      StepErrors                  e;
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            fe_values.reinit(cell);
            fe_values[v].get_function_values(d_w, w_values);
            fe_values[v].get_function_gradients(d_w, gw);
            fe_values[v].get_function_gradients(d_u, gu);
            for (const unsigned int q : fe_values.quadrature_point_indices())
              {
                const double JxW = fe_values.JxW(q);
                e.w_L2 += w_values[q].norm_square() * JxW;
                e.w_V += symmetrize(gw[q]) * symmetrize(gw[q]) * JxW;
                e.w_H1 += gw[q].norm_square() * JxW;
                e.u_V += symmetrize(gu[q]) * symmetrize(gu[q]) * JxW;
                e.u_H1 += gu[q].norm_square() * JxW;
                e.energy += energy(gu[q], gw[q]) * JxW;
              }
          }
      return e.sum(comm);
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

    /** The sums over the steps of one level that make its LevelResult. */
    struct LevelSums
    {
      ErrorNorms errors;
      double     sum_V = 0, sum_V_H1 = 0, sum_dofs = 0;
      /** k sum_n of |||e_n|||^2, eta_n^2 and of each term's square */
      double sum_energy = 0, sum_estimate = 0, sum_terms[4] = {0, 0, 0, 0};
      bool   estimated = false;
      /** k sum_n |||w_n - w_{n-1}|||^2, the time indicator's */
      double       sum_time       = 0;
      bool         time_estimated = false;
      unsigned int newton = 0, max_newton = 0, n_steps = 0, max_dofs = 0;
      /** k sum_n |theta(t_n) - theta_n|_H1^2 */
      double sum_theta_H1     = 0;
      bool   with_temperature = false;
      double branch[7]        = {0, 0, 0, 0, 0, 0, 0};

      /** Add step @p s (of length @p k) with its errors @p e. */
      void
      add(const StepStatistics &s, const StepErrors &e, const double k)
      {
        errors.E_H    = std::max(errors.E_H, std::sqrt(e.w_L2));
        errors.E_u    = std::max(errors.E_u, std::sqrt(e.u_V));
        errors.E_u_H1 = std::max(errors.E_u_H1, std::sqrt(e.u_H1));
        sum_V += k * e.w_V;
        sum_V_H1 += k * e.w_H1;
        sum_energy += k * e.energy;
        if (e.with_temperature)
          {
            with_temperature = true;
            errors.E_theta   = std::max(errors.E_theta, std::sqrt(e.theta_L2));
            sum_theta_H1 += k * e.theta_H1;
          }
        if (s.estimated)
          {
            estimated = true;
            sum_estimate += k * s.estimate * s.estimate;
            const double terms[4] = {s.estimate_interior,
                                     s.estimate_jumps,
                                     s.estimate_neumann,
                                     s.estimate_contact};
            for (unsigned int t = 0; t < 4; ++t)
              sum_terms[t] += k * terms[t] * terms[t];
          }
        if (s.time_estimated)
          {
            time_estimated = true;
            sum_time += k * s.estimate_time * s.estimate_time;
          }
        newton += s.newton_iterations;
        max_newton = std::max(max_newton, s.newton_iterations);
        sum_dofs += s.n_dofs;
        max_dofs = std::max(max_dofs, s.n_dofs);
        ++n_steps;
        const unsigned int counts[7] = {s.n_separating,
                                        s.n_normal_stick,
                                        s.n_damped,
                                        s.n_stick,
                                        s.n_slip,
                                        s.n_at_breakpoint,
                                        s.n_at_wall};
        for (unsigned int b = 0; b < 7; ++b)
          branch[b] += counts[b];
      }

      /** Everything but h, k, n_dofs and the wall time. */
      LevelResult
      result() const
      {
        LevelResult r;
        r.n_steps           = n_steps;
        r.errors            = errors;
        r.errors.E_V        = std::sqrt(sum_V);
        r.errors.E_V_H1     = std::sqrt(sum_V_H1);
        r.errors.E_energy   = std::sqrt(sum_energy);
        r.with_temperature  = with_temperature;
        r.errors.E_theta_H1 = std::sqrt(sum_theta_H1);
        r.estimated         = estimated;
        r.estimate          = std::sqrt(sum_estimate);
        r.effectivity       = r.estimate / r.errors.E_energy;
        for (unsigned int t = 0; t < 4; ++t)
          r.estimate_terms[t] = std::sqrt(sum_terms[t]);
        r.time_estimated = time_estimated;
        r.estimate_time  = std::sqrt(sum_time);
        r.effectivity_total =
          std::sqrt(sum_estimate + sum_time) / r.errors.E_energy;
        r.mean_dofs              = sum_dofs / n_steps;
        r.max_dofs               = max_dofs;
        r.mean_newton_iterations = double(newton) / n_steps;
        r.max_newton_iterations  = max_newton;
        const double n_pairs_normal =
          branch[0] + branch[1] + branch[2] + branch[5] + branch[6];
        for (unsigned int b = 0; b < 5; ++b)
          r.branch_share[b] = branch[b] / n_pairs_normal;
        r.breakpoint_share = branch[5] / n_pairs_normal;
        r.wall_share       = branch[6] / n_pairs_normal;
        return r;
      }
    };

    /**
     * The reference of a 'k' study: the run with parameters @p p (the
     * reference time step), with u and w kept at every multiple of
     * @p finest_step.
     */
    template <int dim>
    ReferenceRun
    run_reference(const Parameters &p,
                  ParameterHandler &prm,
                  MPI_Comm          comm,
                  const double      finest_step)
    {
      const ContactLaws               laws = create_contact_laws(prm);
      const ManufacturedSolution<dim> exact(p, *laws.normal, *laws.friction);
      ContactProblem<dim>             problem(p,
                                  create_contact_laws(prm),
                                  exact.make_problem_data(),
                                  comm);
      problem.setup();
      ReferenceRun reference;
      reference.finest_step = finest_step;
      while (!problem.finished())
        {
          const double j = problem.advance().time / finest_step;
          if (std::abs(j - std::round(j)) < 1e-6)
            {
              reference.u.push_back(problem.state().displacement);
              reference.w.push_back(problem.state().velocity);
            }
        }
      return reference;
    }

    /**
     * Run one level with parameters @p p: every step's errors on the mesh
     * it ran on (against @p reference if given, else against the
     * manufactured solution), then (if due) an adaptation of the mesh as
     * in run().
     */
    template <int dim>
    LevelResult
    run_level(const Parameters   &p,
              ParameterHandler   &prm,
              MPI_Comm            comm,
              const bool          check_smoothness,
              const ReferenceRun *reference)
    {
      Timer                           wall;
      const ContactLaws               laws = create_contact_laws(prm);
      const ManufacturedSolution<dim> exact(p, *laws.normal, *laws.friction);
      ContactProblem<dim>             problem(p,
                                  create_contact_laws(prm),
                                  exact.make_problem_data(),
                                  comm);
      problem.setup();
      if (check_smoothness)
        {
          const std::string jump = find_manufactured_jump(
            exact,
            problem.state().dof_handler.get_triangulation(),
            p.time.end_time,
            comm);
          if (!jump.empty() && Utilities::MPI::this_mpi_process(comm) == 0)
            std::cerr
              << "hemicontact: warning: the manufactured solution is not "
                 "smooth: "
              << jump
              << ". Its body force and tractions come from symbolic "
                 "derivatives, which miss the singular part of a jump, and "
                 "the error orders assume u, w and their gradients "
                 "continuous in x and t (doc/verification.md); expect "
                 "orders that do not reach 1."
              << std::endl;
        }
      IndexSet relevant =
        DoFTools::extract_locally_relevant_dofs(problem.state().dof_handler);
      const std::unique_ptr<SpatialCache> cache = exact.make_fields_cache();
      LevelSums                           sums;
      Timer                               steps_wall;
      while (!problem.finished())
        {
          StepStatistics s = problem.advance();
          sums.add(
            s,
            reference ?
              reference_step_errors(
                problem, *reference, s.time, relevant, comm) :
              step_errors(problem, exact, s.time, relevant, *cache, comm),
            problem.state().time_step);
          if (adaptation_due(problem.state()))
            {
              problem.adapt_mesh(s);
              relevant = DoFTools::extract_locally_relevant_dofs(
                problem.state().dof_handler);
            }
        }
      const double step_wall_seconds = steps_wall.wall_time();
      LevelResult  result            = sums.result();
      result.step_wall_seconds       = step_wall_seconds;
      result.h            = mesh_size(problem.state().dof_handler, comm);
      result.k            = problem.state().time_step;
      result.n_dofs       = problem.state().dof_handler.n_dofs();
      result.wall_seconds = wall.wall_time();
      return result;
    }

  } // namespace

  namespace
  {
    /** The spelling of @p type in the parameter file. */
    std::string
    name_of(const StudyType type)
    {
      switch (type)
        {
          case StudyType::h:
            return "h";
          case StudyType::k:
            return "k";
          case StudyType::coupled:
            return "coupled";
          default:
            return "single";
        }
    }
  } // namespace

  Parameters
  study_parameters(const Parameters &parameters, const unsigned int level)
  {
    Parameters      p    = parameters;
    const StudyType type = parameters.study.type;
    if (type == StudyType::h || type == StudyType::coupled)
      {
        p.geometry.global_refinements += level;
        if (p.adaptivity.interval > 0)
          {
            // the adaptive mesh may grow as the uniform one does
            p.adaptivity.max_level += level;
            p.adaptivity.max_cells = static_cast<unsigned int>(
              std::min(std::ldexp(double(p.adaptivity.max_cells),
                                  parameters.dimension * level),
                       double(std::numeric_limits<unsigned int>::max())));
          }
      }
    if (type == StudyType::k || type == StudyType::coupled)
      p.time.time_step /= std::pow(2., level);
    return p;
  }

  template <int dim>
  std::vector<LevelResult>
  run_convergence_study(const Parameters &parameters,
                        ParameterHandler &prm,
                        MPI_Comm          comm)
  {
    const bool root = Utilities::MPI::this_mpi_process(comm) == 0;
    const bool verbose =
      root && parameters.output.terminal != TerminalOutput::quiet;
    const StudyType    type = parameters.study.type;
    const unsigned int n_levels =
      type == StudyType::single ? 1 : parameters.study.n_levels;
    const bool adaptive = parameters.adaptivity.interval > 0;
    // a 'k' study keeps its orders per halving of k
    const bool against_dofs =
      adaptive && (type == StudyType::h || type == StudyType::coupled);

    // convergence.csv is replaced (atomically) after each level: an
    // earlier study's file stays until this one has a row of its own
    convergence_report::require_writable_csv(parameters, comm);
    std::string csv = convergence_report::csv_header();

    // a 'k' study against a reference run on its mesh: the reference first
    std::unique_ptr<ReferenceRun> reference;
    const double reference_step = parameters.study.reference_time_step;
    if (reference_step > 0)
      {
        Timer      wall;
        Parameters p      = parameters;
        p.time.time_step  = reference_step;
        p.output.terminal = TerminalOutput::quiet;
        reference         = std::make_unique<ReferenceRun>(run_reference<dim>(
          p,
          prm,
          comm,
          study_parameters(parameters, n_levels - 1).time.time_step));
        if (verbose)
          std::cout << "reference: time step " << reference_step
                    << " on the mesh of every level (" << std::fixed
                    << std::setprecision(1) << wall.wall_time()
                    << std::defaultfloat
                    << " s); the errors are those against it" << std::endl;
      }

    std::vector<LevelResult> results;
    ConvergenceTable         table;
    for (unsigned int level = 0; level < n_levels; ++level)
      {
        Parameters p      = study_parameters(parameters, level);
        p.output.terminal = TerminalOutput::quiet;
        results.push_back(
          run_level<dim>(p, prm, comm, level == 0, reference.get()));
        convergence_report::add_table_row(table,
                                          level,
                                          results.back(),
                                          adaptive);
        csv += convergence_report::csv_row(level, results.back());
        throw_if_any(root ? write_atomically(parameters.output.directory +
                                               "/convergence.csv",
                                             csv) :
                            "",
                     comm);
        if (verbose)
          convergence_report::print_branch_shares(level, results.back());
      }

    convergence_report::format_table(table,
                                     n_levels,
                                     against_dofs,
                                     parameters.output.error_estimate,
                                     results.back().time_estimated,
                                     results.back().with_temperature);
    if (verbose)
      {
        if (against_dofs)
          std::cout << "convergence study '" << name_of(type)
                    << "', adaptive (orders: "
                    << "-log(error ratio)/log(mean dofs ratio) between "
                    << "levels; O(h) is " << 1. / dim << ")\n";
        else
          std::cout << "convergence study '" << name_of(type)
                    << "' (orders: log2 of "
                    << "the error ratio between levels)\n";
        table.write_text(std::cout, TableHandler::org_mode_table);
      }
    return results;
  }

  template std::vector<LevelResult>
  run_convergence_study<2>(const Parameters &, ParameterHandler &, MPI_Comm);
  template std::vector<LevelResult>
  run_convergence_study<3>(const Parameters &, ParameterHandler &, MPI_Comm);
} // namespace hemicontact
