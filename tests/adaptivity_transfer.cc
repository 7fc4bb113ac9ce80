// Mesh adaptation moves w_n and u_n to the new mesh with
// parallel::distributed::SolutionTransfer. Fields that lie in the finite
// element space (here w = (x, 2x + xy), u = (x/2, -x), bilinear, zero on the
// clamped side x = 0) must survive refinement and coarsening exactly: after
// each of three adaptations (a fixed number of cells refined and coarsened)
// the transferred fields equal the interpolants on the new mesh.
#include <deal.II/base/function_parser.h>
#include <deal.II/numerics/vector_tools.h>

#include <hemicontact/input/parameters.h>
#include <hemicontact/problem/contact_problem.h>

#include "tests.h"

using namespace hemicontact;

namespace
{
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
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const std::string                text = R"(
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
  set initial velocity     = x; 2*x + x*y
  set initial displacement = x/2; -x
end
subsection adaptivity
  set interval         = 1
  set strategy         = fixed number
  set refine fraction  = 0.3
  set coarsen fraction = 0.3
  set min level        = 1
end
subsection output
  set terminal = quiet
end
)";
  ParameterHandler                 prm;
  const Parameters  parameters = read_parameters_from_string(prm, text);
  ContactProblem<2> problem(parameters,
                            create_contact_laws(prm),
                            MPI_COMM_WORLD);
  problem.setup();

  const auto &tria = problem.state().dof_handler.get_triangulation();
  for (unsigned int cycle = 0; cycle < 3; ++cycle)
    {
      StepStatistics stats;
      problem.adapt_mesh(stats);
      unsigned int coarser = 0, finer = 0;
      for (const auto &cell : tria.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            coarser += (cell->level() < 3);
            finer += (cell->level() > 3);
          }
      coarser = Utilities::MPI::sum(coarser, MPI_COMM_WORLD);
      finer   = Utilities::MPI::sum(finer, MPI_COMM_WORLD);
      const double dw =
        max_difference(problem, problem.state().velocity, "x; 2*x + x*y");
      const double du =
        max_difference(problem, problem.state().displacement, "x/2; -x");
      out() << "adaptation " << cycle + 1 << ": cells coarser than "
            << "the start: " << (coarser > 0 ? "yes" : "no")
            << ", finer: " << (finer > 0 ? "yes" : "no")
            << "; w transferred exactly: " << (dw < 1e-12 ? "yes" : "no")
            << ", u transferred exactly: " << (du < 1e-12 ? "yes" : "no")
            << "; stored energy unchanged: "
            << (std::abs(stats.kinetic_after_adaptation +
                         stats.elastic_after_adaptation -
                         stats.kinetic_before_adaptation -
                         stats.elastic_before_adaptation) <
                    1e-12 * stats.kinetic_before_adaptation ?
                  "yes" :
                  "no")
            << "\n";
    }
}
