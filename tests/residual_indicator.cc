// The residual indicator ('adaptivity/indicator = residual') of a state
// whose exact values are known, on the 4 x 1 block with 32 x 8 cells
// (h = 1/8), mu = 2, lambda = 3, w = w_{n-1} = 0, no contact traction yet:
//
// 1. u = (x y, 0) is bilinear, so the discrete stress is the exact one,
//    sigma = [[7y, 2x], [2x, 3y]], continuous, with div sigma = (0, 5).
//    With f0 = (0, -5) and f2, f3 = sigma nu on the right, top and contact
//    sides, every term vanishes, except that f3 has an extra (0, 1) for
//    x > 3: there eta_K = sqrt(h_F * h_F * 1) = h_F. The indicator drives
//    two adaptations (hanging faces), and the check is repeated on the new
//    mesh: the interior jumps across hanging faces must vanish too.
// 2. u = (0, 2x) for x < 2 and (0, 4) for x > 2 (a kink at x = 2): sigma_12
//    jumps by 2 mu = 4 there. An interior cell next to x = 2 has
//    eta_K^2 = 1/2 h_F |F| 16 = 8 h^2, every other interior cell 0.
#include <hemicontact/input/parameters.h>
#include <hemicontact/problem/error_indicators.h>

#include "tests.h"

using namespace hemicontact;

namespace
{
  const std::string common = R"(
set dimension = 2
subsection geometry
  set upper right corner = 4, 1
  set subdivisions       = 4, 1
  set global refinements = 3
end
subsection material
  subsection elasticity
    set mu     = 2
    set lambda = 3
  end
end
subsection output
  set terminal = quiet
end
)";

  /** Print whether every eta_K equals expected(cell) within 1e-6, with the
   *  numbers of cells with a hanging face and with a nonzero expectation. */
  template <typename Expected>
  void
  compare(const ContactProblem<2> &problem,
          const Expected          &expected,
          const std::string       &label)
  {
    const Vector<float> eta   = residual_indicators(problem);
    double              error = 0, largest = 0;
    unsigned int        nonzero = 0, hanging = 0;
    for (const auto &cell : problem.state().dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          const double e = expected(cell);
          error = std::max(error, std::abs(eta[cell->active_cell_index()] - e));
          largest = std::max(largest, e);
          nonzero += (e > 0);
          for (const unsigned int f : cell->face_indices())
            if (!cell->at_boundary(f) &&
                (cell->neighbor_is_coarser(f) || cell->face(f)->has_children()))
              {
                ++hanging;
                break;
              }
        }
    error   = Utilities::MPI::max(error, MPI_COMM_WORLD);
    largest = Utilities::MPI::max(largest, MPI_COMM_WORLD);
    nonzero = Utilities::MPI::sum(nonzero, MPI_COMM_WORLD);
    hanging = Utilities::MPI::sum(hanging, MPI_COMM_WORLD);
    out() << label << ": " << problem.state().dof_handler.n_dofs() << " dofs, "
          << hanging << " cells with a hanging face, " << nonzero
          << " cells expected nonzero (largest " << largest
          << "); indicators as expected (within 1e-6): "
          << (error < 1e-6 ? "yes" : "no") << "\n";
  }

  /** A set-up problem from the parameters @p text (and their normal law). */
  std::unique_ptr<ContactProblem<2>>
  set_up(const std::string &text)
  {
    ParameterHandler prm;
    const Parameters parameters = read_parameters_from_string(prm, text);
    auto             problem = std::make_unique<ContactProblem<2>>(parameters,
                                                       create_contact_laws(prm),
                                                       MPI_COMM_WORLD);
    problem->setup();
    return problem;
  }

  /** sqrt(h_F int_F (x - 3)^2) on the face of @p cell on y = 0 right of
   *  x = 3, else 0. */
  template <typename Cell>
  double
  expected_contact_term(const Cell &cell)
  {
    for (const unsigned int f : cell->face_indices())
      if (cell->at_boundary(f) && cell->face(f)->boundary_id() == 2 &&
          cell->face(f)->center()[0] > 3)
        {
          const double h = cell->face(f)->diameter();
          const double b = cell->face(f)->center()[0] + h / 2 - 3;
          const double a = b - h;
          return std::sqrt(h * (b * b * b - a * a * a) / 3);
        }
    return 0;
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);

  {
    const std::string  text            = common + R"(
subsection boundary
  set clamped boundary ids  = 0
  set traction boundary ids = 1, 3
  set contact boundary ids  = 2
end
subsection data
  set initial displacement = x*y; 0
  set body force           = 0; -5
  set surface traction     = if(x > 3.999, 7*y, 2*x); if(x > 3.999, 8, 3*y)
  set contact traction     = -2*x; -3*y + if(x > 3, x - 3, 0)
end
subsection adaptivity
  set interval         = 1
  set indicator        = residual
  set strategy         = fixed fraction
  set refine fraction  = 0.5
  set coarsen fraction = 0
  set min level        = 3
  set max level        = 5
end
)";
    const auto         problem_pointer = set_up(text);
    ContactProblem<2> &problem         = *problem_pointer;
    const auto         expected        = [](const auto &cell) {
      return expected_contact_term(cell);
    };
    compare(problem, expected, "bilinear u, start mesh");
    for (unsigned int cycle = 1; cycle <= 2; ++cycle)
      {
        StepStatistics stats;
        problem.adapt_mesh(stats);
        compare(problem,
                expected,
                "bilinear u, adaptation " + std::to_string(cycle));
      }
  }

  {
    const std::string  text            = common + R"(
subsection boundary
  set clamped boundary ids  = 0
  set traction boundary ids = 3
  set contact boundary ids  = 2
end
subsection data
  set initial displacement = 0; x - abs(x - 2) + 2
end
)";
    const auto         problem_pointer = set_up(text);
    ContactProblem<2> &problem         = *problem_pointer;
    const auto         expected        = [](const auto &cell) {
      const double h = cell->face(0)->diameter();
      return std::abs(std::abs(cell->center()[0] - 2) - h / 2) < 1e-12 ?
                              std::sqrt(8.) * h :
                              0.;
    };
    // boundary cells carry boundary terms: compare interior cells only
    const Vector<float> eta    = residual_indicators(problem);
    double              error  = 0;
    unsigned int        n_kink = 0;
    for (const auto &cell : problem.state().dof_handler.active_cell_iterators())
      if (cell->is_locally_owned() && !cell->at_boundary())
        {
          const double e = expected(cell);
          error = std::max(error, std::abs(eta[cell->active_cell_index()] - e));
          n_kink += (e > 0);
        }
    error  = Utilities::MPI::max(error, MPI_COMM_WORLD);
    n_kink = Utilities::MPI::sum(n_kink, MPI_COMM_WORLD);
    out() << "kink at x = 2: " << n_kink
          << " interior cells next to it with eta = sqrt(8) h, the others 0 "
             "(within 1e-6): "
          << (error < 1e-6 ? "yes" : "no") << "\n";
  }
}
