/* ---------------------------------------------------------------------
 *
 * hemicontact tutorial, step-1: static elastic contact with a nonmonotone
 * normal compliance and Tresca friction, solved by the primal-dual active
 * set (semismooth Newton) method.
 *
 * The introduction (doc/intro.md) states the model, the weak form, the
 * discretisation and the algorithm; the results (doc/results.md) show
 * what this program prints. The program depends on deal.II alone.
 *
 * ---------------------------------------------------------------------
 */

// @sect3{Include files}

// The usual deal.II headers of a serial program (step-8 for elasticity,
// step-7 for the convergence table, step-41 for an active set).
#include <deal.II/base/convergence_table.h>
#include <deal.II/base/function.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/sparse_direct.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/vector.h>
#include <deal.II/numerics/data_out.h>
#include <deal.II/numerics/vector_tools.h>

// And a few headers of the C++ standard library: containers for the
// breakpoints and the contact nodes, streams for the output files, and
// <limits> for the start of the power iteration.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <limits>
#include <map>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace Step1
{
  using namespace dealii;

  // @sect3{The normal law}

  // The normal compliance: the response $\xi_\nu$ of the foundation to a
  // penetration $r = u_\nu > 0$ is a continuous piecewise-linear function
  // given by breakpoints $(r_k, \xi_k)$, $r_0 = 0$, linear in between and
  // constant after the last one. For $r < 0$ the body has left the
  // foundation and there is no force; at $r = 0$ the law jumps from $0$ to
  // $\xi_0 = a$, and the Clarke subdifferential fills the jump with the
  // whole interval: $\partial j_\nu(0) = [0, a]$ (the introduction,
  // "Nonsmooth and nonconvex", draws it). We split the law into the convex
  // jump and a Lipschitz remainder,
  // @f[
  //   \partial j_\nu(r) = \partial(a r_+)(r) + p(r),\qquad
  //   p(r) = \xi(r) - a \ (r > 0),\quad p(r) = 0 \ (r \le 0),
  // @f]
  // because the two parts are treated differently: the jump becomes a
  // complementarity condition with a projection onto $[0, a]$ (a set
  // valued, convex piece), the remainder a smooth force that Newton's
  // method linearises. A law that rises and then falls is nonmonotone:
  // $j_\nu$ is not convex, but $j_\nu + \alpha_\nu r^2/2$ is, with
  // $\alpha_\nu$ the steepest descent slope of $\xi$ (the relaxed
  // monotonicity of the introduction).
  //
  // The rest of the program sees a law only through these seven members,
  // which is all a new law has to supply (the exercise of the results
  // page):
  // - jump(): $a$, the height of the jump at $r = 0$;
  // - response(r): $\xi(r)$ for $r > 0$;
  // - remainder(r) and remainder_derivative(r): $p(r)$ and $p'(r)$;
  // - potential(r): $j_\nu(r) = \int_0^r \xi$, for the energy of the line
  //   search;
  // - alpha: $\alpha_\nu$, for the uniqueness condition;
  // - steepest_rise: the largest $p'$, for the floor of the constants $c_i$
  //   (setup_contact_nodes()).
  //
  // breakpoints() only serves the output of the law for the figures
  // (write_law()).
  class PiecewiseLinearLaw
  {
  public:
    explicit PiecewiseLinearLaw(
      const std::vector<std::pair<double, double>> &breakpoints)
      : points(breakpoints)
    {
      // A law is data the user types, so we check it where it enters the
      // program, with AssertThrow (which stays active in Release mode, unlike
      // Assert): the first breakpoint must be the jump at $r = 0$, and the
      // penetrations must increase, or the segments below would overlap. A
      // negative response would pull the body into the foundation, which no
      // foundation does.
      AssertThrow(points[0].first == 0. && points[0].second >= 0,
                  ExcMessage("The first breakpoint must be at r = 0."));
      for (unsigned int k = 0; k + 1 < points.size(); ++k)
        {
          AssertThrow(points[k + 1].first > points[k].first &&
                        points[k + 1].second >= 0,
                      ExcMessage("The breakpoints must have increasing r "
                                 "and a response >= 0."));
          // $\alpha_\nu$ is the steepest descent slope; the steepest rise
          // sets a floor of the complementarity constants
          // (setup_contact_nodes()).
          alpha         = std::max(alpha, -slope(k));
          steepest_rise = std::max(steepest_rise, slope(k));
        }
    }

    // The jump $a$ of the subdifferential at $r = 0$.
    double
    jump() const
    {
      return points[0].second;
    }

    // The response $\xi(r)$ for $r > 0$, the remainder $p(r)$ and its
    // derivative $p'(r)$ (at a breakpoint, the slope to its right).
    double
    // The response on segment $k$ is the straight line through its two
    // breakpoints; beyond the last breakpoint the law stays at its last value,
    // which is what "constant after" means in the introduction.
    response(const double r) const
    {
      const unsigned int k = segment(r);
      if (k + 1 == points.size())
        return points.back().second;
      return points[k].second + slope(k) * (r - points[k].first);
    }

    double
    remainder(const double r) const
    {
      return r > 0 ? response(r) - jump() : 0.;
    }

    double
    remainder_derivative(const double r) const
    {
      const unsigned int k = segment(r);
      return (r <= 0 || k + 1 == points.size()) ? 0. : slope(k);
    }

    // The potential $j_\nu(r) = \int_0^r \xi$, exact segment by segment.
    double
    // On each segment $\xi$ is linear, so the trapezoidal rule integrates it
    // exactly: we add the trapezoids of the segments left of $r$, the last one
    // cut at $r$. The energy of the line search, and so the choice of step
    // lengths, rests on this number: an approximate potential would let the
    // line search accept steps that raise the true $J_h$.
    potential(const double r) const
    {
      double integral = 0;
      for (unsigned int k = 0; k < points.size() && points[k].first < r; ++k)
        {
          const double end =
            k + 1 < points.size() ? std::min(r, points[k + 1].first) : r;
          integral +=
            0.5 * (points[k].second + response(end)) * (end - points[k].first);
        }
      return integral;
    }

    double alpha = 0, steepest_rise = 0;

    const std::vector<std::pair<double, double>> &
    breakpoints() const
    {
      return points;
    }

  private:
    // The segment $[r_k, r_{k+1})$ that holds $r$ (the last $k$ beyond the
    // last breakpoint), and its slope.
    unsigned int
    // A linear search: a law has a handful of breakpoints, and a binary search
    // would gain nothing but lines. Note the $\le$: a breakpoint belongs to the
    // segment to its right, so remainder_derivative() returns the slope to the
    // right of a kink, the one a Newton step that moves into the foundation
    // sees.
    segment(const double r) const
    {
      unsigned int k = 0;
      while (k + 1 < points.size() && points[k + 1].first <= r)
        ++k;
      return k;
    }

    double
    slope(const unsigned int k) const
    {
      return (points[k + 1].second - points[k].second) /
             (points[k + 1].first - points[k].first);
    }

    std::vector<std::pair<double, double>> points;
  };

  // The law as the program uses it, written to a CSV file (r, xi, j) for
  // the figures of the documentation (doc/plot_law.py, doc/plot_contact.py),
  // so that a changed law is drawn as it is: $\xi$ and $j_\nu$ from $r =
  // -0.05$ to twice the last breakpoint, at every breakpoint and 400 points
  // between, with two rows at $r = 0$ for the vertical segment $[0, a]$ of
  // the subdifferential. The column is_breakpoint marks the $r_k$.
  void
  write_law(const PiecewiseLinearLaw &law, const std::string &filename)
  {
    std::ofstream file(filename);
    AssertThrow(file, ExcIO());
    file << "r,xi,potential,is_breakpoint\n" << std::setprecision(10);
    const double end = 2 * law.breakpoints().back().first;
    file << -0.05 << ",0,0,0\n"
         << "0,0,0,0\n";
    std::map<double, bool> r_values; // r -> is a breakpoint
    for (unsigned int k = 0; k <= 400; ++k)
      r_values[end * k / 400.] = false;
    for (const auto &point : law.breakpoints())
      r_values[point.first] = true;
    for (const auto &[r, is_breakpoint] : r_values)
      file << r << ',' << (r > 0 ? law.response(r) : law.jump()) << ','
           << law.potential(r) << ',' << is_breakpoint << '\n';
  }

  // @sect3{The problem data}

  // The boundary is split by boundary id: $\Gamma_1$ (clamped) has id 0,
  // $\Gamma_3$ (contact) id 2, and every other boundary is $\Gamma_2$
  // (traction). GridGenerator::subdivided_hyper_rectangle() with
  // colorize = true numbers a rectangle's sides left 0, right 1, bottom 2,
  // top 3: the left side clamped, the bottom in contact.
  namespace BoundaryIds
  {
    constexpr types::boundary_id clamped = 0;
    constexpr types::boundary_id contact = 2;
  } // namespace BoundaryIds

  // What defines one problem: the material (Lamé constants of $B$), the
  // laws, the loads $f_0$ in $\Omega$ and $f_2$ on $\Gamma_2$ at the load
  // parameter $t$, and, in a manufactured solution, a traction $f_3$ on
  // $\Gamma_3$ and the exact solution.
  template <int dim>
  class ProblemData
  {
  public:
    ProblemData(const double                                  mu,
                const double                                  lambda,
                const double                                  F_b,
                const std::vector<std::pair<double, double>> &breakpoints =
                  {{0, 1}, {0.02, 1.4}, {0.15, 1.3}})
      : mu(mu)
      , lambda(lambda)
      , friction_bound(F_b)
      , law(breakpoints)
    {}

    virtual ~ProblemData() = default;

    // What a problem supplies, in the way deal.II's Function class asks for
    // values: the coarse mesh with its boundary ids, and the two loads as
    // functions of the point and the load parameter. Everything the solver
    // needs beyond these (the stress, the laws) is the same for every problem
    // of this program and lives in this base class.
    virtual void
    make_coarse_grid(Triangulation<dim> &triangulation) const = 0;

    // $f_0(x, t)$ and the prescribed traction at $x$ on the boundary
    // with id @p id and outward normal @p normal ($f_2$, or $f_3$ on
    // $\Gamma_3$).
    virtual Tensor<1, dim>
    body_force(const Point<dim> &x, const double t) const = 0;

    virtual Tensor<1, dim>
    traction(const Point<dim>        &x,
             const Tensor<1, dim>    &normal,
             const types::boundary_id id,
             const double             t) const = 0;

    // $\sigma = B\varepsilon = 2\mu\varepsilon + \lambda\,\mathrm{tr}
    // (\varepsilon) I$.
    SymmetricTensor<2, dim>
    stress(const SymmetricTensor<2, dim> &eps) const
    {
      return 2 * mu * eps + lambda * trace(eps) * unit_symmetric_tensor<dim>();
    }

    const double             mu, lambda;
    const double             friction_bound;
    const PiecewiseLinearLaw law;
  };

  // @sect4{The block}

  // The problem the program shares with the full code (and that the test
  // tests/tutorial/step_1_vs_hemicontact.sh runs in both): a block
  // $[0,4]\times[0,1]$ clamped on the left, free on the right, on a
  // foundation along its bottom, loaded on its top by a traction that
  // pulls up left of $x = 1$, presses down right of it and shears, all
  // growing with $t$.
  //
  // The block takes the normal law as an argument: the main study uses the
  // law of every other problem of this program, and the study of
  // nonconvexity at the end of main() one whose fall is far steeper than
  // the body can hold.
  class BlockData : public ProblemData<2>
  {
  public:
    BlockData(const std::vector<std::pair<double, double>> &breakpoints =
                {{0, 1}, {0.02, 1.4}, {0.15, 1.3}})
      : ProblemData<2>(/*mu=*/100, /*lambda=*/150, /*F_b=*/0.6, breakpoints)
    {}

    void
    make_coarse_grid(Triangulation<2> &triangulation) const override
    {
      GridGenerator::subdivided_hyper_rectangle(
        triangulation, {4, 1}, Point<2>(0, 0), Point<2>(4, 1), true);
    }

    Tensor<1, 2>
    body_force(const Point<2> &, const double) const override
    {
      return Tensor<1, 2>();
    }

    Tensor<1, 2>
    traction(const Point<2> &x,
             const Tensor<1, 2> &,
             const types::boundary_id id,
             const double             t) const override
    {
      if (id != 3) // the top; the right side is free
        return Tensor<1, 2>();
      // The traction on the top, $f_2(x, t) = t\,(0.5\,x/4,\ -2.5\,(x - 1)/3)$:
      // the shear grows from the clamped end to $0.5\,t$ at the free end; the
      // normal part is positive (upwards) left of $x = 1$ and presses down
      // right of it, up to $2.5\,t$ at the free end. So the block is lifted
      // near the clamp and pressed into the foundation further out, and the
      // contact zone has all three normal branches at once.
      return Tensor<1, 2>({0.5 * t * x[0] / 4, -2.5 * t * (x[0] - 1) / 3});
    }
  };

  // @sect4{A manufactured solution}

  // On the unit square, clamped on the left, with $\Gamma_3$ the bottom
  // ($\nu = (0,-1)$), the field
  // @f[
  //   u(x, y) = (1 + y)\,\bigl(g_\tau(x),\; -g_\nu(x)\bigr),\qquad
  //   g_\tau(x) = (x - \tfrac34)_+^3,\quad
  //   g_\nu(x) = 2 (x - \tfrac12)_+^3 - 8 x (\tfrac14 - x)_+^3,
  // @f]
  // has on $\Gamma_3$ $u_\nu = g_\nu(x)$: separation on $(0, \frac14)$,
  // contact without penetration on $[\frac14, \frac12]$, penetration
  // on $(\frac12, 1]$ up to $u_\nu = 0.25$ across all three segments of
  // the law; and $u_\tau = g_\tau(x)$: stick on $(0, \frac34]$, slip beyond.
  // $u$ is $C^2$, so $f_0 = -\mathrm{Div}\,\sigma(u)$ is continuous.
  // It solves the problem with $f_2 = \sigma\nu$ and, on $\Gamma_3$,
  // $f_3 = \sigma\nu + \xi_\nu\nu + \xi_\tau$ with $\xi_\nu \in \partial
  // j_\nu(u_\nu)$, $\xi_\tau \in \partial(F_b|\cdot|)(u_\tau)$: the
  // extra traction $f_3$ is exactly what the laws would have to supply
  // for $u$ to be in equilibrium. Where the exact solution holds at zero
  // we take $\xi_\nu = a/2$ and $\xi_\tau = F_b/2$, strictly inside the
  // intervals, so that no node sits at the switch between two branches
  // (where the discrete branches could flip with round-off). The points
  // $\frac14, \frac12, \frac34$ where $f_3$ jumps are mesh vertices.
  class ManufacturedData : public ProblemData<2>
  {
  public:
    ManufacturedData()
      : ProblemData<2>(/*mu=*/100, /*lambda=*/150, /*F_b=*/0.6)
    {}

    void
    make_coarse_grid(Triangulation<2> &triangulation) const override
    {
      GridGenerator::subdivided_hyper_rectangle(
        triangulation, {1, 1}, Point<2>(0, 0), Point<2>(1, 1), true);
    }

    // The exact solution is built from $z_+^3$, a $C^2$ function whose third
    // derivative jumps at $z = 0$: smooth enough for the data to be
    // continuous, and with kinks exactly where the contact conditions switch.
    // $z_+^3$ and its first two derivatives.
    static std::array<double, 3>
    cube_plus(const double z)
    {
      const double zp = std::max(z, 0.);
      return {{zp * zp * zp, 3 * zp * zp, 6 * zp}};
    }

    // $g_\tau$, $g_\nu$ and their derivatives up to the second.
    static std::array<double, 3>
    g_tau(const double x)
    {
      return cube_plus(x - 0.75);
    }

    static std::array<double, 3>
    g_nu(const double x)
    {
      const auto r = cube_plus(x - 0.5);
      const auto h = cube_plus(0.25 - x); // h' = -cube_plus'(0.25 - x)
      return {{2 * r[0] - 8 * x * h[0],
               2 * r[1] - 8 * (h[0] - x * h[1]),
               2 * r[2] - 8 * (-2 * h[1] + x * h[2])}};
    }

    Tensor<1, 2>
    exact_value(const Point<2> &p) const
    {
      const double phi = 1 + p[1];
      return Tensor<1, 2>({phi * g_tau(p[0])[0], -phi * g_nu(p[0])[0]});
    }

    Tensor<2, 2>
    exact_gradient(const Point<2> &p) const
    {
      const double phi = 1 + p[1];
      const auto   gt = g_tau(p[0]), gn = g_nu(p[0]);
      return Tensor<2, 2>({{phi * gt[1], gt[0]}, {-phi * gn[1], -gn[0]}});
    }

    // $f_0 = -\mu\Delta u - (\mu+\lambda)\nabla\,\mathrm{div}\,u$, with
    // $\Delta u = (1+y)(g_\tau'', -g_\nu'')$ and
    // $\nabla\,\mathrm{div}\,u = ((1+y) g_\tau'' - g_\nu',\; g_\tau')$.
    Tensor<1, 2>
    body_force(const Point<2> &p, const double) const override
    {
      const double phi = 1 + p[1];
      const auto   gt = g_tau(p[0]), gn = g_nu(p[0]);
      return Tensor<1, 2>(
        {-mu * phi * gt[2] - (mu + lambda) * (phi * gt[2] - gn[1]),
         mu * phi * gn[2] - (mu + lambda) * gt[1]});
    }

    Tensor<1, 2>
    traction(const Point<2>          &p,
             const Tensor<1, 2>      &normal,
             const types::boundary_id id,
             const double) const override
    {
      // On $\Gamma_2$ the traction is simply $\sigma(u)\nu$. On $\Gamma_3$ we
      // add what the laws would supply at the exact solution, so that the
      // discrete problem with the laws on $\Gamma_3$ has $u$ as its solution in
      // the limit.
      const Tensor<1, 2> sigma_nu =
        stress(symmetrize(exact_gradient(p))) * normal;
      if (id != BoundaryIds::contact)
        return sigma_nu;
      const double u_nu   = exact_value(p) * normal;
      const double u_tau  = exact_value(p)[0]; // the tangent is e_x
      const double xi_nu  = u_nu < 0  ? 0. :
                            u_nu == 0 ? 0.5 * law.jump() :
                                        law.response(u_nu);
      const double xi_tau = u_tau == 0 ? 0.5 * friction_bound : friction_bound;
      return sigma_nu + xi_nu * normal + Tensor<1, 2>({xi_tau, 0.});
    }
  };

  // @sect3{One contact node}

  // The contact conditions hold node by node (nodal quadrature on
  // $\Gamma_3$): each node $x_i$ of $\Gamma_3$ keeps its degrees of
  // freedom, its weight $m_i = \int_{\Gamma_3}\varphi_i$, its normal
  // $\nu_i$, the constant $c_i$ of the complementarity functions, and its
  // current branches.
  enum class NormalBranch
  {
    separating, // s_nu + c u_nu < 0:    s_nu = 0, u_nu free
    stick,      // 0 <= s_nu + c u_nu <= a: u_nu = 0
    penetrating // s_nu + c u_nu > a:    s_nu = a, u_nu free
  };

  enum class TangentialBranch
  {
    stick, // |s_tau + c u_tau| <= F_b: u_tau = 0
    slip   // s_tau = F_b q/|q|, q = s_tau + c u_tau
  };

  template <int dim>
  struct ContactNode
  {
    // The position serves the output only (the x column of contact-NN.csv);
    // the dofs are the node's $d$ degrees of freedom, in the order of the
    // components; mass is $m_i$; normal is $\nu_i$; c is $c_i$. The branches
    // start as "separating" and "stick": the first update_active_set(), before
    // any Newton step, replaces them by those of the start.
    Point<dim>                               position;
    std::array<types::global_dof_index, dim> dofs;
    double                                   mass = 0;
    Tensor<1, dim>                           normal;
    double                                   c = 0;
    NormalBranch     normal_branch             = NormalBranch::separating;
    TangentialBranch tangential_branch         = TangentialBranch::stick;
  };

  // @sect3{The StaticContactProblem class}

  // The structure of step-8 (elasticity) and step-41 (an active set
  // method): make_grid(), setup_system() (which also finds the contact
  // nodes), assemble_system() for the stiffness matrix $K = B$ and the
  // load $F_n$, solve() for the active-set Newton method with its helpers,
  // and output_results(). run() solves one load value.
  template <int dim>
  class StaticContactProblem
  {
  public:
    // The problem keeps a reference to its data (the material, the law and
    // the loads), which must outlive it, and builds its mesh with the given
    // number of global refinements of the data's coarse mesh.
    StaticContactProblem(const ProblemData<dim> &data,
                         const unsigned int      n_refinements);

    // Solve at load parameter $t$, starting from the previous solution.
    void
    run(const double t);

    // Write the files of one solution, their names ending in @p name
    // (the number of the load value, or the start of the study of
    // nonconvexity), and print its summary line.
    void
    output_results(const std::string &name) const;

    // $\|u - u_h\|_{L^2}$ and $\|\varepsilon(u - u_h)\|_{L^2}$.
    // Exact is any class with exact_value() and exact_gradient(). A template
    // rather than virtual functions of ProblemData, because only the
    // manufactured solution has an exact solution to compare with.
    template <class Exact>
    std::pair<double, double>
    compute_errors(const Exact &exact) const;

    unsigned int
    n_dofs() const
    {
      return dof_handler.n_dofs();
    }

    // The constant $\lambda_1$ of the smallness condition (the
    // introduction, "Uniqueness"): $J_h$ is strictly convex, and the
    // discrete problem has exactly one solution, when $\alpha_\nu <
    // \lambda_1$.
    double
    smallness_constant() const;

    // The Newton iterations of the last run(), for the convergence table.
    unsigned int newton_iterations = 0;

    // The study of nonconvexity (at the end of the program) chooses where
    // the iteration starts, and compares the energies $J_h$ of the
    // solutions it finds: run() starts from whatever set_solution() left.
    const Vector<double> &
    get_solution() const
    {
      return solution;
    }

    void
    set_solution(const Vector<double> &u)
    {
      solution = u;
    }

    double
    energy(const Vector<double> &u) const;

    // The largest penetration $\max_i u_{i,\nu}$ over the contact nodes.
    double
    largest_penetration() const
    {
      double largest = 0;
      for (const ContactNode<dim> &node : contact_nodes)
        {
          double u_nu = 0;
          for (unsigned int c = 0; c < dim; ++c)
            u_nu += solution(node.dofs[c]) * node.normal[c];
          largest = std::max(largest, u_nu);
        }
      return largest;
    }

  private:
    void
    make_grid(const unsigned int n_refinements);
    void
    setup_system();
    void
    setup_contact_nodes();
    void
    assemble_system(const AffineConstraints<double> &constraints,
                    SparseMatrix<double>            &matrix,
                    Vector<double>                  &rhs) const;
    void
    solve();

    // The pieces of solve(): the state of a node at the current iterate,
    // the branches, the nonsmooth residual, the Newton system and the
    // energy of the line search.
    struct NodeState;
    NodeState
    node_state(const ContactNode<dim> &node,
               const Vector<double>   &residual) const;
    unsigned int
    update_active_set(const Vector<double> &residual);
    double
    nonsmooth_residual(const Vector<double> &residual) const;
    void
    assemble_newton_system(const Vector<double> &residual);

    const ProblemData<dim> &data;
    double                  time = 0; // the load parameter t

    // The finite element machinery of step-8: a mesh, $Q_1$ in each of the
    // $d$ components, and the numbering of the degrees of freedom.
    Triangulation<dim> triangulation;
    FESystem<dim>      fe;
    DoFHandler<dim>    dof_handler;

    // Two sets of constraints: the clamped boundary alone, with which $K$
    // and $F_n$ are assembled, and the clamped boundary plus the held
    // conditions of the current branches, rebuilt in every Newton
    // iteration (as step-41 rebuilds its active set).
    AffineConstraints<double> clamped_constraints;
    AffineConstraints<double> newton_constraints;

    // $K$ and the matrix of one Newton step share one sparsity pattern:
    // the contact terms couple only the components of one node, which the
    // pattern of $K$ already holds.
    SparsityPattern      sparsity_pattern;
    SparseMatrix<double> stiffness_matrix;
    SparseMatrix<double> newton_matrix;

    Vector<double> solution;   // $u$, kept from one load value to the next
    Vector<double> load;       // $F_n$
    Vector<double> newton_rhs; // $g$ of the Newton step, condensed

    std::vector<ContactNode<dim>> contact_nodes;
  };

  // The constructor builds the mesh and the system; the solution starts
  // at zero.
  template <int dim>
  StaticContactProblem<dim>::StaticContactProblem(
    const ProblemData<dim> &data,
    const unsigned int      n_refinements)
    : data(data)
    , fe(FE_Q<dim>(1), dim)
    , dof_handler(triangulation)
  {
    make_grid(n_refinements);
    setup_system();
  }

  // @sect4{StaticContactProblem::make_grid}

  template <int dim>
  void
  StaticContactProblem<dim>::make_grid(const unsigned int n_refinements)
  {
    // The coarse mesh comes from the data (one cell per unit length), so
    // that every refinement halves $h$ and the points where the
    // manufactured solution switches branches stay mesh vertices.
    data.make_coarse_grid(triangulation);
    triangulation.refine_global(n_refinements);
  }

  // @sect4{StaticContactProblem::setup_system}

  // $V^h$: continuous $Q_1$ vector fields vanishing on $\Gamma_1$. The
  // sparsity pattern couples every component of a node with every
  // component of its neighbours, so it also holds the entries that the
  // contact constraints of solve() create (they tie the components of one
  // node together).
  template <int dim>
  void
  StaticContactProblem<dim>::setup_system()
  {
    // The clamped boundary $\Gamma_1$ (boundary id 0) becomes constraints
    // $u = 0$ on its degrees of freedom; assembling with them (as step-8
    // does) keeps $K$ symmetric and positive definite on the remaining ones.
    dof_handler.distribute_dofs(fe);

    clamped_constraints.clear();
    VectorTools::interpolate_boundary_values(dof_handler,
                                             BoundaryIds::clamped,
                                             Functions::ZeroFunction<dim>(dim),
                                             clamped_constraints);
    clamped_constraints.close();

    // We build the pattern without the constraints: the Newton constraints
    // change from iteration to iteration, and a pattern that ignores them has
    // room for every set of them (each ties only the components of one node,
    // which are coupled anyway).
    DynamicSparsityPattern dsp(dof_handler.n_dofs());
    DoFTools::make_sparsity_pattern(dof_handler, dsp);
    sparsity_pattern.copy_from(dsp);
    stiffness_matrix.reinit(sparsity_pattern);
    newton_matrix.reinit(sparsity_pattern);

    solution.reinit(dof_handler.n_dofs());
    load.reinit(dof_handler.n_dofs());
    newton_rhs.reinit(dof_handler.n_dofs());

    // The contact nodes need the diagonal of $K$ (their constants $c_i$),
    // so $K$ is assembled here, before any load value; run() assembles it
    // again together with the load of its $t$ (one function computes both,
    // and $K$ comes out the same).
    assemble_system(clamped_constraints, stiffness_matrix, load);
    setup_contact_nodes();
  }

  // @sect4{The contact nodes}

  // The nodal weights $m_i = \int_{\Gamma_3}\varphi_i$ and the nodal
  // normals $\nu_i = \int_{\Gamma_3}\varphi_i\nu / |\cdot|$ are assembled
  // like a right-hand side. Nodes on $\Gamma_1$ are not contact nodes
  // (they do not move). The constant $c_i$ of the complementarity
  // functions is the mean diagonal entry of $K$ at the node over $m_i$,
  // and at least twice the law's steepest rise. Why a floor: on a free
  // segment the multiplier $s_\nu$ falls by $p'$ as $u_\nu$ grows, so $q =
  // s + c\,u_\nu$ grows along the law only if $c > p'$; below that an
  // iterate could be held on the wrong branch. The diagonal of $K$ makes
  // $c_i u_\nu$ and $s$ forces of the same size, so that neither term of
  // $q$ drowns the other. $c_i$ changes the path of the iteration, never
  // its solution (the complementarity functions vanish at the same
  // points for every $c > 0$).
  template <int dim>
  void
  StaticContactProblem<dim>::setup_contact_nodes()
  {
    Vector<double> mass(dof_handler.n_dofs()), normal(dof_handler.n_dofs());
    const QGauss<dim - 1>                face_quadrature(2);
    FEFaceValues<dim>                    fe_face_values(fe,
                                     face_quadrature,
                                     update_values | update_normal_vectors |
                                       update_JxW_values);
    std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());

    for (const auto &cell : dof_handler.active_cell_iterators())
      for (const auto &face : cell->face_iterators())
        if (face->at_boundary() && face->boundary_id() == BoundaryIds::contact)
          {
            // The face integrals of $\varphi_i$ and $\varphi_i\nu$ with two
            // Gauss points are exact for $Q_1$ on straight faces. Each
            // component's shape function contributes to its own entry, so that
            // mass and normal come out per degree of freedom: we read the mass
            // at the node's first component and the normal's components at
            // its components.
            fe_face_values.reinit(cell, face);
            cell->get_dof_indices(dofs);
            for (const unsigned int q :
                 fe_face_values.quadrature_point_indices())
              for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
                {
                  const unsigned int c = fe.system_to_component_index(i).first;
                  const double       phi_JxW =
                    fe_face_values.shape_value_component(i, q, c) *
                    fe_face_values.JxW(q);
                  mass(dofs[i]) += phi_JxW;
                  normal(dofs[i]) +=
                    phi_JxW * fe_face_values.normal_vector(q)[c];
                }
          }

    // Every vertex of $\Gamma_3$ is met once per face it belongs to: the
    // flags keep the first meeting. A vertex that is also on $\Gamma_1$
    // (the corner of the clamped side) is held at zero by the clamped
    // constraints and must not get contact conditions too: a degree of
    // freedom can carry only one constraint.
    contact_nodes.clear();
    std::vector<bool> seen(dof_handler.n_dofs(), false);
    for (const auto &cell : dof_handler.active_cell_iterators())
      for (const auto &face : cell->face_iterators())
        if (face->at_boundary() && face->boundary_id() == BoundaryIds::contact)
          for (const unsigned int v : face->vertex_indices())
            {
              ContactNode<dim> node;
              for (unsigned int c = 0; c < dim; ++c)
                node.dofs[c] = face->vertex_dof_index(v, c);
              if (seen[node.dofs[0]] ||
                  clamped_constraints.is_constrained(node.dofs[0]))
                continue;
              seen[node.dofs[0]] = true;
              node.position      = face->vertex(v);
              node.mass          = mass(node.dofs[0]);
              double diagonal    = 0;
              for (unsigned int c = 0; c < dim; ++c)
                {
                  node.normal[c] = normal(node.dofs[c]);
                  diagonal += stiffness_matrix.diag_element(node.dofs[c]) / dim;
                }
              node.normal /= node.normal.norm();
              node.c =
                std::max(diagonal / node.mass, 2 * data.law.steepest_rise);
              contact_nodes.push_back(node);
            }
  }

  // @sect4{StaticContactProblem::assemble_system}

  // The cell terms of the energy, condensed with the given constraints:
  // the stiffness $\int_K B\varepsilon(\varphi_j) : \varepsilon(
  // \varphi_i)$ (Gauss, 2 points per direction, exact for $Q_1$ on
  // parallelograms) and the load $\int_K f_0\cdot\varphi_i +
  // \int_{\partial K\cap(\Gamma_2\cup\Gamma_3)} f\cdot\varphi_i$ (3
  // points per direction). With the clamped constraints alone this is $K$
  // and $F_n$, the quadratic part $\frac12 u\cdot K u - F_n\cdot u$ of the
  // energy $J$; solve() calls it again with the constraints of each
  // Newton step.
  template <int dim>
  void
  StaticContactProblem<dim>::assemble_system(
    const AffineConstraints<double> &constraints,
    SparseMatrix<double>            &matrix,
    Vector<double>                  &rhs) const
  {
    const FEValuesExtractors::Vector     displacement(0);
    const unsigned int                   n = fe.n_dofs_per_cell();
    FEValues<dim>                        fe_values(fe,
                            QGauss<dim>(2),
                            update_gradients | update_JxW_values);
    FEValues<dim>                        fe_load(fe,
                          QGauss<dim>(3),
                          update_values | update_quadrature_points |
                            update_JxW_values);
    FEFaceValues<dim>                    fe_face(fe,
                              QGauss<dim - 1>(3),
                              update_values | update_quadrature_points |
                                update_normal_vectors | update_JxW_values);
    FullMatrix<double>                   cell_matrix(n, n);
    Vector<double>                       cell_rhs(n);
    std::vector<types::global_dof_index> dofs(n);

    // The constraints are applied while assembling
    // (distribute_local_to_global()), so the matrix and the vector come out
    // condensed: for the clamped constraints that is $K$ and $F_n$ with the
    // clamped rows decoupled, for those of a Newton step the reduced
    // system of that step. The load uses one Gauss point more than the
    // matrix: the data are not polynomials (the manufactured ones are
    // piecewise cubic and jump on $\Gamma_3$), and their quadrature error
    // must stay below the discretisation error on the finest mesh.
    matrix = 0;
    rhs    = 0;
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        // The cell matrix is step-8's: $\sigma(\varphi_i) = B\varepsilon(
        // \varphi_i)$ against $\varepsilon(\varphi_j)$, with the stress law of
        // the problem data, so that a different material changes one function.
        cell_matrix = 0;
        cell_rhs    = 0;
        fe_values.reinit(cell);
        for (const unsigned int q : fe_values.quadrature_point_indices())
          for (unsigned int i = 0; i < n; ++i)
            {
              const SymmetricTensor<2, dim> sigma_i =
                data.stress(fe_values[displacement].symmetric_gradient(i, q));
              for (unsigned int j = 0; j < n; ++j)
                cell_matrix(i, j) +=
                  sigma_i * fe_values[displacement].symmetric_gradient(j, q) *
                  fe_values.JxW(q);
            }

        fe_load.reinit(cell);
        for (const unsigned int q : fe_load.quadrature_point_indices())
          {
            const Tensor<1, dim> f0 =
              data.body_force(fe_load.quadrature_point(q), time);
            for (unsigned int i = 0; i < n; ++i)
              cell_rhs(i) +=
                f0 * fe_load[displacement].value(i, q) * fe_load.JxW(q);
          }
        for (const auto &face : cell->face_iterators())
          // Every boundary face that is not clamped carries a traction: $f_2$
          // on
          // $\Gamma_2$, and, for the manufactured solution, $f_3$ on $\Gamma_3$
          // (the block's data return zero there, since its contact forces come
          // from the laws alone).
          if (face->at_boundary() &&
              face->boundary_id() != BoundaryIds::clamped)
            {
              fe_face.reinit(cell, face);
              for (const unsigned int q : fe_face.quadrature_point_indices())
                {
                  const Tensor<1, dim> f =
                    data.traction(fe_face.quadrature_point(q),
                                  fe_face.normal_vector(q),
                                  face->boundary_id(),
                                  time);
                  for (unsigned int i = 0; i < n; ++i)
                    cell_rhs(i) +=
                      f * fe_face[displacement].value(i, q) * fe_face.JxW(q);
                }
            }

        cell->get_dof_indices(dofs);
        constraints.distribute_local_to_global(
          cell_matrix, cell_rhs, dofs, matrix, rhs);
      }
  }

  // @sect3{The active-set Newton method}

  // @sect4{The state of a node}

  // From the residual $R = K u - F_n$ the nodal contact force is
  // $G_i = -R_i$ (the force the laws must supply for equilibrium), and
  // the traction is $G_i/m_i$. Split into normal and tangential parts, the
  // multipliers of the convex parts of the laws are (the members s_nu and
  // s_tau of NodeState)
  // @f[
  //   s_\nu = G_i\cdot\nu/m_i - p(u_\nu),\qquad
  //   s_\tau = G_{i,\tau}/m_i
  // @f]
  // (Tresca friction has no remainder), and the complementarity functions
  // (the introduction shows why they vanish exactly where the laws hold)
  // are
  // @f[
  //   C_\nu = s_\nu - P_{[0,a]}(s_\nu + c\,u_\nu),\qquad
  //   C_\tau = s_\tau - P_{|\cdot|\le F_b}(s_\tau + c\,u_\tau).
  // @f]
  // Both vanish exactly at a solution of the nodal contact conditions.
  template <int dim>
  // The members, in the order of the formulas above: the normal
  // displacement and the slip, the two multipliers, and the arguments of
  // the two projections. We recompute them from the residual whenever they
  // are needed instead of storing them in ContactNode: they change with
  // every iterate, and a stored copy could go stale.
  struct StaticContactProblem<dim>::NodeState
  {
    double         u_nu;
    Tensor<1, dim> u_tau;
    double         s_nu;
    Tensor<1, dim> s_tau;
    double         q_nu;  // s_nu + c u_nu
    Tensor<1, dim> q_tau; // s_tau + c u_tau
  };

  template <int dim>
  typename StaticContactProblem<dim>::NodeState
  StaticContactProblem<dim>::node_state(const ContactNode<dim> &node,
                                        const Vector<double>   &residual) const
  {
    Tensor<1, dim> u, traction;
    for (unsigned int c = 0; c < dim; ++c)
      {
        u[c]        = solution(node.dofs[c]);
        traction[c] = -residual(node.dofs[c]) / node.mass;
      }
    // The residual at a contact node is the force the laws do not yet
    // supply; divided by the weight $m_i$ it is a traction, comparable with
    // the law's response $\xi$ and the friction bound $F_b$.
    NodeState m;
    m.u_nu  = u * node.normal;
    m.u_tau = u - m.u_nu * node.normal;
    m.s_nu  = traction * node.normal - data.law.remainder(m.u_nu);
    m.s_tau = traction - (traction * node.normal) * node.normal;
    m.q_nu  = m.s_nu + node.c * m.u_nu;
    m.q_tau = m.s_tau + node.c * m.u_tau;
    return m;
  }

  // The projection onto the friction disk $|s_\tau| \le F_b$.
  template <int dim>
  Tensor<1, dim>
  project_on_disk(const Tensor<1, dim> &q, const double F_b)
  {
    return q.norm() <= F_b ? q : F_b / q.norm() * q;
  }

  // @sect4{The branches}

  // The branch of each node follows from the projections: $q_\nu < 0$
  // separating, $0 \le q_\nu \le a$ stick (held at $u_\nu = 0$), $q_\nu >
  // a$ penetrating; $|q_\tau| \le F_b$ stick ($u_\tau = 0$), otherwise
  // slip. Returns the number of nodes whose branches changed.
  template <int dim>
  unsigned int
  StaticContactProblem<dim>::update_active_set(const Vector<double> &residual)
  {
    unsigned int n_changed = 0;
    for (ContactNode<dim> &node : contact_nodes)
      {
        const NodeState m = node_state(node, residual);
        // The thresholds are the kinks of the projections: a value exactly on a
        // kink goes to the held branch, where the projection is the identity.
        const NormalBranch     nb = m.q_nu < 0 ? NormalBranch::separating :
                                    m.q_nu <= data.law.jump() ?
                                                 NormalBranch::stick :
                                                 NormalBranch::penetrating;
        const TangentialBranch tb = m.q_tau.norm() <= data.friction_bound ?
                                      TangentialBranch::stick :
                                      TangentialBranch::slip;
        if (nb != node.normal_branch || tb != node.tangential_branch)
          ++n_changed;
        node.normal_branch     = nb;
        node.tangential_branch = tb;
      }
    return n_changed;
  }

  // The nonsmooth residual: equilibrium $R$ on the free degrees of freedom
  // that are not at contact nodes, plus the complementarity functions at
  // the contact nodes, weighted by $m_i$ to be forces too.
  template <int dim>
  double
  StaticContactProblem<dim>::nonsmooth_residual(
    const Vector<double> &residual) const
  {
    // At a contact node the residual is not expected to vanish (it is the
    // contact force); there the complementarity functions take its place.
    // The clamped rows of the residual are zero already (the condensed
    // $K$ times a $u$ that vanishes there, minus a zero load).
    // Both parts are forces, so we add their squares: a mixed norm in which
    // neither the equilibrium nor the contact conditions can hide behind the
    // other.
    Vector<double> free_part(residual);
    double         contact_part = 0;
    for (const ContactNode<dim> &node : contact_nodes)
      {
        for (unsigned int c = 0; c < dim; ++c)
          free_part(node.dofs[c]) = 0;
        const NodeState m = node_state(node, residual);
        const double    C_nu =
          m.s_nu - std::min(std::max(m.q_nu, 0.), data.law.jump());
        const Tensor<1, dim> C_tau =
          m.s_tau - project_on_disk(m.q_tau, data.friction_bound);
        contact_part +=
          node.mass * node.mass * (C_nu * C_nu + C_tau.norm_square());
      }
    return std::sqrt(free_part.norm_sqr() + contact_part);
  }

  // @sect4{The Newton system}

  // On the current branches the problem is smooth, and one Newton step
  // minimises its quadratic model $\frac12 x\cdot(K + L)x - g\cdot x$
  // over the displacements that satisfy the held conditions:
  // - a stick node in the normal direction: $x_i\cdot\nu_i = 0$;
  // - a stick node in the tangential direction: $x_i - (x_i\cdot\nu_i)
  //   \nu_i = 0$.
  //
  // Free branches add the nodal force $f_i$ of the laws and its
  // derivative $L_i$, with $g_i = F_i + L_i u_i - f_i$:
  // - penetrating: $f_i = m_i (a + p(u_\nu))\nu$, $L_i = m_i p'(u_\nu)
  //   \nu\otimes\nu$ (negative on a falling segment of the law);
  // - slip: $f_i = m_i F_b d + T_i u_\tau$, $d = q_\tau/|q_\tau|$, and
  //   $L_i = T_i$, the condensed tangent of the friction disk $T_i = m_i
  //   F_b c /(|q_\tau| - F_b)\,(I - \nu\otimes\nu - d\otimes d)$, which
  //   vanishes in 2D (the denominator is kept above $|q_\tau|/100$ for
  //   nodes that barely slip). The term $T_i u_\tau$: the Newton step of
  //   $C_\tau = 0$ gives the new multiplier $s_\tau = F_b d + T_i x_i /
  //   m_i$, whose part across $d$ grows with the new slip $x_i$. Written as
  //   $f_i + L_i(x_i - u_i)$, like the other forces, it needs $f_i = m_i
  //   F_b d + T_i u_i$, and $T_i u_i = T_i u_\tau$ since $T_i\nu = 0$.
  //
  // The held conditions are linear constraints between the components of
  // a node, solved for its component of largest $|\nu_c|$; deal.II's
  // AffineConstraints eliminates them while assembling, as step-41 does
  // for its active set.
  template <int dim>
  void
  StaticContactProblem<dim>::assemble_newton_system(
    const Vector<double> &residual)
  {
    newton_constraints.clear();
    newton_constraints.merge(clamped_constraints);
    for (const ContactNode<dim> &node : contact_nodes)
      {
        const bool normal_held = node.normal_branch == NormalBranch::stick;
        const bool tangent_held =
          node.tangential_branch == TangentialBranch::stick;
        // A held condition is solved for one component, and we divide by that
        // component of the normal: we pick the largest, $|\nu_k| \ge
        // 1/\sqrt{d}$, so that the division is always well conditioned,
        // whatever the shape of $\Gamma_3$.
        unsigned int k = 0;
        for (unsigned int c = 1; c < dim; ++c)
          if (std::abs(node.normal[c]) > std::abs(node.normal[k]))
            k = c;
        if (normal_held && tangent_held) // x_i = 0
          for (unsigned int c = 0; c < dim; ++c)
            newton_constraints.add_line(node.dofs[c]);
        else if (normal_held) // x_k = -sum_{c != k} nu_c/nu_k x_c
          {
            newton_constraints.add_line(node.dofs[k]);
            for (unsigned int c = 0; c < dim; ++c)
              if (c != k && node.normal[c] != 0)
                newton_constraints.add_entry(node.dofs[k],
                                             node.dofs[c],
                                             -node.normal[c] / node.normal[k]);
          }
        else if (tangent_held) // x_c = nu_c/nu_k x_k for c != k
          for (unsigned int c = 0; c < dim; ++c)
            if (c != k)
              {
                newton_constraints.add_line(node.dofs[c]);
                if (node.normal[c] != 0)
                  newton_constraints.add_entry(node.dofs[c],
                                               node.dofs[k],
                                               node.normal[c] / node.normal[k]);
              }
      }
    newton_constraints.close();

    assemble_system(newton_constraints, newton_matrix, newton_rhs);

    // The constraints are closed, and the cell terms are in the matrix and the
    // right-hand side. What remains are the nodal terms of the free branches,
    // which we add through the same constraints, as if each contact node were
    // a little element with $d$ degrees of freedom.
    // the nodal terms of the free branches
    FullMatrix<double>                   node_matrix(dim, dim);
    Vector<double>                       node_rhs(dim);
    std::vector<types::global_dof_index> node_dofs(dim);
    for (const ContactNode<dim> &node : contact_nodes)
      {
        const NodeState      m  = node_state(node, residual);
        const Tensor<1, dim> nu = node.normal;
        Tensor<2, dim>       L;
        Tensor<1, dim>       f;
        if (node.normal_branch == NormalBranch::penetrating)
          {
            f +=
              node.mass * (data.law.jump() + data.law.remainder(m.u_nu)) * nu;
            L += node.mass * data.law.remainder_derivative(m.u_nu) *
                 outer_product(nu, nu);
          }
        if (node.tangential_branch == TangentialBranch::slip)
          {
            const double         F_b    = data.friction_bound;
            const double         qn     = m.q_tau.norm();
            const Tensor<1, dim> d      = m.q_tau / qn;
            const double         excess = std::max(qn - F_b, 1e-2 * qn);
            const Tensor<2, dim> tangent =
              node.mass * F_b * node.c / excess *
              (unit_symmetric_tensor<dim>() - outer_product(nu, nu) -
               outer_product(d, d));
            L += tangent;
            f += node.mass * F_b * d + tangent * m.u_tau;
          }
        Tensor<1, dim> u;
        for (unsigned int c = 0; c < dim; ++c)
          u[c] = solution(node.dofs[c]);
        const Tensor<1, dim> g = L * u - f;
        for (unsigned int i = 0; i < dim; ++i)
          {
            node_dofs[i] = node.dofs[i];
            node_rhs(i)  = g[i];
            for (unsigned int j = 0; j < dim; ++j)
              node_matrix(i, j) = L[i][j];
          }
        newton_constraints.distribute_local_to_global(
          node_matrix, node_rhs, node_dofs, newton_matrix, newton_rhs);
      }
  }

  // @sect4{The energy}

  // $J(u) = \frac12 u\cdot K u - F_n\cdot u + \sum_i m_i [j_\nu(u_{i,\nu})
  // + F_b |u_{i,\tau}|]$, the function the line search decreases.
  template <int dim>
  double
  StaticContactProblem<dim>::energy(const Vector<double> &u) const
  {
    // matrix_norm_square() is $u\cdot Ku$. The clamped rows of $K$ are
    // decoupled and $u$ vanishes there, so they add nothing.
    double J = 0.5 * stiffness_matrix.matrix_norm_square(u) - load * u;
    for (const ContactNode<dim> &node : contact_nodes)
      {
        Tensor<1, dim> v;
        for (unsigned int c = 0; c < dim; ++c)
          v[c] = u(node.dofs[c]);
        const double u_nu = v * node.normal;
        J +=
          node.mass * (data.law.potential(u_nu) +
                       data.friction_bound * (v - u_nu * node.normal).norm());
      }
    return J;
  }

  // @sect4{StaticContactProblem::solve}

  // The primal-dual active set iteration: compute the residual, update the
  // branches, stop when no branch changed and the nonsmooth residual is
  // below the tolerance (relative to $|F_n|$), else solve the Newton
  // system on the current branches with a direct solver and take the
  // step, halved until it does not raise $J$ (the full step if no length
  // lowers it; the rule is explained where it is coded).
  template <int dim>
  void
  StaticContactProblem<dim>::solve()
  {
    // The tolerance is relative to the load: the residual is a force, and
    // $10^{-11}|F_n|$ lies well above the round-off of evaluating it while
    // being tight enough for the comparison with the full program at
    // $10^{-10}$. Once the residual is a hundred times below it, the
    // iteration stops even if a branch still changes: a node whose
    // $q$ lies within round-off of a switch may flip back and forth
    // without changing the solution.
    const double   tolerance = 1e-11 * load.l2_norm();
    Vector<double> residual(dof_handler.n_dofs());
    newton_iterations = 0;
    for (unsigned int iteration = 0;; ++iteration)
      {
        // The residual of the current iterate decides everything else: the
        // branches, the stopping test and the right-hand side of the Newton
        // step.
        stiffness_matrix.vmult(residual, solution);
        residual -= load;
        const unsigned int n_changed = update_active_set(residual);
        const double       r         = nonsmooth_residual(residual);
        if ((n_changed == 0 && r <= tolerance) || r <= 1e-2 * tolerance)
          break;
        AssertThrow(iteration < 50,
                    ExcMessage("The active set Newton method did not "
                               "converge in 50 iterations."));

        assemble_newton_system(residual);
        // The matrix changes with the branches, so we factorise it in every
        // iteration. On the meshes of this program UMFPACK does this
        // quickly, and a direct solver keeps the iteration count a property
        // of the nonsmooth method alone, with no inner tolerance to tune.
        SparseDirectUMFPACK direct_solver;
        direct_solver.initialize(newton_matrix);
        Vector<double> trial(newton_rhs);
        direct_solver.solve(trial);
        newton_constraints.distribute(trial);

        // The line search on $J$, the same rule as in step-2: try $\theta
        // = 1, \frac12, \frac14, \dots, 2^{-10}$ and take the first step
        // $u + \theta d$ that does not raise $J$ beyond round-off (a
        // relative $10^{-12}$, since $J$ is a sum of terms of either sign
        // and its last digits are noise). A full Newton step can raise $J$
        // because $j_\nu$ is not convex: the quadratic model of one branch
        // is wrong beyond that branch's segment of the law. If no step
        // length lowers $J$ (the direction is not one of descent, which
        // happens only while the branches are still wrong), the full step
        // is taken: a tiny step would leave the branches as they are and
        // stall the iteration, while the full step moves to the branches
        // the next update_active_set() corrects. The default run (the block
        // and five levels) never reaches that fallback.
        // The trial vector holds the new iterate $u + d$; the direction is the
        // difference, and the loop below tries fractions of it.
        Vector<double> direction(trial);
        direction -= solution;
        const double J0    = energy(solution);
        double       theta = 1;
        for (; theta >= 1. / 1024; theta /= 2)
          {
            trial = solution;
            trial.add(theta, direction);
            const double J = energy(trial);
            if (J <= J0 + 1e-12 * (std::abs(J0) + std::abs(J)))
              break;
          }
        if (theta < 1. / 1024)
          theta = 1;
        solution.add(theta, direction);
        ++newton_iterations;
      }
  }

  // @sect4{StaticContactProblem::run}

  // One load value: assemble the load at $t$ and solve.
  template <int dim>
  void
  StaticContactProblem<dim>::run(const double t)
  {
    // $K$ does not depend on $t$, so assembling it again is wasted work; we
    // accept it because one function assembles both, and every Newton step
    // that follows assembles a matrix of the same size anyway.
    time = t;
    assemble_system(clamped_constraints, stiffness_matrix, load);
    solve();
  }

  // @sect4{StaticContactProblem::smallness_constant}

  // The uniqueness condition of the introduction asks that
  // @f[
  //   \lambda_1 = \min_{v \ne 0}
  //     \frac{v\cdot K v}{\sum_i m_i (v_i\cdot\nu_i)^2} > \alpha_\nu,
  // @f]
  // the smallest eigenvalue of the pencil $(K, M_\nu)$ with the normal boundary
  // mass $M_\nu = \sum_i m_i \nu_i\otimes\nu_i$ (nodal quadrature of
  // $\int_{\Gamma_3} v_\nu^2$). $M_\nu$ is singular (it sees only the normal
  // components on $\Gamma_3$), so we compute the largest eigenvalue
  // $1/\lambda_1$ of $K^{-1}M_\nu$ instead, by the power iteration
  // $x \leftarrow K^{-1} M_\nu x$: each step is one solve with the UMFPACK
  // factorisation of $K$, computed once. The Rayleigh quotient
  // $x\cdot Kx / x\cdot M_\nu x$ of the iterate approaches $\lambda_1$ from
  // above, with an error of the square of the iterate's; we stop when it
  // changes by less than $10^{-12}$ relative. The start is the normal
  // field on $\Gamma_3$, which the lowest mode resembles. The full program
  // estimates the same number (by a preconditioned eigensolver) and warns
  // when $\alpha_\nu$ is not below it. Nothing here changes the solution.
  template <int dim>
  double
  StaticContactProblem<dim>::smallness_constant() const
  {
    // We never assemble $M_\nu$ as a matrix: it is diagonal in the nodes, and
    // applying it is one loop over the contact nodes, which project $v$ onto
    // their normals and weight it with $m_i$.
    const auto apply_M_nu = [&](const Vector<double> &v, Vector<double> &Mv) {
      Mv = 0;
      for (const ContactNode<dim> &node : contact_nodes)
        {
          double v_nu = 0;
          for (unsigned int c = 0; c < dim; ++c)
            v_nu += v(node.dofs[c]) * node.normal[c];
          for (unsigned int c = 0; c < dim; ++c)
            Mv(node.dofs[c]) = node.mass * v_nu * node.normal[c];
        }
    };

    // The clamped degrees of freedom have a nonzero diagonal entry in the
    // condensed $K$ (deal.II puts one there when it condenses), so $K$ is
    // invertible, and the power iteration never sees them: $M_\nu$ vanishes
    // there.
    SparseDirectUMFPACK K_inverse;
    K_inverse.initialize(stiffness_matrix);
    Vector<double> x(dof_handler.n_dofs()), Mx(x), Kx(x);
    for (const ContactNode<dim> &node : contact_nodes)
      for (unsigned int c = 0; c < dim; ++c)
        x(node.dofs[c]) = node.normal[c];

    // The power iteration. Each step applies $K^{-1}M_\nu$ and normalises; the
    // iterate approaches the eigenvector of the largest eigenvalue of
    // $K^{-1}M_\nu$ at the rate of the ratio of the two largest, and the cap of
    // 1000 steps guards against a pair too close to separate.
    double lambda = std::numeric_limits<double>::max();
    for (unsigned int iteration = 0; iteration < 1000; ++iteration)
      {
        apply_M_nu(x, Mx);
        K_inverse.vmult(x, Mx);
        x /= x.l2_norm();
        stiffness_matrix.vmult(Kx, x);
        apply_M_nu(x, Mx);
        const double quotient = (x * Kx) / (x * Mx);
        if (std::abs(quotient - lambda) <= 1e-12 * quotient)
          return quotient;
        lambda = quotient;
      }
    AssertThrow(false,
                ExcMessage("The power iteration for the smallness constant "
                           "did not converge in 1000 steps."));
    return lambda;
  }

  // @sect4{StaticContactProblem::output_results}

  // Four files per solution, their names ending in @p name: the
  // displacement for ParaView (solution-NN.vtu), the contact quantities
  // along $\Gamma_3$ (contact-NN.csv: $u_\nu$, $u_\tau$, $-\sigma_\nu$,
  // $\sigma_\tau$ and the branches; the traction is $-R_i/m_i$), the nodal
  // displacement in full double precision (displacement-NN.txt, for the
  // comparison with the full program) and the cells with the displacement
  // of their vertices (body-NN.csv, from which doc/plot_body.py draws the
  // deformed mesh without ParaView). A short summary line goes to the
  // terminal.
  template <int dim>
  void
  StaticContactProblem<dim>::output_results(const std::string &name) const
  {
    DataOut<dim> data_out;
    // The VTU file, as in step-8: the $d$ components together form one vector
    // field, so that ParaView can warp the mesh by it.
    data_out.attach_dof_handler(dof_handler);
    const std::vector<DataComponentInterpretation::DataComponentInterpretation>
      interpretation(dim,
                     DataComponentInterpretation::component_is_part_of_vector);
    data_out.add_data_vector(solution,
                             std::vector<std::string>(dim, "displacement"),
                             DataOut<dim>::type_dof_data,
                             interpretation);
    data_out.build_patches();
    std::ofstream vtu("solution-" + name + ".vtu");
    data_out.write_vtu(vtu);

    // The picture of the body needs only what a plot library can draw: one
    // polygon per cell. We write each cell's vertices in counterclockwise
    // order (deal.II numbers the vertices of a quadrilateral
    // lexicographically, 0 1 / 2 3, so the order around it is 0, 1, 3, 2)
    // with the displacement there and, at a contact node, its two branches
    // (-1 elsewhere); the script adds position and displacement and
    // colours the contact nodes by branch.
    if (dim == 2)
      {
        std::map<types::global_dof_index, const ContactNode<dim> *> node_at;
        for (const ContactNode<dim> &node : contact_nodes)
          node_at[node.dofs[0]] = &node;
        std::ofstream body("body-" + name + ".csv");
        body << "cell,x,y,u_x,u_y,normal_branch,tangential_branch\n"
             << std::setprecision(10);
        for (const auto &cell : dof_handler.active_cell_iterators())
          for (const unsigned int v : {0u, 1u, 3u, 2u})
            {
              body << cell->active_cell_index();
              for (unsigned int c = 0; c < dim; ++c)
                body << ',' << cell->vertex(v)[c];
              for (unsigned int c = 0; c < dim; ++c)
                body << ',' << solution(cell->vertex_dof_index(v, c));
              const auto node = node_at.find(cell->vertex_dof_index(v, 0));
              if (node == node_at.end())
                body << ",-1,-1\n";
              else
                body << ',' << static_cast<int>(node->second->normal_branch)
                     << ',' << static_cast<int>(node->second->tangential_branch)
                     << '\n';
            }
      }

    // The contact quantities come from the residual at the solution, as in
    // solve(): the column minus_sigma_nu is $s_\nu + p(u_\nu)$, the whole
    // normal traction, and sigma_tau the first component of the
    // multiplier $s_\tau$ (the tangent of the bottom is $e_x$).
    // (The residual at the solution is the contact force that balances the
    // body; dividing by $m_i$ turns it into the traction a pressure sensor in
    // the foundation would read.)
    Vector<double> residual(dof_handler.n_dofs());
    stiffness_matrix.vmult(residual, solution);
    residual -= load;
    std::ofstream csv("contact-" + name + ".csv");
    csv << "x,u_nu,u_tau,minus_sigma_nu,sigma_tau,normal_branch,"
           "tangential_branch\n";
    unsigned int n_normal[3] = {0, 0, 0}, n_tangential[2] = {0, 0};
    for (const ContactNode<dim> &node : contact_nodes)
      {
        const NodeState m = node_state(node, residual);
        csv << std::setprecision(10) << node.position[0] << ',' << m.u_nu << ','
            << m.u_tau[0] << ',' << m.s_nu + data.law.remainder(m.u_nu) << ','
            << m.s_tau[0] << ',' << static_cast<int>(node.normal_branch) << ','
            << static_cast<int>(node.tangential_branch) << '\n';
        ++n_normal[static_cast<int>(node.normal_branch)];
        ++n_tangential[static_cast<int>(node.tangential_branch)];
      }

    // The nodal file uses printf's %.17g, which prints a double so that it
    // reads back bit for bit: the comparison with the full program at
    // $10^{-10}$ must not be limited by the output.
    std::FILE *nodal =
      std::fopen(("displacement-" + name + ".txt").c_str(), "w");
    std::vector<bool> written(triangulation.n_vertices(), false);
    for (const auto &cell : dof_handler.active_cell_iterators())
      for (const unsigned int v : cell->vertex_indices())
        if (!written[cell->vertex_index(v)])
          {
            written[cell->vertex_index(v)] = true;
            for (unsigned int c = 0; c < dim; ++c)
              std::fprintf(nodal, "%.17g ", cell->vertex(v)[c]);
            for (unsigned int c = 0; c < dim; ++c)
              std::fprintf(nodal,
                           c + 1 < dim ? "%.17g " : "%.17g\n",
                           solution(cell->vertex_dof_index(v, c)));
          }
    std::fclose(nodal);

    // The line that the results page shows for every load value: the Newton
    // iterations and how many nodes are on each branch.
    std::cout << "t = " << std::fixed << std::setprecision(2) << time << ": "
              << newton_iterations
              << " Newton iterations, normal separating/stick/penetrating "
              << n_normal[0] << '/' << n_normal[1] << '/' << n_normal[2]
              << ", tangential stick/slip " << n_tangential[0] << '/'
              << n_tangential[1] << std::defaultfloat << std::endl;
  }

  // @sect4{StaticContactProblem::compute_errors}

  // $E_H = \|u - u_h\|_{L^2}$ and $E_V = \|\varepsilon(u - u_h)\|_{L^2}$
  // with a 4-point Gauss rule per direction: two points more than the
  // assembly, since the exact solution is a cubic and the quadrature error
  // must stay below the discretisation error on the finest mesh.
  template <int dim>
  template <class Exact>
  std::pair<double, double>
  StaticContactProblem<dim>::compute_errors(const Exact &exact) const
  {
    const QGauss<dim>                    quadrature(4);
    FEValues<dim>                        fe_values(fe,
                            quadrature,
                            update_values | update_gradients |
                              update_quadrature_points | update_JxW_values);
    const FEValuesExtractors::Vector     displacement(0);
    std::vector<Tensor<1, dim>>          values(quadrature.size());
    std::vector<SymmetricTensor<2, dim>> strains(quadrature.size());
    double                               E_H2 = 0, E_V2 = 0;
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        // We integrate the squared errors cell by cell, with the exact solution
        // at the quadrature points and the discrete one interpolated there by
        // FEValues.
        fe_values.reinit(cell);
        fe_values[displacement].get_function_values(solution, values);
        fe_values[displacement].get_function_symmetric_gradients(solution,
                                                                 strains);
        for (const unsigned int q : fe_values.quadrature_point_indices())
          {
            const Point<dim> &x = fe_values.quadrature_point(q);
            E_H2 += (exact.exact_value(x) - values[q]).norm_square() *
                    fe_values.JxW(q);
            const SymmetricTensor<2, dim> e =
              symmetrize(exact.exact_gradient(x)) - strains[q];
            E_V2 += scalar_product(e, e) * fe_values.JxW(q);
          }
      }
    return {std::sqrt(E_H2), std::sqrt(E_V2)};
  }
  // @sect3{When the smallness condition fails: several solutions}

  // Every problem above satisfies $\alpha_\nu < \lambda_1$, so $J_h$ is
  // strictly convex and has exactly one stationary point: whatever the
  // start, the iteration finds the same solution. Here we break the
  // condition on purpose, to see what the word "hemivariational" costs. We
  // keep the block, its mesh and its loads, and give it the law
  // `0:1, 0.02:3, 0.04:0.1, 0.5:0.1`: after the jump the response rises
  // to 3 and then collapses to 0.1 within a penetration of 0.02, a slope
  // of $-145$. So $\alpha_\nu = 145$, far above $\lambda_1 = 1.08$ of
  // the block: the foundation gives way much faster than the body can
  // resist, and beyond $u_\nu = 0.04$ it offers almost nothing.
  //
  // A solution of the discrete inequality is a point where the nonsmooth
  // residual vanishes, that is a stationary point of $J_h$ ($0 \in
  // \partial J_h(u)$ in Clarke's sense), and nothing more: it need not be
  // a minimiser, and different stationary points have different
  // energies. We start the same iteration from three points at the full
  // load $t = 1$:
  // - along the load path $t = 0.25, 0.5, 0.75, 1$, each value started
  //   from the solution of the one before, as in the main study (a
  //   loading history, the start a physicist would choose);
  // - from zero, the undeformed body;
  // - from three times the first solution: the same shape, pressed deeper.
  //
  // For each we print the energy $J_h$ and the largest penetration, and
  // write the four files of output_results(), so that doc/plot_body.py
  // and doc/plot_nonconvex.py draw the three bodies. Between the first
  // solution and each of the others we also write $J_h$ along the straight
  // segment joining them (energy-nonconvex.csv): where the energy rises
  // before it falls, the first solution sits in a valley of its own along
  // that line; where it falls from one end, the solution at that end is
  // no minimiser at all.
  void
  run_nonconvexity_study()
  {
    const BlockData         block({{0, 1}, {0.02, 3}, {0.04, 0.1}, {0.5, 0.1}});
    StaticContactProblem<2> problem(block, 3);
    write_law(block.law, "law-nonconvex.csv");
    const double lambda_1 = problem.smallness_constant();
    std::cout << "The block with the law 0:1,0.02:3,0.04:0.1,0.5:0.1:\n"
              << "  alpha_nu = " << std::setprecision(6) << block.law.alpha
              << ", lambda_1 = " << lambda_1
              << (block.law.alpha < lambda_1 ?
                    " (alpha_nu < lambda_1: one solution)" :
                    " (alpha_nu >= lambda_1: maybe several solutions)")
              << std::endl;

    // The report of one solution: its energy and its largest
    // penetration, then the summary line of its files.
    // Six digits of $J_h$ are enough to tell the solutions apart; the test
    // tutorial/step_1_nonconvex reads them from this line.
    const auto report = [&](const std::string &name, const std::string &start) {
      const Vector<double> &u = problem.get_solution();
      std::cout << "  " << name << ", " << start
                << ": J_h = " << std::setprecision(6) << problem.energy(u)
                << ", largest u_nu = " << problem.largest_penetration()
                << "\n    ";
      problem.output_results(name);
      return u;
    };

    // The first start: the loading history of the main study, each load value
    // started from the solution of the one before. This is also how the block
    // of the main study reaches its $t = 1$.
    for (unsigned int n = 1; n <= 4; ++n)
      problem.run(0.25 * n);
    const Vector<double> path = report("path", "along the load path");

    // The second start: the undeformed body at the full load, with no history.
    problem.set_solution(Vector<double>(problem.n_dofs()));
    problem.run(1);
    const Vector<double> zero = report("zero", "from zero");

    // The third start: the first solution, three times as deep. It starts
    // every penetrating node three times deeper on the law, nearer to its
    // peak or past it.
    Vector<double> start(path);
    start *= 3;
    problem.set_solution(start);
    problem.run(1);
    const Vector<double> triple = report("triple", "from three times path");

    // $J_h$ on the segments $u_\text{path} + \theta (u - u_\text{path})$,
    // $0 \le \theta \le 1$, to the other two solutions.
    // The three are stationary points of one function; the values of $J_h$
    // between them show what kind. We evaluate $J_h$ on 201 points of each
    // segment, enough to resolve the barrier near the first solution.
    std::ofstream profile("energy-nonconvex.csv");
    profile << "theta,path_to_zero,path_to_triple\n" << std::setprecision(10);
    for (unsigned int k = 0; k <= 200; ++k)
      {
        const double   theta = k / 200.;
        Vector<double> to_zero(path), to_triple(path);
        to_zero.sadd(1 - theta, theta, zero);
        to_triple.sadd(1 - theta, theta, triple);
        profile << theta << ',' << problem.energy(to_zero) << ','
                << problem.energy(to_triple) << '\n';
      }
  }
} // namespace Step1

// @sect3{The command line}

// The program runs everything without arguments, or one part by its mode,
// as the usage says. Its check is one table and one test in main(): the
// table names each mode and how many arguments it takes, itself included
// (the empty mode is the run without arguments); the test refuses an
// unknown mode, a surplus argument and a number of levels that is not one
// to three decimal digits from 1 to max_levels (std::stoul() alone would
// read "3x" as 3 and "-1" as four billion). A bad command line ends the
// program before anything is computed, with a message that quotes the
// arguments, the usage and the exit code 2 (1 is kept for a computation
// that fails).
namespace CommandLine
{
  const char *const usage =
    "usage: step-1                        the block, 5 levels of the\n"
    "                                     manufactured solution, the\n"
    "                                     nonconvex law on the block\n"
    "       step-1 block                  the block only\n"
    "       step-1 convergence [LEVELS]   LEVELS levels (1 to 7, default 5)\n"
    "                                     of the manufactured solution\n"
    "       step-1 nonconvex              the nonconvex law only\n"
    "       step-1 --help                 this text\n"
    "exit codes: 0 done, 1 the computation failed, 2 a bad argument";

  const std::map<std::string, std::size_t> modes = {{"", 0},
                                                    {"block", 1},
                                                    {"convergence", 2},
                                                    {"nonconvex", 1},
                                                    {"--help", 1}};

  // Each level has four times the unknowns of the one before and, with
  // UMFPACK, about four times the memory: level 7 (132,098 unknowns) took 96 s
  // and 0.63 GB, an eighth would take ten minutes and 2.5 GB, so we refuse it
  // rather than let a typo exhaust the machine.
  const unsigned int max_levels = 7;
} // namespace CommandLine

// @sect3{The main function}

// The program has three parts. First the block at four load values $t =
// 0.25, 0.5, 0.75, 1$, each one static problem started from the previous
// solution; then the manufactured solution on the meshes $h = 1/4, \dots,
// 1/64$, with the errors and their observed orders in a ConvergenceTable;
// last the study of nonconvexity, the block with a law that breaks the
// smallness condition. The modes "block", "convergence LEVELS" and
// "nonconvex" run one of them.
int
main(int argc, char **argv)
{
  using namespace Step1;
  const std::vector<std::string> arguments(argv + 1, argv + argc);
  const std::string              mode = arguments.empty() ? "" : arguments[0];
  // The default of the convergence study: five levels, $h = 1/4$ to $1/64$,
  // a few seconds in all.
  const std::string levels = arguments.size() == 2 ? arguments[1] : "5";
  // A bad command line ends here, before any output file is opened, and
  // so does --help.
  if ((!arguments.empty() && mode.empty()) ||
      CommandLine::modes.count(mode) == 0 ||
      arguments.size() > CommandLine::modes.at(mode) || levels.empty() ||
      levels.size() > 3 ||
      levels.find_first_not_of("0123456789") != std::string::npos ||
      std::stoul(levels) < 1 || std::stoul(levels) > CommandLine::max_levels)
    {
      std::cerr << "step-1: cannot run";
      for (const std::string &argument : arguments)
        std::cerr << " '" << argument << "'";
      std::cerr << ".\n" << CommandLine::usage << std::endl;
      return 2;
    }
  if (mode == "--help")
    {
      std::cout << CommandLine::usage << std::endl;
      return 0;
    }
  const unsigned int n_levels = std::stoul(levels);

  try
    {
      if (mode.empty() || mode == "block")
        {
          std::cout << "The block, 3 global refinements:" << std::endl;
          // Part 1: the block with step-1's law, which satisfies the smallness
          // condition: four load values, one solution each.
          const BlockData         block;
          StaticContactProblem<2> block_problem(block, 3);
          write_law(block.law, "law.csv");
          // The uniqueness condition, checked before solving.
          const double lambda_1 = block_problem.smallness_constant();
          std::cout << "  " << block_problem.n_dofs()
                    << " dofs, alpha_nu = " << block.law.alpha
                    << ", lambda_1 = " << lambda_1
                    << (block.law.alpha < lambda_1 ?
                          " (alpha_nu < lambda_1: one solution)" :
                          " (alpha_nu >= lambda_1: maybe several solutions)")
                    << std::endl;
          for (unsigned int n = 1; n <= 4; ++n)
            {
              block_problem.run(0.25 * n);
              std::cout << "  ";
              block_problem.output_results(Utilities::int_to_string(n, 2));
            }
        }

      if (mode.empty() || mode == "convergence")
        {
          std::cout << (mode.empty() ? "\n" : "")
                    << "The manufactured solution:" << std::endl;
          // Part 2: the manufactured solution on successively refined meshes, a
          // new problem on each, since the coarse mesh is refined globally. The
          // table collects the errors and the constant $\lambda_1$ of each
          // mesh.
          const ManufacturedData manufactured;
          ConvergenceTable       table;
          for (unsigned int refinements = 2; refinements < 2 + n_levels;
               ++refinements)
            {
              StaticContactProblem<2> problem(manufactured, refinements);
              problem.run(1);
              const auto [E_H, E_V] = problem.compute_errors(manufactured);
              table.add_value("1/h", 1u << refinements);
              table.add_value("dofs", problem.n_dofs());
              table.add_value("Newton", problem.newton_iterations);
              table.add_value("lambda_1", problem.smallness_constant());
              table.set_precision("lambda_1", 1);
              table.add_value("E_H", E_H);
              table.add_value("E_V", E_V);
            }
          for (const std::string column : {"E_H", "E_V"})
            {
              table.set_scientific(column, true);
              table.set_precision(column, 3);
              table.evaluate_convergence_rates(
                column, ConvergenceTable::reduction_rate_log2);
            }
          table.write_text(std::cout);
        }

      if (mode.empty() || mode == "nonconvex")
        {
          std::cout << (mode.empty() ? "\n" : "");
          // Part 3: the law that breaks the smallness condition.
          run_nonconvexity_study();
        }
    }
  // A computation that fails (a Newton iteration that does not converge, a
  // file that cannot be written) throws; as deal.II's tutorial programs do,
  // we print the reason and return 1.
  catch (std::exception &exc)
    {
      std::cerr << "\nException: " << exc.what() << "\nAborting!" << std::endl;
      return 1;
    }
  return 0;
}
