/**
 * Where the 2D step's iterations grow: prm/block_2d.prm (100 steps of
 * k = 0.01) at 'global refinements' r, with one solver choice changed:
 *
 *   default         the shipped settings
 *   fixed           'linear solver/forcing term = fixed': every Krylov solve
 *                   to 'relative tolerance' (Krylov per full solve)
 *   no-constrained  SolverTuning::constrained_preconditioner = false
 *   no-settled      SolverTuning::exact_solve_when_settled = false
 *   fixed-frictionless  'fixed' with 'data/friction bound = 0'
 *   following       SolverTuning::constrained_amg_follows_branches = true:
 *                   the AMG's constraints are those of every iteration
 *   fixed-following 'fixed' and 'following'
 *
 * Prints one CSV line per run: variant, r, dofs, Newton iterations per
 * step, Krylov iterations per Newton iteration, seconds per step.
 *
 *   cmake -S bench/solver_variants -B build-variants -DCMAKE_BUILD_TYPE=Release
 *   cmake --build build-variants
 *   for v in default fixed no-constrained no-settled fixed-frictionless \
 *           following fixed-following; do
 *     for r in 4 5 6; do
 *       build-variants/solver_variants $v $r; done; done
 *
 * bench/results/solver_variants.csv also has r = 7, 8 for 'default' and
 * 'following' (the same command, run on their own).
 *
 * Links the library of the Release build in build/ (doc/performance.md,
 * "Limits and open targets").
 */
#include <deal.II/base/mpi.h>

#include <hemicontact/input/parameters.h>
#include <hemicontact/problem/contact_problem.h>

#include <fstream>
#include <iostream>
#include <sstream>

using namespace hemicontact;

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  if (argc != 3)
    {
      std::cerr << "usage: solver_variants VARIANT REFINEMENTS\n";
      return 1;
    }
  const std::string variant     = argv[1];
  const int         refinements = std::stoi(argv[2]);
  std::ifstream     in(HEMICONTACT_SOURCE_DIR "/prm/block_2d.prm");
  std::stringstream text;
  text << in.rdbuf()
       << "subsection geometry\n  set global refinements = " << refinements
       << "\nend\n"
       << "subsection output\n  set directory = output-solver-variants\n"
       << "  set terminal = quiet\n  set output interval = 0\n"
       << "  set probe points =\nend\n";
  if (variant.rfind("fixed", 0) == 0)
    text << "subsection linear solver\n  set forcing term = fixed\nend\n";
  if (variant == "fixed-frictionless")
    text << "subsection data\n  set friction bound = 0\nend\n";
  dealii::ParameterHandler prm;
  Parameters parameters = read_parameters_from_string(prm, text.str());
  if (variant == "no-constrained")
    parameters.solver_tuning.constrained_preconditioner = false;
  else if (variant == "no-settled")
    parameters.solver_tuning.exact_solve_when_settled = false;
  else if (variant == "following" || variant == "fixed-following")
    parameters.solver_tuning.constrained_amg_follows_branches = true;
  else if (variant != "default" && variant != "fixed" &&
           variant != "fixed-frictionless")
    {
      std::cerr << "unknown variant '" << variant << "'\n";
      return 1;
    }

  ContactProblem<2> problem(parameters,
                            create_contact_laws(prm),
                            MPI_COMM_WORLD);
  problem.setup();
  unsigned int newton = 0, krylov = 0, steps = 0;
  double       wall = 0;
  while (!problem.finished())
    {
      const StepStatistics s = problem.advance();
      newton += s.newton_iterations;
      krylov += s.linear_iterations;
      wall += s.wall_seconds;
      ++steps;
    }
  std::cout << variant << ',' << refinements << ','
            << problem.get_dof_handler().n_dofs() << ','
            << double(newton) / steps << ',' << double(krylov) / newton << ','
            << wall / steps << std::endl;
  return 0;
}
