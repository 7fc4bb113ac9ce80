// The constrained AMG of the projected solver (SolverTuning::
// constrained_preconditioner):
// the first AMG of a mesh is built from rho/k M + A plus a penalty on the
// directions the contact branches constrain, so that it treats stuck nodes
// as Dirichlet conditions, and is given up for the AMG of rho/k M + A once
// too many nodes have freed a direction it constrains. It changes how fast
// CG converges, never the solution: the short 2D and 3D block runs give the
// same final velocity with it (the default) and without it, and need fewer
// Krylov iterations with it (3D at 2 refinements: on the coarser short mesh
// the two are even). Rebuilt whenever the constrained directions change
// (SolverTuning::constrained_amg_follows_branches), it gives the same final
// velocity again with still fewer Krylov iterations (2D at 4 refinements).
#include "block_run.h"
#include "tests.h"

using namespace hemicontact;

namespace
{
  template <int dim>
  void
  compare(const std::string &file, const std::string &extra = "")
  {
    const BlockRun constrained = run_block<dim>(file, extra);
    const BlockRun plain =
      run_block<dim>(file, extra, [](SolverTuning &tuning) {
        tuning.constrained_preconditioner = false;
      });
    out() << "  " << dim << "D constrained vs plain AMG: "
          << agreement(constrained.velocity, plain.velocity) << "\n";
    out() << "  " << dim << "D Krylov iterations with the constrained AMG: "
          << (constrained.linear_iterations < plain.linear_iterations ?
                "fewer" :
                "NOT FEWER")
          << "\n";
  }

  template <int dim>
  void
  compare_following(const std::string &file, const std::string &extra)
  {
    const BlockRun standard = run_block<dim>(file, extra);
    const BlockRun following =
      run_block<dim>(file, extra, [](SolverTuning &tuning) {
        tuning.constrained_amg_follows_branches = true;
      });
    out() << "  " << dim << "D following vs first-iteration constraints: "
          << agreement(following.velocity, standard.velocity) << "\n";
    out() << "  " << dim
          << "D Krylov iterations with the AMG following the branches: "
          << (following.linear_iterations < standard.linear_iterations ?
                "fewer" :
                "NOT FEWER")
          << "\n";
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  compare<2>(SOURCE_DIR "/block_2d_short.prm");
  compare<3>(SOURCE_DIR "/block_3d_short.prm",
             "subsection geometry\n  set global refinements = 2\nend\n");
  compare_following<2>(
    SOURCE_DIR "/block_2d_short.prm",
    "subsection geometry\n  set global refinements = 4\nend\n");
}
