// The projected Newton operator (step matrix and its AMG once per mesh,
// contact blocks and constrained directions applied node-wise, inexact
// Krylov solves) must give the same time steps as the reassembled Newton
// matrix with the contact constraints eliminated, and as the direct solver:
// 15 steps of the short 2D and 3D block runs, in which stick, slip, damped
// and separating nodes all occur, compared in the final velocity.
#include "block_run.h"
#include "tests.h"

using namespace hemicontact;

namespace
{
  template <int dim>
  TrilinosWrappers::MPI::Vector
  run(const std::string &file, const std::string &solver)
  {
    return run_block<dim>(file, "subsection linear solver\n" + solver +
                                  "end\n")
      .velocity;
  }

  template <int dim>
  void
  compare(const std::string &file)
  {
    const auto projected =
      run<dim>(file, "  set newton operator = projected\n");
    const auto projected_fixed =
      run<dim>(file, "  set newton operator = projected\n"
                     "  set forcing term = fixed\n");
    const auto assembled =
      run<dim>(file, "  set newton operator = assembled\n");
    const auto direct = run<dim>(file, "  set type = direct\n");
    for (const auto &[name, v] :
         {std::make_pair("projected, Eisenstat-Walker", &projected),
          std::make_pair("projected, fixed tolerance", &projected_fixed),
          std::make_pair("direct", &direct)})
      out() << "  " << dim << "D " << name
            << " vs assembled: " << agreement(*v, assembled) << "\n";
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  compare<2>(SOURCE_DIR "/block_2d_short.prm");
  compare<3>(SOURCE_DIR "/block_3d_short.prm");
}
