// One load value of the static class (doc/theory.md, section 9.1) whose
// exact discrete answer is known in closed form, on quadrilaterals/hexahedra
// (Q1) and triangles/tetrahedra (P1): the block of one_step_block.h, clamped
// on top, in contact at the bottom, loaded so that the exact displacement
// u = U (1 - y/H) e (linear in the thickness) lies in the finite element
// space. The laws act on u; K = B, no inertia and no viscosity. The program
// must reproduce u to solver tolerance, with the expected branch at every
// contact node (the cases of one_step_constant_stress.h; "compliant": the
// bottom penetrates the foundation).
#include <hemicontact/input/parameters.h>

#include "one_step_constant_stress.h"

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  // the density and viscosity are set to values the static class ignores;
  // the step's stress is B's
  const double mu_e = 10, lambda_e = 5;
  check_constant_stress_cases(
    {"subsection problem\n  set class = static\nend\n",
     {1, 1, 1, mu_e, lambda_e},
     mu_e,
     lambda_e,
     "compliant"});
}
