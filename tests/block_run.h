#pragma once
// Shared by the tests that rerun the short block examples with different
// solver settings: run 0.15 time units of a .prm plus extra settings and
// return the final velocity and the Newton and Krylov iterations it took.
// The solver's tuning constants (SolverTuning) are changed from C++.
// In 2D 3 steps of k = 0.04 (as in tests/block_2d_short.prm), in 3D 8 steps
// of k = 0.01875 (the nearest divisor of 0.15 to the 0.02 of
// tests/block_3d_short.prm).
#include <hemicontact/input/parameters.h>
#include <hemicontact/problem/contact_problem.h>

#include <fstream>
#include <functional>
#include <sstream>
#include <string>

struct BlockRun
{
  dealii::TrilinosWrappers::MPI::Vector velocity;
  unsigned int                          newton_iterations = 0;
  unsigned int                          linear_iterations = 0;
};

template <int dim>
BlockRun
run_block(const std::string                                      &file,
          const std::string                                      &settings,
          const std::function<void(hemicontact::SolverTuning &)> &tune = {})
{
  using namespace hemicontact;
  std::ifstream      in(file);
  std::stringstream  text;
  const unsigned int n_steps  = (dim == 2 ? 3 : 8);
  const double       end_time = (dim == 2 ? 0.12 : 0.15);
  text.precision(17);
  text << in.rdbuf() << "subsection time\n  set end time = " << end_time
       << "\n  set time step = " << end_time / n_steps << "\nend\n"
       << "subsection output\n  set directory = output-" << dim
       << "d\n  set terminal = quiet\nend\n"
       << settings;
  dealii::ParameterHandler prm;
  Parameters parameters = read_parameters_from_string(prm, text.str());
  if (tune)
    tune(parameters.solver_tuning);
  ContactProblem<dim> problem(parameters,
                              create_contact_laws(prm),
                              MPI_COMM_WORLD);
  problem.setup();
  BlockRun result;
  while (!problem.finished())
    {
      const StepStatistics step = problem.advance();
      result.newton_iterations += step.newton_iterations;
      result.linear_iterations += step.linear_iterations;
    }
  result.velocity = problem.state().velocity;
  return result;
}

/** "agree to 1e-7" if |a - b| <= 1e-7 |b| (l2 norms), else "DIFFER". */
inline std::string
agreement(const dealii::TrilinosWrappers::MPI::Vector &a,
          const dealii::TrilinosWrappers::MPI::Vector &b)
{
  dealii::TrilinosWrappers::MPI::Vector difference(a);
  difference -= b;
  return difference.l2_norm() <= 1e-7 * b.l2_norm() ? "agree to 1e-7" :
                                                      "DIFFER";
}
