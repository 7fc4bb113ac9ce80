// The warm starts of a step's Newton iteration -- the extrapolated initial
// guess w_{n-1} + k_n/k_{n-1} (w_{n-1} - w_{n-2}) and the Krylov solve to the
// Newton tolerance once no node changes branch -- change where Newton starts
// and how far each linear solve goes, never the solution: 15 steps of the short
// 2D and 3D block runs with both on (the defaults) and both off give the same
// final velocity, and the defaults need fewer Newton iterations.
#include "block_run.h"
#include "tests.h"

using namespace hemicontact;

namespace
{
  template <int dim>
  void
  compare(const std::string &file)
  {
    const BlockRun warm = run_block<dim>(file, "");
    const BlockRun cold =
      run_block<dim>(file,
                     "subsection nonlinear solver\n"
                     "  set initial guess = previous\nend\n",
                     [](SolverTuning &tuning) {
                       tuning.exact_solve_when_settled = false;
                       tuning.maximum_forcing_term     = 0.1;
                     });
    const BlockRun extrapolated_only =
      run_block<dim>(file, "", [](SolverTuning &tuning) {
        tuning.exact_solve_when_settled = false;
      });

    for (const auto &[name, r] :
         {std::make_pair("defaults", &warm),
          std::make_pair("extrapolated guess only", &extrapolated_only)})
      out() << "  " << dim << "D " << name
            << " vs cold starts: " << agreement(r->velocity, cold.velocity)
            << "\n";
    out() << "  " << dim << "D defaults need fewer Newton iterations: "
          << (warm.newton_iterations < cold.newton_iterations ? "yes" : "NO")
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
