// The memory breakdown of performance.csv (doc/performance.md, "Memory"):
// after 8 steps of the short 3D block, its parts sum to no more than the
// peak resident memory (on 1 and on 2 ranks), the matrices share one
// sparsity graph, counted once, the viscous matrix is not held, and while
// the constrained AMG is in use (never dropped here) the AMG of K0 holds
// nothing.
#include <hemicontact/base/memory_breakdown.h>
#include <hemicontact/input/parameters.h>
#include <hemicontact/output/performance_summary.h>
#include <hemicontact/problem/contact_problem.h>

#include <fstream>
#include <sstream>

#include "tests.h"

using namespace hemicontact;

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::ifstream                    in(SOURCE_DIR "/block_3d_short.prm");
  std::stringstream                text;
  text << in.rdbuf() << "subsection time\n  set end time = 0.15\n"
       << "  set time step = 0.01875\nend\n"
       << "subsection output\n  set directory = output-3d\n"
       << "  set terminal = quiet\nend\n";
  ParameterHandler prm;
  Parameters       parameters = read_parameters_from_string(prm, text.str());
  // the constrained AMG kept however many nodes slip
  parameters.solver_tuning.constrained_mismatch_limit = 2;
  ContactProblem<3> problem(parameters,
                            create_contact_laws(prm),
                            MPI_COMM_WORLD);
  problem.setup();
  const auto amg_bytes = [&](const std::string &part) {
    double bytes = 0;
    for (const auto &[name, b] :
         memory_breakdown(problem).summed(MPI_COMM_WORLD))
      bytes += (name == part) * b;
    return bytes;
  };
  const auto print_amgs = [&](const std::string &when) {
    out() << when << ": constrained AMG in use: "
          << (problem.state().preconditioner.uses_constrained_amg() ? "yes" :
                                                                      "no")
          << ", holds memory: "
          << (amg_bytes("constrained AMG") > 0 ? "yes" : "no")
          << ", the AMG of K0 holds memory: "
          << (amg_bytes("AMG of K0") > 0 ? "yes" : "no") << "\n";
  };
  problem.advance();
  print_amgs("after the first step");
  while (!problem.finished())
    problem.advance();
  print_amgs("after the last step");

  const auto   parts = memory_breakdown(problem).summed(MPI_COMM_WORLD);
  const double peak =
    Utilities::MPI::sum(peak_resident_bytes(), MPI_COMM_WORLD);
  double sum = 0, graph = 0;
  out() << "parts:";
  for (const auto &[name, bytes] : parts)
    {
      out() << " '" << name << "'";
      sum += bytes;
      graph += (name == "sparsity graph") * bytes;
    }
  out() << "\n";
  const auto  &k = problem.state().step_matrix;
  const double one_graph =
    Utilities::MPI::sum(matrix_graph_bytes(k), MPI_COMM_WORLD);
  out() << "the parts sum to no more than the peak resident memory: "
        << (sum > 0 && sum <= peak ? "yes" : "NO") << "\n"
        << "the sparsity graph counted once: "
        << (graph == one_graph ? "yes" : "NO") << "\n";
}
