#include <deal.II/base/mpi.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/lac/trilinos_sparsity_pattern.h>
#include <deal.II/numerics/vector_tools.h>

#include <hemicontact/base/exceptions.h>
#include <hemicontact/fields/coupled_field_registry.h>
#include <hemicontact/problem/contact_node_setup.h>
#include <hemicontact/problem/contact_problem.h>
#include <hemicontact/problem/stability.h>
#include <hemicontact/problem/wall_admissibility.h>

#include <cmath>
#include <map>

namespace hemicontact
{
  template <int dim>
  ContactProblem<dim>::ContactProblem(const Parameters &parameters,
                                      ContactLaws       laws,
                                      MPI_Comm          comm)
    : ContactProblem(parameters,
                     std::move(laws),
                     make_problem_data<dim>(parameters.data),
                     comm)
  {}

  template <int dim>
  ContactProblem<dim>::ContactProblem(const Parameters &parameters,
                                      ContactLaws       laws,
                                      ProblemData<dim>  data,
                                      MPI_Comm          comm)
    : mpi_communicator(comm)
    , parameters(parameters)
    , pcout(std::cout, terminal_output_on(parameters, comm))
    , timer(pcout, TimerOutput::never, TimerOutput::wall_times)
    , material(
        StepScheme(parameters.problem).class_material(parameters.material))
    , scheme(parameters.problem)
    , law(std::move(laws.normal))
    , friction(std::move(laws.friction))
    , data(std::move(data))
    , memory(parameters.relaxation,
             parameters.normal_memory,
             parameters.wear,
             parameters.data.constants,
             comm)
    , discretization(parameters.geometry, comm)
    , dof_handler(*discretization.triangulation)
    , linear_solver(parameters.linear_solver, comm)
    , preconditioner(parameters.solver_tuning, comm)
  {
    AssertThrow(dim == parameters.dimension,
                ExcMessage("ContactProblem<dim> built for another dimension."));
    n_steps   = std::max<unsigned int>(1,
                                     static_cast<unsigned int>(std::llround(
                                       parameters.time.end_time /
                                       parameters.time.time_step)));
    time_step = parameters.time.end_time / n_steps;
    require(!(scheme.is_static() &&
              this->data.friction_bound->uses_normal_velocity()),
            "data: 'friction bound' uses w_nu, the normal velocity, which the "
            "static class does not have (the laws act on the displacement); "
            "write the bound in u_nu.");
    // the slip a bound in s_tau reads (doc/theory.md, section 11.10)
    if (this->data.friction_bound->uses_slip())
      memory.measure_slip(scheme.is_static());
    // the wear of the foundation (section 11.12)
    memory.set_static_class(scheme.is_static());
    // the coupled fields the parameters enable, each a field of the state
    // (the temperature, section 13)
    std::vector<std::string> taken;
    for (const StateField<dim> &f : state_fields({}))
      taken.push_back(f.name);
    create_coupled_fields<dim>(
      {parameters, scheme.is_static(), this->data, comm},
      discretization.is_simplex(),
      added_fields,
      taken,
      coupled_fields);
  }

  template <int dim>
  void
  ContactProblem<dim>::setup()
  {
    TimerOutput::Scope t(timer, "setup");
    discretization.make_mesh(parameters.geometry);
    discretization.check_boundary_ids(parameters.boundary);
    setup_on_current_mesh();
    initialize_state();
    memory_rule_unstable =
      check_time_step_limits(state(), preconditioner, timer);
    check_convexity();
  }

  template <int dim>
  void
  ContactProblem<dim>::setup_on_current_mesh()
  {
    dof_handler.distribute_dofs(*discretization.fe);
    locally_owned_dofs = dof_handler.locally_owned_dofs();
    locally_relevant_dofs =
      DoFTools::extract_locally_relevant_dofs(dof_handler);

    // hanging nodes and u = 0 on Gamma_1
    base_constraints.clear();
    base_constraints.reinit(locally_relevant_dofs);
    DoFTools::make_hanging_node_constraints(dof_handler, base_constraints);
    const Functions::ZeroFunction<dim>                  zero(dim);
    std::map<types::boundary_id, const Function<dim> *> clamped;
    for (const unsigned int id : parameters.boundary.clamped_ids)
      clamped[id] = &zero;
    VectorTools::interpolate_boundary_values(*discretization.mapping,
                                             dof_handler,
                                             clamped,
                                             base_constraints);
    base_constraints.close();

    TrilinosWrappers::SparsityPattern sparsity(locally_owned_dofs,
                                               locally_owned_dofs,
                                               locally_relevant_dofs,
                                               mpi_communicator);
    DoFTools::make_sparsity_pattern(dof_handler,
                                    sparsity,
                                    base_constraints,
                                    /*keep_constrained_dofs=*/true,
                                    Utilities::MPI::this_mpi_process(
                                      mpi_communicator));
    sparsity.compress();
    for (TrilinosWrappers::SparseMatrix *m :
         {&mass_matrix, &step_matrix, &elastic_matrix})
      m->reinit(sparsity);

    for (TrilinosWrappers::MPI::Vector *v : {&velocity,
                                             &old_velocity,
                                             &displacement,
                                             &load,
                                             &step_rhs,
                                             &contact_traction})
      v->reinit(locally_owned_dofs, mpi_communicator);

    displacement_space = {"displacement",
                          &dof_handler,
                          &locally_owned_dofs,
                          &locally_relevant_dofs,
                          &base_constraints};
    added_fields.reinit(*discretization.triangulation, mpi_communicator);
    assemble_constant_matrices(scheme.step_matrix(time_step));
    contact_nodes = collect_contact_nodes(state());
    // a convexity check covers its own nodes
    convexity.checked_alpha_tau.clear();
    update_friction_bounds(step_number * time_step);
    unsigned int n_owned = 0;
    for (const auto &node : contact_nodes)
      n_owned += node.locally_owned;
    require(Utilities::MPI::sum(n_owned, mpi_communicator) > 0,
            "boundary: the contact boundary Gamma_3 has no free node (every "
            "node is clamped); check 'contact boundary ids'.");
    coupled_fields.reinit(added_fields, mechanical_view(state()));
    preconditioner.reinit(dof_handler, *discretization.mapping);
    memory.reinit(dof_handler,
                  *discretization.mapping,
                  discretization.cell_quadrature(2),
                  base_constraints,
                  locally_owned_dofs,
                  locally_relevant_dofs,
                  contact_nodes);
  }

  template <int dim>
  double
  ContactProblem<dim>::update_friction_bounds(
    const double                         t,
    const TrilinosWrappers::MPI::Vector *traction)
  {
    const FrictionBound<dim> &bound = *data.friction_bound;
    // the static class's u is its step's unknown (doc/theory.md 9.1)
    TrilinosWrappers::MPI::Vector u, w, p, s;
    if (bound.uses_slip())
      {
        // zero before the memory has its vectors on this mesh (the bounds
        // of setup_on_current_mesh(): no slip yet, or read again on resume)
        s.reinit(locally_owned_dofs, locally_relevant_dofs, mpi_communicator);
        if (memory.contact_memory().slip().size() == dof_handler.n_dofs())
          s = memory.contact_memory().slip();
      }
    if (bound.depends_on_state())
      {
        u.reinit(locally_owned_dofs, locally_relevant_dofs, mpi_communicator);
        w.reinit(locally_owned_dofs, locally_relevant_dofs, mpi_communicator);
        p.reinit(locally_owned_dofs, locally_relevant_dofs, mpi_communicator);
        u = scheme.is_static() ? velocity : displacement;
        w = velocity;
        p = traction != nullptr ? *traction : contact_traction;
      }
    // a bad value is reported by every rank, so that none waits for another
    // in the step that follows
    std::string error;
    double      largest = 0, change = 0;
    for (ContactNode<dim> &node : contact_nodes)
      {
        double u_nu = 0, w_nu = 0, p_nu = 0;
        if (bound.depends_on_state())
          for (unsigned int c = 0; c < dim; ++c)
            {
              u_nu += u[node.dofs[c]] * node.normal[c];
              w_nu += w[node.dofs[c]] * node.normal[c];
              p_nu += p[node.dofs[c]] * node.normal[c];
            }
        try
          {
            const double before = node.friction_bound;
            node.friction_bound =
              bound.value(node.position,
                          t,
                          u_nu,
                          w_nu,
                          p_nu,
                          bound.uses_slip() ? s[node.dofs[0]] : 0.);
            if (node.locally_owned)
              {
                largest = std::max(largest, node.friction_bound);
                change =
                  std::max(change, std::abs(node.friction_bound - before));
              }
          }
        catch (const InputError &e)
          {
            if (error.empty())
              error = e.what();
          }
      }
    for (const std::string &message :
         Utilities::MPI::all_gather(mpi_communicator, error))
      if (!message.empty())
        throw InputError(message);
    largest = Utilities::MPI::max(largest, mpi_communicator);
    change  = Utilities::MPI::max(change, mpi_communicator);
    return largest > 0 ? change / largest : 0.;
  }

  template <int dim>
  void
  ContactProblem<dim>::initialize_state()
  {
    ++state_revision;
    data.set_time(0);
    added_fields.initialize(*discretization.mapping);
    const auto interpolate_checked = [&](const Function<dim>           &f,
                                         TrilinosWrappers::MPI::Vector &v,
                                         const std::string             &name) {
      VectorTools::interpolate(*discretization.mapping, dof_handler, f, v);
      unsigned int n_not_finite = 0;
      for (const auto i : locally_owned_dofs)
        n_not_finite += !std::isfinite(v[i]);
      require(Utilities::MPI::sum(n_not_finite, mpi_communicator) == 0,
              "data: the " + name + " is not a finite number (NaN or Inf) at " +
                std::to_string(
                  Utilities::MPI::sum(n_not_finite, mpi_communicator)) +
                " nodal values; check its expression ('data/" + name +
                "', or 'manufactured solution/exact displacement').");
      double on_clamped = 0, largest = 0;
      for (const auto i : locally_owned_dofs)
        {
          largest = std::max(largest, std::abs(v[i]));
          if (base_constraints.is_constrained(i) &&
              base_constraints.get_constraint_entries(i)->empty())
            on_clamped = std::max(on_clamped, std::abs(v[i]));
        }
      on_clamped = Utilities::MPI::max(on_clamped, mpi_communicator);
      largest    = Utilities::MPI::max(largest, mpi_communicator);
      require(on_clamped <= 1e-12 * std::max(largest, 1.),
              "data: the " + name +
                " does not vanish on the clamped boundary "
                "Gamma_1 (value " +
                std::to_string(on_clamped) +
                " there); it must satisfy u = 0 on Gamma_1.");
      base_constraints.distribute(v);
    };
    if (scheme.is_static())
      {
        // no initial state: the first load value starts from u = 0
        // (doc/theory.md 9.2)
        velocity     = 0;
        displacement = 0;
      }
    else
      {
        interpolate_checked(*data.initial_velocity,
                            velocity,
                            "initial velocity");
        interpolate_checked(*data.initial_displacement,
                            displacement,
                            "initial displacement");
      }
    require_admissible_initial_state(state());
    old_velocity = velocity;
    step_number  = 0;
    // no contact pressure before the first step (doc/theory.md 9.9)
    contact_traction = 0;
    update_friction_bounds(0.);
    memory.clear();
    // the coupled fields at t = 0, before the initial solves read their
    // loads (the electric potential phi_0 from u_0)
    coupled_fields.start(mechanical_view(state()),
                         linear_solver,
                         added_fields,
                         false);
    // the step problem at t = 0 with the right-hand side b that @p set_rhs
    // sets from the load F_0, solved from w = 0 by the step solver
    const auto solve_initial_problem = [&](const auto        &set_rhs,
                                           const std::string &what) {
      assemble_load(0.);
      set_rhs();
      base_constraints.set_zero(step_rhs);
      velocity = 0;
      try
        {
          solve_with_bound(0., nullptr, time_step, true);
        }
      catch (const SolverFailure &failure)
        {
          throw SolverFailure(what + " failed: " + failure.what());
        }
      old_velocity = velocity;
    };
    if (scheme.is_static() && memory.active())
      {
        // u_0, the first state of the memory sum, is the solution of load
        // value 0 (M_0 = 0: the problem without memory; doc/theory.md,
        // section 11)
        solve_initial_problem([&]() { step_rhs = load; },
                              "the initial displacement u_0 of the static "
                              "class with memory (the problem of load value "
                              "t = 0, doc/theory.md section 11)");
        scheme.displacement_after_step(displacement, velocity, time_step);
      }
    if (scheme.initial_velocity_from_step())
      {
        // doc/theory.md, section 9.2: the equation at t_0 with the data u_0,
        // K = A and b = F_0 - B u_0
        const bool other_matrix =
          !(scheme.initial_matrix() == scheme.step_matrix(time_step));
        if (other_matrix)
          {
            assemble_constant_matrices(scheme.initial_matrix());
            preconditioner.clear();
          }
        solve_initial_problem(
          [&]() {
            scheme.initial_rhs(elastic_matrix, displacement, load, step_rhs);
          },
          "the initial velocity w_0 of the quasistatic class (the step "
          "problem at t = 0 with the initial displacement, doc/theory.md "
          "section 9.2)");
        if (other_matrix)
          {
            assemble_constant_matrices(scheme.step_matrix(time_step));
            preconditioner.clear();
          }
      }
    energy = EnergyBalance();
    update_energy_balance(/*initial=*/true);
  }

#define HEMICONTACT_INSTANTIATE(dim)                               \
  template ContactProblem<dim>::ContactProblem(const Parameters &, \
                                               ContactLaws,        \
                                               MPI_Comm);          \
  template ContactProblem<dim>::ContactProblem(const Parameters &, \
                                               ContactLaws,        \
                                               ProblemData<dim>,   \
                                               MPI_Comm);          \
  template double ContactProblem<dim>::update_friction_bounds(     \
    const double, const TrilinosWrappers::MPI::Vector *);          \
  template void ContactProblem<dim>::setup();                      \
  template void ContactProblem<dim>::setup_on_current_mesh();      \
  template void ContactProblem<dim>::initialize_state();

  HEMICONTACT_INSTANTIATE(2)
  HEMICONTACT_INSTANTIATE(3)
#undef HEMICONTACT_INSTANTIATE
} // namespace hemicontact
