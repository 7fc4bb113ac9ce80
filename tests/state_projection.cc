// 'adaptivity/state transfer = projection' (source/problem/state_projection.cc)
// keeps the data of the next step, rho M w_n and B u_{n+1} with
// u_{n+1} = u_n + k w_n, as functionals on the new mesh.
//
// 1. Fields that are not in the finite element space (w, u smooth, zero on
//    the clamped side x = 0), three adaptations that only coarsen (min
//    level 1): for test functions v in both the old and the new space
//    (bilinear on the whole block, zero at x = 0), int rho w.v and
//    a_B(u_{n+1}, v) must be the same before and after, and the stored
//    energy must not grow (orthogonal projections). With 'interpolation'
//    the same integrals change: the check can fail.
// 2. Fields in the space (as tests/adaptivity_transfer.cc) survive refinement
//    and coarsening together unchanged.
#include <deal.II/base/function_parser.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/numerics/vector_tools.h>

#include <hemicontact/input/parameters.h>
#include <hemicontact/model/kelvin_voigt.h>
#include <hemicontact/problem/contact_problem.h>

#include "tests.h"

using namespace hemicontact;

namespace
{
  const std::string test_functions[] = {"x; 0",
                                        "0; x",
                                        "x*y; 0",
                                        "0; x*y",
                                        "x*y; x"};

  /** int rho w.v and a_B(u + k w, v) for each of the test functions v. */
  std::vector<double>
  functionals(const ContactProblem<2> &problem, const Parameters &parameters)
  {
    const KelvinVoigtMaterial<2>  material(parameters.material);
    const DoFHandler<2>          &dofs = problem.state().dof_handler;
    TrilinosWrappers::MPI::Vector w, u_next;
    const IndexSet relevant = DoFTools::extract_locally_relevant_dofs(dofs);
    w.reinit(dofs.locally_owned_dofs(), relevant, MPI_COMM_WORLD);
    u_next.reinit(w);
    TrilinosWrappers::MPI::Vector sum(problem.state().displacement);
    sum.add(problem.state().time_step, problem.state().velocity);
    w      = problem.state().velocity;
    u_next = sum;

    std::vector<double> result;
    for (const std::string &expression : test_functions)
      {
        FunctionParser<2> v(2);
        v.initialize("x,y", expression, {});
        FEValues<2> fe_values(*problem.state().discretization.mapping,
                              dofs.get_fe(),
                              QGauss<2>(3),
                              update_values | update_gradients |
                                update_quadrature_points | update_JxW_values);
        const FEValuesExtractors::Vector   field(0);
        std::vector<Tensor<1, 2>>          w_q(fe_values.n_quadrature_points);
        std::vector<SymmetricTensor<2, 2>> eps_u(fe_values.n_quadrature_points);
        double                             mass = 0, elastic = 0;
        for (const auto &cell : dofs.active_cell_iterators())
          if (cell->is_locally_owned())
            {
              fe_values.reinit(cell);
              fe_values[field].get_function_values(w, w_q);
              fe_values[field].get_function_symmetric_gradients(u_next, eps_u);
              for (const unsigned int q : fe_values.quadrature_point_indices())
                {
                  const Point<2> &p = fe_values.quadrature_point(q);
                  Tensor<1, 2>    v_q;
                  Tensor<2, 2>    grad_v;
                  for (unsigned int c = 0; c < 2; ++c)
                    {
                      v_q[c]    = v.value(p, c);
                      grad_v[c] = v.gradient(p, c);
                    }
                  mass +=
                    material.density() * (w_q[q] * v_q) * fe_values.JxW(q);
                  elastic += material.elastic_stress(eps_u[q]) *
                             symmetrize(grad_v) * fe_values.JxW(q);
                }
            }
        result.push_back(Utilities::MPI::sum(mass, MPI_COMM_WORLD));
        result.push_back(Utilities::MPI::sum(elastic, MPI_COMM_WORLD));
      }
    return result;
  }

  std::string
  settings(const std::string &transfer,
           const std::string &w,
           const std::string &u,
           const std::string &refine)
  {
    return R"(
set dimension = 2
subsection geometry
  set upper right corner = 4, 1
  set subdivisions       = 4, 1
  set global refinements = 3
end
subsection boundary
  set clamped boundary ids  = 0
  set traction boundary ids = 3
  set contact boundary ids  = 2
end
subsection data
  set initial velocity     = )" +
           w + R"(
  set initial displacement = )" +
           u + R"(
end
subsection adaptivity
  set interval         = 1
  set strategy         = fixed number
  set refine fraction  = )" +
           refine + R"(
  set coarsen fraction = 0.3
  set min level        = 1
  set state transfer   = )" +
           transfer + R"(
end
subsection output
  set terminal = quiet
end
)";
  }

  void
  coarsen_smooth_fields(const std::string &transfer)
  {
    ParameterHandler prm;
    const Parameters parameters =
      read_parameters_from_string(prm,
                                  settings(transfer,
                                           "sin(3*x)*(1+y*y); x*cos(2*y)",
                                           "x*exp(y)/4; sin(x)",
                                           "0"));
    ContactProblem<2> problem(parameters,
                              create_contact_laws(prm),
                              MPI_COMM_WORLD);
    problem.setup();
    const std::vector<double> before     = functionals(problem, parameters);
    double                    max_change = 0, scale = 0;
    bool                      energy_grew = false;
    const auto &tria         = problem.state().dof_handler.get_triangulation();
    const auto  cells_before = tria.n_global_active_cells();
    for (unsigned int cycle = 0; cycle < 3; ++cycle)
      {
        StepStatistics stats;
        problem.adapt_mesh(stats);
        const std::vector<double> after = functionals(problem, parameters);
        for (unsigned int i = 0; i < after.size(); ++i)
          {
            max_change = std::max(max_change, std::abs(after[i] - before[i]));
            scale      = std::max(scale, std::abs(before[i]));
          }
        energy_grew =
          energy_grew ||
          stats.kinetic_after_adaptation > stats.kinetic_before_adaptation ||
          stats.elastic_after_adaptation > stats.elastic_before_adaptation;
      }
    out()
      << transfer << ", coarsening only: " << cells_before << " -> "
      << tria.n_global_active_cells()
      << " cells in 3 adaptations; int rho w.v and a_B(u_{n+1}, v) kept (to 1e-8 "
      << "relative): " << (max_change < 1e-8 * scale ? "yes" : "no")
      << "; stored energy grew: " << (energy_grew ? "yes" : "no") << "\n";
  }

  double
  max_difference(const ContactProblem<2>             &problem,
                 const TrilinosWrappers::MPI::Vector &field,
                 const std::string                   &expression)
  {
    FunctionParser<2> exact(2);
    exact.initialize("x,y", expression, {});
    TrilinosWrappers::MPI::Vector interpolant(field);
    VectorTools::interpolate(*problem.state().discretization.mapping,
                             problem.state().dof_handler,
                             exact,
                             interpolant);
    interpolant -= field;
    return interpolant.linfty_norm();
  }

  void
  fields_in_the_space()
  {
    ParameterHandler prm;
    const Parameters parameters = read_parameters_from_string(
      prm, settings("projection", "x; 2*x + x*y", "x/2; -x", "0.3"));
    ContactProblem<2> problem(parameters,
                              create_contact_laws(prm),
                              MPI_COMM_WORLD);
    problem.setup();
    double max_dw = 0, max_du = 0;
    for (unsigned int cycle = 0; cycle < 3; ++cycle)
      {
        StepStatistics stats;
        problem.adapt_mesh(stats);
        max_dw = std::max(max_dw,
                          max_difference(problem,
                                         problem.state().velocity,
                                         "x; 2*x + x*y"));
        max_du = std::max(max_du,
                          max_difference(problem,
                                         problem.state().displacement,
                                         "x/2; -x"));
      }
    out() << "projection, refining and coarsening: fields in the space "
          << "unchanged (to 1e-8): w " << (max_dw < 1e-8 ? "yes" : "no")
          << ", u " << (max_du < 1e-8 ? "yes" : "no") << "\n";
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  coarsen_smooth_fields("projection");
  coarsen_smooth_fields("interpolation");
  fields_in_the_space();
}
