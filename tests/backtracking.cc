// The backtracking rule of the Newton line search (backtracking_step_length):
// a full step whose energy change is within round-off is taken; an
// overshooting descent direction is damped to the first halving that
// decreases the energy; a direction along which the energy only grows (by
// less than the round-off bound for small theta) gets the full step, never
// a creeping theta whose increase hides under the bound.
#include <hemicontact/solver/backtracking.h>

#include "tests.h"

using namespace hemicontact;
using namespace dealii;

namespace
{
  void
  report(const std::string &name, const std::function<double(double)> &change)
  {
    unsigned int n_reductions = 0;
    const double theta =
      backtracking_step_length(change, /*scale=*/1, /*min=*/1e-3, n_reductions);
    out() << "  " << name << ": theta = " << theta << " after " << n_reductions
          << " halvings\n";
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  report("full step within round-off", [](double t) { return 1e-13 * t; });
  report("full step decreasing", [](double t) { return -t + 0.5 * t * t; });
  // minimum at theta = 1/3: J(1) > J(0), J(1/2) < J(0)
  report("overshooting descent", [](double t) { return -t + 1.5 * t * t; });
  // grows like 1e-10 theta: below the 1e-12 bound from theta = 1/128 on
  report("not a descent direction", [](double t) { return 1e-10 * t; });
}
