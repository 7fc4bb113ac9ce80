// The stiff-direction split of the projected preconditioner
// (SolverTuning::stiff_contact_threshold): the contact directions much stiffer
// than rho/k M + A (the slip stiffness next to a stick-slip front) are inverted
// node by node instead of being left to the AMG of rho/k M + A. It changes how
// fast CG converges, never the solution: 15 steps of the short 3D block run
// with the split (the default) and without it give the same final velocity, and
// the split needs fewer Krylov iterations. In 2D it must not hurt.
#include "block_run.h"
#include "tests.h"

using namespace hemicontact;

namespace
{
  template <int dim>
  void
  compare(const std::string &file)
  {
    const BlockRun split = run_block<dim>(file, "");
    const BlockRun plain = run_block<dim>(file, "", [](SolverTuning &tuning) {
      tuning.stiff_contact_threshold = 0;
    });

    out() << "  " << dim << "D split vs plain AMG: "
          << agreement(split.velocity, plain.velocity) << "\n";
    const bool fewer = split.linear_iterations < plain.linear_iterations;
    const bool no_more =
      split.linear_iterations <= 1.05 * plain.linear_iterations;
    out() << "  " << dim << "D Krylov iterations with the split: "
          << (dim == 3 ? (fewer ? "fewer" : "NOT FEWER") :
                         (no_more ? "no more (within 5%)" : "MORE"))
          << "\n";
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  compare<2>(SOURCE_DIR "/block_2d_short.prm");
  compare<3>(SOURCE_DIR "/block_3d_short.prm");
}
