// One step of the quasistatic class with the implicit rule (doc/theory.md,
// section 9.1) whose exact discrete answer is known in closed form, on
// quadrilaterals/hexahedra (Q1) and triangles/tetrahedra (P1): the block of
// one_step_block.h, clamped on top, in contact at the bottom, u_0 = 0,
// loaded so that the exact velocity w_1 = U (1 - y/H) e (linear in the
// thickness) lies in the finite element space. The step is
// (A + k B) w_1 = F_1 - B u_0 with the laws on w_1 and no inertia: a
// constant stress with the moduli mu_v + k mu_e, lambda_v + k lambda_e.
// The program must reproduce w_1 to solver tolerance, with the expected
// branch at every contact node (the cases of one_step_constant_stress.h;
// "damped": the bottom moves into the foundation).
#include <hemicontact/input/parameters.h>

#include "one_step_constant_stress.h"

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  // the density is set to a value the quasistatic class ignores
  const double mu_v = 1.5, lambda_v = 0.7, mu_e = 10, lambda_e = 5,
               k = constant_stress_time_step;
  check_constant_stress_cases({"subsection problem\n  set class = quasistatic\n"
                               "  set time scheme = implicit\nend\n",
                               {2, mu_v, lambda_v, mu_e, lambda_e},
                               mu_v + k * mu_e,
                               lambda_v + k * lambda_e,
                               "damped"});
}
