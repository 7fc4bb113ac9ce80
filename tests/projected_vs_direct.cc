// The projected Newton operator (step matrix and its AMG once per mesh,
// contact blocks and constrained directions applied node-wise, CG with
// StepPreconditioner) must give the same time steps as the direct solve of
// the assembled projected matrix Pi (K0 + sum L_i) Pi + (I - Pi) ('linear
// solver/type = direct'), with inexact (Eisenstat-Walker) and with fixed
// Krylov tolerances: 15 steps of the short 2D and 3D block runs, in which
// stick, slip, damped and separating nodes all occur, compared in the final
// velocity and in the Newton iterations.
#include "block_run.h"
#include "tests.h"

using namespace hemicontact;

namespace
{
  template <int dim>
  BlockRun
  run(const std::string &file, const std::string &solver)
  {
    return run_block<dim>(file,
                          "subsection linear solver\n" + solver + "end\n");
  }

  template <int dim>
  void
  compare(const std::string &file)
  {
    const BlockRun projected = run<dim>(file, "");
    const BlockRun projected_fixed =
      run<dim>(file, "  set forcing term = fixed\n");
    const BlockRun direct = run<dim>(file, "  set type = direct\n");
    for (const auto &[name, r] :
         {std::make_pair("projected, Eisenstat-Walker", &projected),
          std::make_pair("projected, fixed tolerance", &projected_fixed)})
      out() << "  " << dim << "D " << name
            << " vs direct: " << agreement(r->velocity, direct.velocity)
            << ", Newton iterations " << r->newton_iterations << " vs "
            << direct.newton_iterations << "\n";
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  compare<2>(SOURCE_DIR "/block_2d_short.prm");
  compare<3>(SOURCE_DIR "/block_3d_short.prm");
}
