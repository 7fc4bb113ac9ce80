// The line search keeps the Newton residual R = K0 w - b up to date by the
// product K0 d it needs for the energy (R(w + theta d) = R(w) + theta K0 d)
// instead of a new matrix-vector product per iteration. Without the line
// search R is computed afresh. Both must reach the same solution: 15 steps
// of the short 2D and 3D block runs give the same final velocity with the
// line search (the default) and without it.
#include "block_run.h"
#include "tests.h"

using namespace hemicontact;

namespace
{
  template <int dim>
  void
  compare(const std::string &file)
  {
    const BlockRun updated = run_block<dim>(file, "");
    const BlockRun fresh   = run_block<dim>(file,
                                          "subsection nonlinear solver\n"
                                            "  set line search = false\nend\n");
    out() << "  " << dim
          << "D residual updated by the line search vs recomputed: "
          << agreement(updated.velocity, fresh.velocity) << "\n";
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  compare<2>(SOURCE_DIR "/block_2d_short.prm");
  compare<3>(SOURCE_DIR "/block_3d_short.prm");
}
