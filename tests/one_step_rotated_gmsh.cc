// The closed-form one-step problems of one_step_exact.cc rotated by 0.5 rad:
// the block is read from a Gmsh file (written here), its contact boundary is
// not axis-aligned, so the nodal normals come from the mesh. The exact
// discrete solution must be reproduced to solver tolerance.
#include <deal.II/numerics/vector_tools.h>

#include <hemicontact/input/parameters.h>
#include <hemicontact/problem/contact_problem.h>

#include <cmath>
#include <fstream>
#include <sstream>

#include "tests.h"

using namespace hemicontact;

namespace
{
  const double theta = 0.5, c = std::cos(theta), s = std::sin(theta);
  const double rho = 2, mu_v = 1.5, lambda_v = 0.7, k = 0.1, V = 0.3, Fb = 0.4,
               a = 1, b = 0.4, beta = 3, L = 2, H = 1;

  /** A structured 8 x 4 quad mesh of the rotated block, boundary ids
   *  0 (xi = 0), 1 (xi = L), 2 (eta = 0, contact), 3 (eta = H). */
  void
  write_mesh(const std::string &name)
  {
    const unsigned int nx = 8, ny = 4;
    std::ofstream      f(name);
    f << "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n"
      << (nx + 1) * (ny + 1) << "\n";
    const auto id = [&](unsigned i, unsigned j) {
      return j * (nx + 1) + i + 1;
    };
    f.precision(17);
    for (unsigned int j = 0; j <= ny; ++j)
      for (unsigned int i = 0; i <= nx; ++i)
        {
          const double xi = L * i / nx, eta = H * j / ny;
          f << id(i, j) << " " << c * xi - s * eta << " " << s * xi + c * eta
            << " 0\n";
        }
    f << "$EndNodes\n$Elements\n" << nx * ny + 2 * (nx + ny) << "\n";
    unsigned int e = 1;
    for (unsigned int i = 0; i < nx; ++i)
      f << e++ << " 1 2 2 2 " << id(i, 0) << " " << id(i + 1, 0) << "\n";
    for (unsigned int i = 0; i < nx; ++i)
      f << e++ << " 1 2 3 3 " << id(i + 1, ny) << " " << id(i, ny) << "\n";
    for (unsigned int j = 0; j < ny; ++j)
      f << e++ << " 1 2 0 0 " << id(0, j + 1) << " " << id(0, j) << "\n";
    for (unsigned int j = 0; j < ny; ++j)
      f << e++ << " 1 2 1 1 " << id(nx, j) << " " << id(nx, j + 1) << "\n";
    for (unsigned int j = 0; j < ny; ++j)
      for (unsigned int i = 0; i < nx; ++i)
        f << e++ << " 3 2 10 10 " << id(i, j) << " " << id(i + 1, j) << " "
          << id(i + 1, j + 1) << " " << id(i, j + 1) << "\n";
    f << "$EndElements\n";
  }

  std::string
  parameter_file(const std::string &f0,
                 const std::string &f2,
                 const std::string &f3)
  {
    std::ostringstream p;
    p.precision(17);
    p << "set dimension = 2\n"
      << "subsection geometry\n  set mesh = gmsh\n"
      << "  set mesh file = rotated_block.msh\n  set global refinements = 0\nend\n"
      << "subsection boundary\n  set clamped boundary ids = 3\n"
      << "  set traction boundary ids = 0, 1\n  set contact boundary ids = 2\nend\n"
      << "subsection material\n  set density = " << rho << "\n"
      << "  subsection viscosity\n    set mu = " << mu_v
      << "\n    set lambda = " << lambda_v << "\n  end\n"
      << "  subsection elasticity\n    set mu = 10\n    set lambda = 5\n  end\n"
      << "end\n"
      << "subsection time\n  set end time = " << k
      << "\n  set time step = " << k << "\nend\n"
      << "subsection data\n"
      << "  set constants = V=" << V << ", rho=" << rho << ", k=" << k
      << ", mv=" << mu_v << ", lv=" << lambda_v << ", Fb=" << Fb << ", a=" << a
      << ", H=" << H << ", c=" << c << ", s=" << s << "\n"
      << "  set body force = " << f0 << "\n"
      << "  set surface traction = " << f2 << "\n"
      << "  set contact traction = " << f3 << "\n"
      << "  set friction bound = Fb\nend\n"
      << "subsection normal law\n  set law = exponential\n"
      << "  subsection exponential\n    set a = " << a << "\n    set b = " << b
      << "\n    set beta = " << beta << "\n  end\nend\n"
      << "subsection nonlinear solver\n  set tolerance = 1e-12\nend\n"
      << "subsection linear solver\n  set relative tolerance = 1e-13\nend\n"
      << "subsection output\n  set terminal = quiet\nend\n";
    return p.str();
  }

  /** expression "A*t + B*n" with t = (c, s), n = (-s, c) */
  std::string
  frame(const std::string &along_t, const std::string &along_n)
  {
    return "(" + along_t + ")*c - (" + along_n + ")*s; (" + along_t +
           ")*s + (" + along_n + ")*c";
  }

  void
  check(const std::string &name,
        const std::string &f0,
        const std::string &f2,
        const std::string &f3,
        const std::string &exact_w)
  {
    ParameterHandler prm;
    const Parameters parameters =
      read_parameters_from_string(prm, parameter_file(f0, f2, f3));
    ContactProblem<2> problem(parameters,
                              create_contact_laws(prm),
                              MPI_COMM_WORLD);
    problem.setup();
    const StepStatistics stats = problem.advance();

    std::ostringstream constants;
    constants.precision(17);
    constants << "V=" << V << ", H=" << H << ", c=" << c << ", s=" << s;
    auto exact = parse_function<2>(exact_w, 2, constants.str(), "exact");
    TrilinosWrappers::MPI::Vector w(problem.state().velocity);
    VectorTools::interpolate(*problem.state().discretization.mapping,
                             problem.state().dof_handler,
                             *exact,
                             w);
    w -= problem.state().velocity;
    const double error = w.linfty_norm() / V;

    double normal_error = 0;
    for (const auto &node : problem.state().contact_nodes)
      normal_error =
        std::max(normal_error, (node.normal - Tensor<1, 2>({s, -c})).norm());

    out() << name << ": nodal normals = (sin, -cos)(0.5): "
          << (normal_error < 1e-12 ? "yes" : "no")
          << "; relative max error < 1e-9: " << (error < 1e-9 ? "yes" : "no")
          << "; sep/stick/damped " << stats.n_separating << "/"
          << stats.n_normal_stick << "/" << stats.n_damped << ", stick/slip "
          << stats.n_stick << "/" << stats.n_slip << std::endl;
    if (error >= 1e-9)
      out() << "  error = " << error << std::endl;
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
    write_mesh("rotated_block.msh");
  MPI_Barrier(MPI_COMM_WORLD);

  const std::string xi  = "(c*x + s*y)";  // along the contact boundary
  const std::string eta = "(-s*x + c*y)"; // thickness coordinate
  const std::string side =
    "(" + xi + " < 1e-9 ? -1 : (" + xi + " > 2 - 1e-9 ? 1 : 0))";

  // slip along t: w = V (1 - eta/H) t
  check("slip",
        frame("rho/k*V*(1-" + eta + "/H)", "0"),
        frame("0", "-" + side + "*mv*V/H"),
        frame("mv*V/H + Fb", "-a/2"),
        frame("V*(1-" + eta + "/H)", "0"));

  // damped: w = -V (1 - eta/H) n, xi_nu = (a-b) exp(-beta V) + b
  const double       xi_nu = (a - b) * std::exp(-beta * V) + b;
  std::ostringstream f3;
  f3.precision(17);
  f3 << "-(2*mv+lv)*V/H - " << xi_nu;
  check("damped",
        frame("0", "-rho/k*V*(1-" + eta + "/H)"),
        frame(side + "*lv*V/H", "0"),
        frame("0", f3.str()),
        frame("0", "-V*(1-" + eta + "/H)"));
}
