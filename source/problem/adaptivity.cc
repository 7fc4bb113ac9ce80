#include <deal.II/distributed/solution_transfer.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/grid/grid_refinement.h>
#include <deal.II/numerics/error_estimator.h>

#include <hemicontact/mesh/marking.h>
#include <hemicontact/problem/error_indicators.h>
#include <hemicontact/problem/stability.h>
#include <hemicontact/problem/state_projection.h>
#include <hemicontact/problem/wall_admissibility.h>
#include <hemicontact/state/field_transfer.h>

#include <cmath>
#include <limits>
#include <set>
#include <vector>

namespace hemicontact
{
  template <int dim>
  Vector<float>
  refinement_indicators(const ContactProblem<dim> &problem)
  {
    const ProblemState<dim>     state    = problem.state();
    const AdaptivityParameters &settings = state.parameters.adaptivity;
    if (settings.indicator == RefinementIndicator::residual)
      return residual_indicators(problem);
    if (settings.indicator == RefinementIndicator::estimator)
      return problem.error_estimate().cell_values();
    const Discretization<dim>    &discretization = state.discretization;
    const DoFHandler<dim>        &dof_handler    = state.dof_handler;
    TrilinosWrappers::MPI::Vector w(state.locally_owned_dofs,
                                    state.locally_relevant_dofs,
                                    state.mpi_communicator);
    w = state.velocity;
    Vector<float> indicators(discretization.triangulation->n_active_cells());
    KellyErrorEstimator<dim>::estimate(
      *discretization.mapping,
      dof_handler,
      discretization.face_quadrature(2),
      {},
      w,
      indicators,
      ComponentMask(),
      nullptr,
      numbers::invalid_unsigned_int,
      discretization.triangulation->locally_owned_subdomain());
    if (settings.indicator != RefinementIndicator::kelly_contact)
      return indicators;

    // the jumps of the nodal contact traction along Gamma_3, face by face
    TrilinosWrappers::MPI::Vector t(w);
    t = state.contact_traction;
    std::set<types::global_dof_index> is_contact_node;
    for (const ContactNode<dim> &node : state.contact_nodes)
      is_contact_node.insert(node.dofs[0]);
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        for (const unsigned int f : cell->face_indices())
          if (cell->face(f)->at_boundary() &&
              state.parameters.boundary.part(cell->face(f)->boundary_id()) ==
                BoundaryPart::contact)
            {
              const auto        &face  = cell->face(f);
              double             jumps = 0;
              const unsigned int n     = face->n_vertices();
              for (unsigned int a = 0; a < n; ++a)
                for (unsigned int b = a + 1; b < n; ++b)
                  {
                    const auto da = face->vertex_dof_index(a, 0);
                    const auto db = face->vertex_dof_index(b, 0);
                    if (!is_contact_node.count(da) ||
                        !is_contact_node.count(db))
                      continue;
                    for (unsigned int c = 0; c < dim; ++c)
                      jumps += std::pow(t[face->vertex_dof_index(a, c)] -
                                          t[face->vertex_dof_index(b, c)],
                                        2);
                  }
              const double contact =
                settings.contact_weight * std::sqrt(face->diameter() * jumps);
              const unsigned int i = cell->active_cell_index();
              indicators[i] =
                std::sqrt(std::pow(indicators[i], 2) + contact * contact);
            }
    return indicators;
  }

  template <int dim>
  void
  ContactProblem<dim>::adapt_mesh(StepStatistics &stats)
  {
    TimerOutput::Scope          t(timer, "adaptivity");
    const AdaptivityParameters &settings = parameters.adaptivity;
    auto *tria = dynamic_cast<parallel::distributed::Triangulation<dim> *>(
      discretization.triangulation.get());
    AssertThrow(tria != nullptr,
                ExcMessage("adaptivity needs a p4est (hypercube) mesh"));

    const StoredEnergy before       = stored_energy(state());
    stats.kinetic_before_adaptation = before.kinetic;
    stats.elastic_before_adaptation = before.elastic;
    // mark: thresholds from all indicators, sorted, so the same on any
    // number of ranks (see marking_thresholds())
    const Vector<float> indicators = refinement_indicators(*this);
    std::vector<float>  owned;
    for (const auto &cell : tria->active_cell_iterators())
      if (cell->is_locally_owned())
        owned.push_back(indicators[cell->active_cell_index()]);
    std::vector<float> all;
    for (const std::vector<float> &part :
         Utilities::MPI::all_gather(mpi_communicator, owned))
      all.insert(all.end(), part.begin(), part.end());
    const types::global_cell_index n_cells = all.size();
    const types::global_cell_index max_cells =
      settings.max_cells > 0 ?
        settings.max_cells :
        std::numeric_limits<types::global_cell_index>::max();
    double refine_fraction  = settings.refine_fraction;
    double coarsen_fraction = settings.coarsen_fraction;
    if (settings.strategy == MarkingStrategy::fixed_number)
      std::tie(refine_fraction, coarsen_fraction) =
        GridRefinement::adjust_refine_and_coarsen_number_fraction<dim>(
          n_cells, max_cells, refine_fraction, coarsen_fraction);
    else if (n_cells >= max_cells)
      refine_fraction = 0;
    MarkingThresholds thresholds = marking_thresholds(all,
                                                      settings.strategy,
                                                      refine_fraction,
                                                      coarsen_fraction);
    // fixed fraction under a cell budget: refine at most the cells that
    // keep the count within it (each refined cell adds 2^dim - 1), the
    // largest indicators first
    if (settings.strategy == MarkingStrategy::fixed_fraction &&
        settings.max_cells > 0)
      {
        const types::global_cell_index room =
          n_cells < max_cells ?
            (max_cells - n_cells) /
              (GeometryInfo<dim>::max_children_per_cell - 1) :
            0;
        const auto n_marked = static_cast<types::global_cell_index>(
          std::count_if(all.begin(), all.end(), [&](const float indicator) {
            return indicator > thresholds.refine;
          }));
        if (n_marked > room)
          thresholds.refine =
            marking_thresholds(all,
                               MarkingStrategy::fixed_number,
                               static_cast<double>(room) / n_cells,
                               0.)
              .refine;
      }
    for (const auto &cell : tria->active_cell_iterators())
      if (cell->is_locally_owned())
        {
          const double indicator = indicators[cell->active_cell_index()];
          const int    level     = cell->level();
          if (indicator > thresholds.refine &&
              level < static_cast<int>(settings.max_level))
            cell->set_refine_flag();
          else if (indicator < thresholds.coarsen &&
                   level > static_cast<int>(settings.min_level))
            cell->set_coarsen_flag();
        }

    // move the state's transferred fields (state_fields.cc: w_n, u_n, the
    // contact traction, the memory's history, the added fields) by
    // interpolation; w_{n-1} of the next step is w_n, the branches are
    // recomputed in its first Newton iteration. 'projection' moves
    // u_{n+1} = u_n + k w_n instead of u_n and keeps the functionals of
    // coarsened cells (state_projection.cc)
    const bool project = settings.state_transfer == StateTransfer::projection;
    const std::vector<double>      history_values = memory.saved_values();
    FieldTransfer<dim>             transfer(fields());
    TrilinosWrappers::MPI::Vector &w = transfer.old_field("velocity");
    TrilinosWrappers::MPI::Vector &u = transfer.old_field("displacement");
    if (project)
      {
        // the displacement held after the step (StepScheme): u_n + k w_n
        // for the left point, u_n for the implicit rule
        TrilinosWrappers::MPI::Vector u_next(displacement);
        u_next.add(scheme.held_displacement_offset(time_step), velocity);
        u = u_next;
      }
    tria->prepare_coarsening_and_refinement();
    transfer.prepare();
    const unsigned int functionals =
      project ? attach_coarsened_functionals(state(), w, u) : 0;
    tria->execute_coarsening_and_refinement();
    // fixed fraction keeps the budget of its marks; the 2:1 balance may
    // refine beyond it: say so with the count
    if (settings.strategy == MarkingStrategy::fixed_fraction &&
        settings.max_cells > 0 &&
        tria->n_global_active_cells() > settings.max_cells)
      pcout << "  adaptation: " << tria->n_global_active_cells()
            << " cells, above 'adaptivity/max cells' = " << settings.max_cells
            << " by the cells the mesh's 2:1 balance refined with the marked "
               "ones"
            << std::endl;

    // rebuild everything that lives on the mesh, then the state on it
    setup_on_current_mesh();
    ++state_revision;
    const std::vector<StateField<dim>> new_fields =
      state_fields(memory.restore(history_values));
    transfer.interpolate(new_fields);
    // (before the hanging-node values are distributed: a kept cell next to
    // a coarsened one still holds the old field there)
    if (project)
      project_transferred_state(state(),
                                linear_solver,
                                preconditioner,
                                functionals,
                                velocity,
                                displacement);
    distribute_constraints(new_fields);
    if (project)
      displacement.add(-scheme.held_displacement_offset(time_step),
                       velocity); // u_n = u_{n+1} - k w_n (left point)
    // a projection can overshoot the wall (doc/theory.md 10.2)
    const auto [n_moved, largest_move] =
      move_state_onto_wall(state(), displacement);
    if (n_moved > 0)
      pcout << "  adaptation: the transferred state crossed the wall "
            << (memory.contact_memory().wear_active() ?
                  "(g + the wear depth) " :
                  "")
            << "at " << n_moved << " contact nodes (by up to " << largest_move
            << "); moved back onto it" << std::endl;
    old_velocity = velocity;

    const StoredEnergy after       = stored_energy(state());
    stats.kinetic_after_adaptation = after.kinetic;
    stats.elastic_after_adaptation = after.elastic;
    stats.adapted                  = true;
    after.book_into(energy);
    energy.transfer_change += after.change_from(before);
    // a finer mesh may have a smaller stability limit
    memory_rule_unstable =
      check_time_step_limits(state(), preconditioner, timer);
  }

  template Vector<float>
  refinement_indicators(const ContactProblem<2> &);
  template Vector<float>
  refinement_indicators(const ContactProblem<3> &);
  template void
  ContactProblem<2>::adapt_mesh(StepStatistics &);
  template void
  ContactProblem<3>::adapt_mesh(StepStatistics &);
} // namespace hemicontact
