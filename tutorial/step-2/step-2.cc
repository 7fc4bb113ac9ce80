/* ---------------------------------------------------------------------
 *
 * hemicontact tutorial, step-2: the paper's step. step-1 plus time: a
 * Kelvin-Voigt body in dynamic contact, the velocity as the unknown of
 * each time step, and the exponential damped normal response of
 *
 *   D. Han and W. Han, "Numerical analysis of an evolutionary
 *   variational-hemivariational inequality with application to a dynamic
 *   contact problem", Journal of Computational and Applied Mathematics,
 *   2019 (Problem 4.4),
 *
 * with Tresca friction, backward Euler in the velocity and the left-point
 * rule for the displacement. Every time step is step-1's static problem
 * with other matrices, solved by step-1's primal-dual active set method.
 *
 * The introduction (doc/intro.md) states the model and lists, in its
 * table "What is new", every change against step-1.cc; the results
 * (doc/results.md) show what this program prints. The program depends on
 * deal.II alone, and it computes the same discrete solution as the full
 * program hemicontact (problem/class = dynamic, time scheme = left point,
 * the exponential law, Tresca): tests/tutorial/step_2_vs_hemicontact.sh
 * compares the two.
 *
 * ---------------------------------------------------------------------
 */

// @sect3{Include files}

// The usual deal.II headers of a serial program (step-8 for elasticity,
// step-7 for the convergence table, step-41 for an active set). They are
// step-1's: time adds vectors and a loop to the program, and no class of
// deal.II that step-1 did not use already.
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
// contact nodes, streams for the output files, and <limits> for the start
// of the power iteration and for nothing else.
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

namespace Step2
{
  using namespace dealii;

  // @sect3{The normal law}

  // In step-1 the law was a normal compliance: a response to the
  // penetration $u_\nu$. In the paper's problem it is a normal *damped
  // response*: the foundation resists the normal velocity $r = w_\nu$, the
  // rate at which the body moves into it, with the exponential law
  // @f[
  //   \partial j_\nu(r) = 0 \ (r < 0),\qquad [0, a] \ (r = 0),\qquad
  //   \xi(r) = (a - b)\, e^{-\beta r} + b \ (r > 0),
  // @f]
  // $a \ge b \ge 0$, $\beta > 0$: the response jumps to $a$ and then falls
  // towards $b$ as the body moves in faster. We split it as step-1 splits
  // its law, into the convex jump $\partial(a r_+)$ and the Lipschitz
  // remainder
  // @f[
  //   p(r) = \xi(r) - a = (a - b)\,(e^{-\beta r} - 1) \ (r > 0),\qquad
  //   p(r) = 0 \ (r \le 0).
  // @f]
  // The response falls everywhere, so $j_\nu$ is not convex; its steepest
  // descent slope is at $r = 0^+$, $\alpha_\nu = \beta(a - b)$, and it never
  // rises: steepest_rise is $0$ and the floor of the constants $c_i$
  // (setup_contact_nodes()) is $0$.
  //
  // The class has step-1's seven members, with the same meaning, so that
  // nothing else in the program sees that the law changed. step-1's
  // breakpoints() and write_law() served its figures of the piecewise
  // linear law, and are gone.
  class ExponentialLaw
  {
  public:
    ExponentialLaw(const double a, const double b, const double beta)
      : a(a)
      , b(b)
      , beta(beta)
    {
      AssertThrow(a >= b && b >= 0 && beta > 0,
                  ExcMessage("The law needs a >= b >= 0 and beta > 0."));
      alpha = beta * (a - b);
    }

    // The jump $a$ of the subdifferential at $r = 0$.
    double
    jump() const
    {
      return a;
    }

    // The response $\xi(r)$ for $r > 0$, the remainder $p(r)$ and its
    // derivative $p'(r)$.
    double
    // The response is the jump plus the remainder: $a$ at $r = 0^+$, falling
    // towards $b$ as $r$ grows.
    response(const double r) const
    {
      return a + remainder(r);
    }

    double
    remainder(const double r) const
    {
      return r > 0 ? (a - b) * (std::exp(-beta * r) - 1.) : 0.;
    }

    double
    remainder_derivative(const double r) const
    {
      return r > 0 ? -beta * (a - b) * std::exp(-beta * r) : 0.;
    }

    // The potential $j_\nu(r) = \int_0^r \xi = a r + (a - b)\bigl((1 -
    // e^{-\beta r})/\beta - r\bigr)$ for $r > 0$. We compute $1 -
    // e^{-\beta r}$ as -std::expm1($-\beta r$), which keeps its digits
    // for small $\beta r$ where the difference would cancel them: the line
    // search compares energies that differ in their last digits.
    double
    // The energy of the line search, and so the choice of step lengths,
    // rests on this number: an approximate potential would let the line
    // search accept steps that raise the true $J_n$, so we integrate $\xi$
    // in closed form.
    potential(const double r) const
    {
      if (r <= 0)
        return 0.;
      return a * r + (a - b) * (-std::expm1(-beta * r) / beta - r);
    }

    // $\alpha_\nu = \beta(a - b)$, set by the constructor, and the steepest
    // rise of the response, which is zero: the law only falls.
    double alpha = 0, steepest_rise = 0;

  private:
    // The jump $a$, the limit $b$ of the response for fast penetration and
    // the rate $\beta$ of its fall.
    const double a, b, beta;
  };

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

  // What defines one problem: the material (the density $\rho$ and the
  // Lamé constants of the viscosity $A$ and the elasticity $B$), the laws,
  // the loads $f_0$ in $\Omega$ and $f_2$ on $\Gamma_2$ at the time $t$,
  // the initial velocity $w_0$, and, in a manufactured solution, a traction
  // $f_3$ on $\Gamma_3$ and the exact solution. step-1's class had $B$
  // and the load parameter $t$; new are $\rho$, $A$, the law as an
  // argument and $w_0$. Both problems of this program start undeformed,
  // $u_0 = 0$.
  template <int dim>
  class ProblemData
  {
  public:
    ProblemData(const double          rho,
                const double          mu_A,
                const double          lambda_A,
                const double          mu,
                const double          lambda,
                const double          F_b,
                const ExponentialLaw &law)
      : density(rho)
      , mu_A(mu_A)
      , lambda_A(lambda_A)
      , mu(mu)
      , lambda(lambda)
      , friction_bound(F_b)
      , law(law)
    {}

    virtual ~ProblemData() = default;

    // What a problem supplies, in the way deal.II's Function class asks for
    // values: the coarse mesh with its boundary ids, and the two loads as
    // functions of the point and the time. Everything the solver
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

    // $w_0(x)$: the body at rest unless a problem says otherwise.
    virtual Tensor<1, dim>
    initial_velocity(const Point<dim> &) const
    {
      return Tensor<1, dim>();
    }

    // $\sigma = B\varepsilon = 2\mu\varepsilon + \lambda\,\mathrm{tr}
    // (\varepsilon) I$.
    SymmetricTensor<2, dim>
    stress(const SymmetricTensor<2, dim> &eps) const
    {
      return 2 * mu * eps + lambda * trace(eps) * unit_symmetric_tensor<dim>();
    }

    // The viscous stress $A\varepsilon = 2\mu_A\varepsilon + \lambda_A\,
    // \mathrm{tr}(\varepsilon) I$ of the Kelvin-Voigt material, whose
    // whole stress is $\sigma = A\varepsilon(w) + B\varepsilon(u)$.
    SymmetricTensor<2, dim>
    viscous_stress(const SymmetricTensor<2, dim> &eps) const
    {
      return 2 * mu_A * eps +
             lambda_A * trace(eps) * unit_symmetric_tensor<dim>();
    }

    // $\rho$ and the Lamé constants of $A$ (new), of $B$, the friction
    // bound $F_b$ and the normal law, as step-1 names them.
    const double         density, mu_A, lambda_A;
    const double         mu, lambda;
    const double         friction_bound;
    const ExponentialLaw law;
  };

  // @sect4{The block}

  // The problem the program shares with the full code (its default example
  // prm/block_2d.prm, which the test tests/tutorial/step_2_vs_hemicontact.sh
  // runs in both): a block $[0,4]\times[0,1]$ clamped on the left, free on
  // the right, on a foundation along its bottom, loaded on its top by a
  // pressure that rises to the right and in time and turns into a lift at
  // $t = 1/2$ (the sine changes sign), and by a shear that grows in time.
  // Its contact boundary sees every branch of the laws during $0 \le t \le
  // 1$. The material: $\rho = 1$; $A$ with $\mu_A = \lambda_A = 1$; $B$
  // from Young's modulus $E = 100$ and Poisson's ratio $0.3$, that is
  // $\mu = 38.46$, $\lambda = 57.69$. The law has $a = 1$, $b = 0.5$,
  // $\beta = 10$, and $F_b = 0.6$.
  class BlockData : public ProblemData<2>
  {
  public:
    BlockData()
      : ProblemData<2>(/*rho=*/1,
                       /*mu_A=*/1,
                       /*lambda_A=*/1,
                       /*mu=*/E / (2 * (1 + poisson)),
                       /*lambda=*/E * poisson /
                         ((1 + poisson) * (1 - 2 * poisson)),
                       /*F_b=*/0.6,
                       ExponentialLaw(1, 0.5, 10))
    {}

    // step-1's coarse mesh: one cell per unit length, the sides numbered
    // left 0 (clamped), right 1, bottom 2 (contact), top 3.
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
      // On the top $f_2 = \bigl(2\sin(\pi t)\,x/4,\; -3\sin(2\pi t)\,(1/4 +
      // x/4)\bigr)$: a shear that grows and falls back once over $[0, 1]$,
      // and a pressure that rises to the right, is largest at $t = 1/4$,
      // turns into a lift after $t = 1/2$ and into a pressure again after
      // $t = 1$. The other sides carry no traction.
      if (id != 3) // the top; the right side is free
        return Tensor<1, 2>();
      return Tensor<1, 2>(
        {2 * std::sin(numbers::PI * t) * x[0] / 4,
         -3 * std::sin(2 * numbers::PI * t) * (0.25 + x[0] / 4)});
    }

  private:
    static constexpr double E = 100, poisson = 0.3;
  };

  // @sect4{A manufactured solution}

  // The exact solution of the full program's
  // prm/verification/mms_2d_quad_exponential.prm, on the unit square with
  // $\Gamma_3$ the bottom ($\nu = (0,-1)$) and, unlike step-1, the top
  // clamped:
  // @f[
  //   u(x, y, t) = \sin t\,(1 - y)\,\bigl(g_\tau(x),\; -g_\nu(x)\bigr)
  //     + t^2\,\tfrac15\,y(1 - y)\,(\sin\pi x,\; \cos\pi x),
  // @f]
  // @f[
  //   g_\tau(x) = 4 (x - 0.4)_+^3,\qquad
  //   g_\nu(x) = 4 (x - 0.7)_+^3 - 4 (0.3 - x)_+^3,
  // @f]
  // the form of step-1's field, with a second term that vanishes on
  // $\Gamma_3$. On $\Gamma_3$ the velocity $w = \dot u$ has $w_\nu = \cos t\,
  // g_\nu(x)$: separating on $(0, 0.3)$, normal stick on $[0.3, 0.7]$, moving
  // into the foundation beyond; and $w_\tau = \cos t\,g_\tau(x)$: stick on $(0,
  // 0.4]$, slip beyond. It starts undeformed ($u_0 = 0$) with $w_0 =
  // \dot u(0)$. With $w = \dot u$ and $\sigma = A\varepsilon(w) +
  // B\varepsilon(u)$ of the exact solution the data follow from the
  // equations,
  // @f[
  //   f_0 = \rho\dot w - \mathrm{Div}\,\sigma,\qquad
  //   f_2 = \sigma\nu,\qquad
  //   f_3 = \sigma\nu + \xi_\nu\nu + \xi_\tau,
  // @f]
  // $\xi_\nu \in \partial j_\nu(w_\nu)$, $\xi_\tau \in
  // \partial(F_b|\cdot|)(w_\tau)$, as in step-1 with $w$ for $u$: where
  // $w_\nu = 0$ we take $\xi_\nu = a/2$, where $w_\tau = 0$ we take
  // $\xi_\tau = F_b/2$, in the middle of their intervals. "Zero" here means
  // below $10^{-13}(1 + |w|)$: the exact $w_\nu$, computed from cosines and
  // cubes, vanishes only up to round-off. The material: $\rho = 1$, $\mu_A =
  // \lambda_A = 1$, $\mu = 2$, $\lambda = 1$; the law $a = 1$, $b = 0.5$,
  // $\beta = 2$ ($\alpha_\nu = 1$), $F_b = 0.5$.
  //
  // The values the program needs at a point and a time: $u$, $w$, $\dot
  // w$, their gradients and $\mathrm{Div}\,\sigma$.
  struct ExactValues
  {
    Tensor<1, 2> u, w, w_dot, div_sigma;
    Tensor<2, 2> grad_u, grad_w;
  };

  class ManufacturedData : public ProblemData<2>
  {
  public:
    ManufacturedData()
      : ProblemData<2>(/*rho=*/1,
                       /*mu_A=*/1,
                       /*lambda_A=*/1,
                       /*mu=*/2,
                       /*lambda=*/1,
                       /*F_b=*/0.5,
                       ExponentialLaw(1, 0.5, 2))
    {}

    // colorize = true numbers the sides left 0, right 1, bottom 2, top 3;
    // we give the top the id 0 of $\Gamma_1$ and the left side the id 1, so
    // that the rest of the program finds $\Gamma_1$ and $\Gamma_3$ under
    // step-1's ids.
    void
    make_coarse_grid(Triangulation<2> &triangulation) const override
    {
      GridGenerator::subdivided_hyper_rectangle(
        triangulation, {1, 1}, Point<2>(0, 0), Point<2>(1, 1), true);
      for (const auto &face : triangulation.active_face_iterators())
        if (face->at_boundary() && face->boundary_id() != BoundaryIds::contact)
          face->set_boundary_id(face->boundary_id() == 3 ? 0 : 1);
    }

    // $4 z_+^3$ and its first two derivatives.
    static std::array<double, 3>
    cube_plus(const double z)
    {
      const double zp = std::max(z, 0.);
      return {{4 * zp * zp * zp, 12 * zp * zp, 24 * zp}};
    }

    // The two spatial fields $\phi_1 = (1 - y)(g_\tau, -g_\nu)$ and $\phi_2 =
    // \frac15 y(1 - y)(\sin\pi x, \cos\pi x)$ at @p p, each as its value,
    // gradient and Hessian (hessian[c][i][j] $= \partial_i\partial_j
    // \phi_c$). Each is $Y(y)\,X_c(x)$; we give $X_c$, $Y$ and their
    // derivatives up to the second and multiply out.
    static void
    field(const unsigned int k,
          const Point<2>    &p,
          Tensor<1, 2>      &value,
          Tensor<2, 2>      &gradient,
          Tensor<3, 2>      &hessian)
    {
      const double                         x = p[0], y = p[1], pi = numbers::PI;
      std::array<std::array<double, 3>, 2> X;
      std::array<double, 3>                Y;
      if (k == 0)
        {
          const auto g_tau = cube_plus(x - 0.4), r = cube_plus(x - 0.7),
                     h = cube_plus(0.3 - x);
          X[0]         = g_tau;
          X[1]         = {{h[0] - r[0], -h[1] - r[1], h[2] - r[2]}}; // -g_nu
          Y            = {{1 - y, -1., 0.}};
        }
      else
        {
          X[0] = {{std::sin(pi * x),
                   pi * std::cos(pi * x),
                   -pi * pi * std::sin(pi * x)}};
          X[1] = {{std::cos(pi * x),
                   -pi * std::sin(pi * x),
                   -pi * pi * std::cos(pi * x)}};
          Y    = {{0.2 * y * (1 - y), 0.2 * (1 - 2 * y), -0.4}};
        }
      for (unsigned int c = 0; c < 2; ++c)
        {
          value[c]         = Y[0] * X[c][0];
          gradient[c][0]   = Y[0] * X[c][1];
          gradient[c][1]   = Y[1] * X[c][0];
          hessian[c][0][0] = Y[0] * X[c][2];
          hessian[c][0][1] = hessian[c][1][0] = Y[1] * X[c][1];
          hessian[c][1][1]                    = Y[2] * X[c][0];
        }
    }

    // $\mathrm{Div}(C\varepsilon(v)) = \mu\Delta v + (\mu +
    // \lambda)\nabla\,\mathrm{div}\,v$ for the Lamé constants of $C$, from
    // the Hessian of $v$.
    static Tensor<1, 2>
    stress_divergence(const double        mu,
                      const double        lambda,
                      const Tensor<3, 2> &hessian)
    {
      Tensor<1, 2> result;
      for (unsigned int c = 0; c < 2; ++c)
        for (unsigned int j = 0; j < 2; ++j)
          result[c] += mu * hessian[c][j][j] + (mu + lambda) * hessian[j][j][c];
      return result;
    }

    // $u = \sin(t)\phi_1 + t^2\phi_2$, $w = \cos(t)\phi_1 + 2t\phi_2$,
    // $\dot w = -\sin(t)\phi_1 + 2\phi_2$, and the rest from them.
    ExactValues
    exact(const Point<2> &p, const double t) const
    {
      const double time[2][3] = {{std::sin(t), std::cos(t), -std::sin(t)},
                                 {t * t, 2 * t, 2.}};
      ExactValues  e;
      Tensor<3, 2> hessian_u, hessian_w;
      for (unsigned int k = 0; k < 2; ++k)
        {
          Tensor<1, 2> value;
          Tensor<2, 2> gradient;
          Tensor<3, 2> hessian;
          // each field times its time factor and the factor's first and
          // second derivative
          field(k, p, value, gradient, hessian);
          e.u += time[k][0] * value;
          e.w += time[k][1] * value;
          e.w_dot += time[k][2] * value;
          e.grad_u += time[k][0] * gradient;
          e.grad_w += time[k][1] * gradient;
          hessian_u += time[k][0] * hessian;
          hessian_w += time[k][1] * hessian;
        }
      e.div_sigma = stress_divergence(mu_A, lambda_A, hessian_w) +
                    stress_divergence(mu, lambda, hessian_u);
      return e;
    }

    // $f_0 = \rho\dot w - \mathrm{Div}\,\sigma$ of the exact solution: the
    // force that makes $u$ move as it does.
    Tensor<1, 2>
    body_force(const Point<2> &p, const double t) const override
    {
      const ExactValues e = exact(p, t);
      return density * e.w_dot - e.div_sigma;
    }

    Tensor<1, 2>
    traction(const Point<2>          &p,
             const Tensor<1, 2>      &normal,
             const types::boundary_id id,
             const double             t) const override
    {
      const ExactValues  e = exact(p, t);
      const Tensor<1, 2> sigma_nu =
        (viscous_stress(symmetrize(e.grad_w)) + stress(symmetrize(e.grad_u))) *
        normal;
      if (id != BoundaryIds::contact)
        return sigma_nu;
      // On $\Gamma_3$ the extra traction $f_3$: what the laws would supply
      // at the exact velocity, with the middle of the interval where a
      // branch holds its variable at zero.
      const double       w_nu  = e.w * normal;
      const Tensor<1, 2> w_tau = e.w - w_nu * normal;
      const double       zero  = 1e-13 * (1 + e.w.norm());
      const double       xi_nu = std::abs(w_nu) <= zero ? 0.5 * law.jump() :
                                 w_nu < 0               ? 0. :
                                                          law.response(w_nu);
      Tensor<1, 2>       xi_tau({0.5 * friction_bound, 0.});
      if (w_tau.norm() > zero)
        xi_tau = friction_bound * w_tau / w_tau.norm();
      return sigma_nu + xi_nu * normal + xi_tau;
    }

    // $w_0 = \dot u(0) = \phi_1$: the body starts undeformed but moving,
    // with its bottom already on all three normal branches.
    Tensor<1, 2>
    initial_velocity(const Point<2> &p) const override
    {
      return exact(p, 0).w;
    }
  };

  // @sect3{One contact node}

  // The contact conditions hold node by node (nodal quadrature on
  // $\Gamma_3$): each node $x_i$ of $\Gamma_3$ keeps its degrees of
  // freedom, its weight $m_i = \int_{\Gamma_3}\varphi_i$, its normal
  // $\nu_i$, the constant $c_i$ of the complementarity functions, and its
  // current branches. As in step-1, with the velocity $w$ in place of the
  // displacement: the branches follow the law, and the law acts on $w$.
  // "separating" means that the node moves away from the foundation,
  // $w_\nu < 0$, whatever its displacement; "penetrating" that it moves
  // into it, $w_\nu > 0$, and feels the damped response (the full program
  // calls this branch "damped").
  enum class NormalBranch
  {
    separating, // s_nu + c w_nu < 0:    s_nu = 0, w_nu free
    stick,      // 0 <= s_nu + c w_nu <= a: w_nu = 0
    penetrating // s_nu + c w_nu > a:    s_nu = a, w_nu free
  };

  enum class TangentialBranch
  {
    stick, // |s_tau + c w_tau| <= F_b: w_tau = 0
    slip   // s_tau = F_b q/|q|, q = s_tau + c w_tau
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

  // @sect3{The DynamicContactProblem class}

  // step-1's class with time: the same functions, and run() solves one
  // time step where step-1's solved one load value. The name changes with
  // the problem (step-1's StaticContactProblem). The constructor takes the
  // time step $k$, which enters the matrix of every step.
  template <int dim>
  class DynamicContactProblem
  {
  public:
    DynamicContactProblem(const ProblemData<dim> &data,
                          const unsigned int      n_refinements,
                          const double            time_step);

    // Solve the time step that ends at $t$: $u_n = u_{n-1} + k w_{n-1}$,
    // then the step problem for $w_n$, started from $w_{n-1}$.
    void
    run(const double t);

    // Write the files of one solution, their names ending in @p name
    // (the number of the step), and print its summary line.
    void
    output_results(const std::string &name) const;

    // $\|w - w_h\|_{L^2}$, $\|\varepsilon(w - w_h)\|_{L^2}$ and
    // $\|\varepsilon(u - u_h)\|_{L^2}$ at the current time.
    template <class Exact>
    std::array<double, 3>
    compute_errors(const Exact &exact) const;

    unsigned int
    n_dofs() const
    {
      return dof_handler.n_dofs();
    }

    // The constant $\lambda_1$ of the smallness condition (the
    // introduction, "One step is a minimisation"): $J_n$ is strictly
    // convex, and each step has exactly one solution, when $\alpha_\nu <
    // \lambda_1$.
    double
    smallness_constant() const;

    // The Newton iterations of the last run(), for the convergence table.
    unsigned int newton_iterations = 0;

    // The step energy $J_n$, which the line search decreases.
    double
    energy(const Vector<double> &w) const;

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
    // the time step $k$, fixed for the whole run, and the time $t_n$ of the
    // step last solved, where step-1 had the load parameter
    const double time_step; // $k$
    double       time = 0;  // $t_n$

    // The finite element machinery of step-8: a mesh, $Q_1$ in each of the
    // $d$ components, and the numbering of the degrees of freedom.
    Triangulation<dim> triangulation;
    FESystem<dim>      fe;
    DoFHandler<dim>    dof_handler;

    // Two sets of constraints: the clamped boundary alone, with which $K_0$
    // and $\ell_n$ are assembled, and the clamped boundary plus the held
    // conditions of the current branches, rebuilt in every Newton
    // iteration (as step-41 rebuilds its active set).
    AffineConstraints<double> clamped_constraints;
    AffineConstraints<double> newton_constraints;

    // $K_0$ and the matrix of one Newton step share one sparsity pattern:
    // the contact terms couple only the components of one node, which the
    // pattern of $K_0$ already holds.
    //
    // The names are step-1's, and what they hold is the step problem's
    // (the introduction, "One step is a minimisation"): stiffness_matrix is
    // $K_0 = \rho/k\,M + K_A$ and load is $\ell_n = \rho/k\,M w_{n-1} -
    // K_B u_n + F_n$ ($K_A$, $K_B$ the matrices of $a_A$, $a_B$), the effective
    // stiffness matrix and the effective load of structural dynamics; solution
    // is the step's unknown, the velocity $w_n$. New are $w_{n-1}$ and $u_n$.
    SparsityPattern      sparsity_pattern;
    SparseMatrix<double> stiffness_matrix;
    SparseMatrix<double> newton_matrix;

    Vector<double> solution;     // $w_n$, kept from one step to the next
    Vector<double> load;         // $\ell_n$
    Vector<double> newton_rhs;   // $g$ of the Newton step, condensed
    Vector<double> old_solution; // $w_{n-1}$
    Vector<double> displacement; // $u_n = u_{n-1} + k w_{n-1}$

    std::vector<ContactNode<dim>> contact_nodes;
  };

  // The constructor builds the mesh and the system, and sets the initial
  // values: $u_0 = 0$ and $w_0$ by nodal interpolation (the values at the
  // vertices are the $Q_1$ coefficients), zero on $\Gamma_1$.
  template <int dim>
  DynamicContactProblem<dim>::DynamicContactProblem(
    const ProblemData<dim> &data,
    const unsigned int      n_refinements,
    const double            time_step)
    : data(data)
    , time_step(time_step)
    , fe(FE_Q<dim>(1), dim)
    , dof_handler(triangulation)
  {
    make_grid(n_refinements);
    setup_system();
    // each vertex of each cell: a vertex shared by several cells gets the
    // same value several times
    for (const auto &cell : dof_handler.active_cell_iterators())
      for (const unsigned int v : cell->vertex_indices())
        for (unsigned int c = 0; c < dim; ++c)
          solution(cell->vertex_dof_index(v, c)) =
            data.initial_velocity(cell->vertex(v))[c];
    clamped_constraints.distribute(solution);
  }

  // @sect4{DynamicContactProblem::make_grid}

  template <int dim>
  void
  DynamicContactProblem<dim>::make_grid(const unsigned int n_refinements)
  {
    // The coarse mesh comes from the data (one cell per unit length), so
    // that every refinement halves $h$ and the points where the
    // manufactured solution switches branches stay mesh vertices.
    data.make_coarse_grid(triangulation);
    triangulation.refine_global(n_refinements);
  }

  // @sect4{DynamicContactProblem::setup_system}

  // $V^h$: continuous $Q_1$ vector fields vanishing on $\Gamma_1$. The
  // sparsity pattern couples every component of a node with every
  // component of its neighbours, so it also holds the entries that the
  // contact constraints of solve() create (they tie the components of one
  // node together).
  template <int dim>
  void
  DynamicContactProblem<dim>::setup_system()
  {
    // The clamped boundary $\Gamma_1$ (boundary id 0) becomes constraints
    // $w = 0$ on its degrees of freedom; assembling with them (as step-8
    // does) keeps $K_0$ symmetric and positive definite on the remaining ones.
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
    // the two vectors that time adds: the velocity of the step before and
    // the displacement, both zero until the constructor and run() set them
    old_solution.reinit(dof_handler.n_dofs());
    displacement.reinit(dof_handler.n_dofs());

    // The contact nodes need the diagonal of $K_0$ (their constants $c_i$),
    // so $K_0$ is assembled here, before the first step; run() assembles it
    // again together with the load of its step (one function computes
    // both, and $K_0$ comes out the same).
    assemble_system(clamped_constraints, stiffness_matrix, load);
    setup_contact_nodes();
  }

  // @sect4{The contact nodes}

  // The nodal weights $m_i = \int_{\Gamma_3}\varphi_i$ and the nodal
  // normals $\nu_i = \int_{\Gamma_3}\varphi_i\nu / |\cdot|$ are assembled
  // like a right-hand side. Nodes on $\Gamma_1$ are not contact nodes
  // (they do not move). The constant $c_i$ of the complementarity
  // functions is the mean diagonal entry of $K_0$ at the node over $m_i$,
  // and at least twice the law's steepest rise. Why a floor: on a free
  // segment the multiplier $s_\nu$ falls by $p'$ as $w_\nu$ grows, so $q =
  // s + c\,w_\nu$ grows along the law only if $c > p'$; below that an
  // iterate could be held on the wrong branch. The exponential law never
  // rises, so here the floor is zero. The diagonal of $K_0$ makes $c_i
  // w_\nu$ and $s$ forces of the same size, so that neither term of $q$
  // drowns the other. $c_i$ changes the path of the iteration, never its
  // solution (the complementarity functions vanish at the same points for
  // every $c > 0$). All of this is step-1's function, unchanged.
  template <int dim>
  void
  DynamicContactProblem<dim>::setup_contact_nodes()
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

  // @sect4{DynamicContactProblem::assemble_system}

  // The cell terms of the step energy, condensed with the given
  // constraints. This is where time enters the program. Backward Euler
  // turns the inertia $\rho\dot w$ into $\rho(w_n - w_{n-1})/k$, and the
  // viscous stress is $A\varepsilon(w_n)$; both act on the unknown $w_n$
  // and make the matrix
  // @f[
  //   (K_0)_{ij} = \int_K \frac{\rho}{k}\,\varphi_j\cdot\varphi_i
  //     + A\varepsilon(\varphi_j) : \varepsilon(\varphi_i),
  // @f]
  // where step-1 had $B$ alone. The elastic stress $B\varepsilon(u_n)$
  // acts on $u_n$, which the left-point rule makes known before the step,
  // so it moves to the right-hand side together with the old velocity:
  // @f[
  //   (\ell_n)_i = \int_K \frac{\rho}{k}\,w_{n-1}\cdot\varphi_i
  //     - B\varepsilon(u_n) : \varepsilon(\varphi_i)
  //     + \int_K f_0\cdot\varphi_i
  //     + \int_{\partial K\cap(\Gamma_2\cup\Gamma_3)} f\cdot\varphi_i.
  // @f]
  // The first two terms use Gauss with 2 points per direction, exact for
  // $Q_1$ on parallelograms; the loads 3 points per direction. With the
  // clamped constraints alone this is $K_0$ and $\ell_n$, the quadratic
  // part $\frac12 w\cdot K_0 w - \ell_n\cdot w$ of the step energy $J_n$;
  // solve() calls it again with the constraints of each Newton step. The
  // extractor is called velocity: the shape functions are those of the
  // step's unknown.
  template <int dim>
  void
  DynamicContactProblem<dim>::assemble_system(
    const AffineConstraints<double> &constraints,
    SparseMatrix<double>            &matrix,
    Vector<double>                  &rhs) const
  {
    const FEValuesExtractors::Vector velocity(0);
    const unsigned int               n = fe.n_dofs_per_cell();
    FEValues<dim>                    fe_values(
      fe, QGauss<dim>(2), update_values | update_gradients | update_JxW_values);
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
    std::vector<Tensor<1, dim>> old_velocities(fe_values.n_quadrature_points);
    std::vector<SymmetricTensor<2, dim>> strains(old_velocities.size());

    // The constraints are applied while assembling
    // (distribute_local_to_global()), so the matrix and the vector come out
    // condensed: for the clamped constraints that is $K_0$ and $\ell_n$ with
    // the clamped rows decoupled, for those of a Newton step the reduced system
    // of that step. The load uses one Gauss point more than the matrix: the
    // data are not polynomials (the manufactured ones are piecewise cubic and
    // jump on $\Gamma_3$), and their quadrature error must stay below the
    // discretisation error on the finest mesh.
    matrix = 0;
    rhs    = 0;
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        // The cell matrix has step-8's form with the viscosity for the
        // elasticity, $A\varepsilon(\varphi_i)$ against
        // $\varepsilon(\varphi_j)$, plus the inertia; the stress laws come
        // from the problem data, so that a different material changes one
        // function.
        cell_matrix = 0;
        cell_rhs    = 0;
        fe_values.reinit(cell);
        // $w_{n-1}$ and $\varepsilon(u_n)$ at the quadrature points, for the
        // two terms of $\ell_n$ that the old state contributes: the inertia
        // of the old velocity and the elastic stress of the displacement.
        fe_values[velocity].get_function_values(old_solution, old_velocities);
        fe_values[velocity].get_function_symmetric_gradients(displacement,
                                                             strains);
        // the cell's part of $K_0$ (the viscous stress of $\varphi_i$
        // against the strain of $\varphi_j$, and the inertia $\rho/k$ of
        // the two) and of $\ell_n$
        const double rho_k = data.density / time_step;
        for (const unsigned int q : fe_values.quadrature_point_indices())
          for (unsigned int i = 0; i < n; ++i)
            {
              const SymmetricTensor<2, dim> sigma_i = data.viscous_stress(
                fe_values[velocity].symmetric_gradient(i, q));
              const Tensor<1, dim> phi_i = fe_values[velocity].value(i, q);
              for (unsigned int j = 0; j < n; ++j)
                cell_matrix(i, j) +=
                  (sigma_i * fe_values[velocity].symmetric_gradient(j, q) +
                   rho_k * phi_i * fe_values[velocity].value(j, q)) *
                  fe_values.JxW(q);
              cell_rhs(i) += (rho_k * old_velocities[q] * phi_i -
                              data.stress(strains[q]) *
                                fe_values[velocity].symmetric_gradient(i, q)) *
                             fe_values.JxW(q);
            }

        fe_load.reinit(cell);
        for (const unsigned int q : fe_load.quadrature_point_indices())
          {
            const Tensor<1, dim> f0 =
              data.body_force(fe_load.quadrature_point(q), time);
            for (unsigned int i = 0; i < n; ++i)
              cell_rhs(i) +=
                f0 * fe_load[velocity].value(i, q) * fe_load.JxW(q);
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
                      f * fe_face[velocity].value(i, q) * fe_face.JxW(q);
                }
            }

        cell->get_dof_indices(dofs);
        constraints.distribute_local_to_global(
          cell_matrix, cell_rhs, dofs, matrix, rhs);
      }
  }

  // @sect3{The active-set Newton method}

  // @sect4{The state of a node}

  // All of this section is step-1's, with the velocity $w$ for $u$, $K_0$
  // for $K$ and $\ell_n$ for $F_n$: one time step is step-1's problem with
  // other matrices (the introduction, "One step is a minimisation").
  //
  // From the residual $R = K_0 w - \ell_n$ the nodal contact force is
  // $G_i = -R_i$ (the force the laws must supply for equilibrium), and
  // the traction is $G_i/m_i$. Split into normal and tangential parts, the
  // multipliers of the convex parts of the laws are (the members s_nu and
  // s_tau of NodeState)
  // @f[
  //   s_\nu = G_i\cdot\nu/m_i - p(w_\nu),\qquad
  //   s_\tau = G_{i,\tau}/m_i
  // @f]
  // (Tresca friction has no remainder), and the complementarity functions
  // (the introduction shows why they vanish exactly where the laws hold)
  // are
  // @f[
  //   C_\nu = s_\nu - P_{[0,a]}(s_\nu + c\,w_\nu),\qquad
  //   C_\tau = s_\tau - P_{|\cdot|\le F_b}(s_\tau + c\,w_\tau).
  // @f]
  // Both vanish exactly at a solution of the nodal contact conditions.
  template <int dim>
  struct DynamicContactProblem<dim>::NodeState
  {
    double         w_nu;
    Tensor<1, dim> w_tau;
    double         s_nu;
    Tensor<1, dim> s_tau;
    double         q_nu;  // s_nu + c w_nu
    Tensor<1, dim> q_tau; // s_tau + c w_tau
  };

  template <int dim>
  typename DynamicContactProblem<dim>::NodeState
  DynamicContactProblem<dim>::node_state(const ContactNode<dim> &node,
                                         const Vector<double>   &residual) const
  {
    Tensor<1, dim> w, traction;
    for (unsigned int c = 0; c < dim; ++c)
      {
        w[c]        = solution(node.dofs[c]);
        traction[c] = -residual(node.dofs[c]) / node.mass;
      }
    // The residual at a contact node is the force the laws do not yet
    // supply; divided by the weight $m_i$ it is a traction, comparable with
    // the law's response $\xi$ and the friction bound $F_b$.
    NodeState m;
    m.w_nu  = w * node.normal;
    m.w_tau = w - m.w_nu * node.normal;
    m.s_nu  = traction * node.normal - data.law.remainder(m.w_nu);
    m.s_tau = traction - (traction * node.normal) * node.normal;
    m.q_nu  = m.s_nu + node.c * m.w_nu;
    m.q_tau = m.s_tau + node.c * m.w_tau;
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
  // separating, $0 \le q_\nu \le a$ stick (held at $w_\nu = 0$), $q_\nu >
  // a$ penetrating; $|q_\tau| \le F_b$ stick ($w_\tau = 0$), otherwise
  // slip. Returns the number of nodes whose branches changed.
  template <int dim>
  unsigned int
  DynamicContactProblem<dim>::update_active_set(const Vector<double> &residual)
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
  DynamicContactProblem<dim>::nonsmooth_residual(
    const Vector<double> &residual) const
  {
    // At a contact node the residual is not expected to vanish (it is the
    // contact force); there the complementarity functions take its place.
    // The clamped rows of the residual are zero already (the condensed
    // $K_0$ times a $w$ that vanishes there, minus a zero load).
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
  // minimises its quadratic model $\frac12 x\cdot(K_0 + L)x - g\cdot x$
  // over the velocities that satisfy the held conditions:
  // - a stick node in the normal direction: $x_i\cdot\nu_i = 0$;
  // - a stick node in the tangential direction: $x_i - (x_i\cdot\nu_i)
  //   \nu_i = 0$.
  //
  // Free branches add the nodal force $f_i$ of the laws and its
  // derivative $L_i$, with $g_i = (\ell_n)_i + L_i w_i - f_i$:
  // - penetrating: $f_i = m_i (a + p(w_\nu))\nu$, $L_i = m_i p'(w_\nu)
  //   \nu\otimes\nu$ (negative on a falling segment of the law);
  // - slip: $f_i = m_i F_b d + T_i w_\tau$, $d = q_\tau/|q_\tau|$, and
  //   $L_i = T_i$, the condensed tangent of the friction disk $T_i = m_i
  //   F_b c /(|q_\tau| - F_b)\,(I - \nu\otimes\nu - d\otimes d)$, which
  //   vanishes in 2D (the denominator is kept above $|q_\tau|/100$ for
  //   nodes that barely slip). The term $T_i w_\tau$: the Newton step of
  //   $C_\tau = 0$ gives the new multiplier $s_\tau = F_b d + T_i x_i /
  //   m_i$, whose part across $d$ grows with the new slip $x_i$. Written as
  //   $f_i + L_i(x_i - w_i)$, like the other forces, it needs $f_i = m_i
  //   F_b d + T_i w_i$, and $T_i w_i = T_i w_\tau$ since $T_i\nu = 0$.
  //
  // The held conditions are linear constraints between the components of
  // a node, solved for its component of largest $|\nu_c|$; deal.II's
  // AffineConstraints eliminates them while assembling, as step-41 does
  // for its active set.
  template <int dim>
  void
  DynamicContactProblem<dim>::assemble_newton_system(
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
        // a penetrating node: the damped response and its derivative,
        // which is negative everywhere for the exponential law
        if (node.normal_branch == NormalBranch::penetrating)
          {
            f +=
              node.mass * (data.law.jump() + data.law.remainder(m.w_nu)) * nu;
            L += node.mass * data.law.remainder_derivative(m.w_nu) *
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
            f += node.mass * F_b * d + tangent * m.w_tau;
          }
        Tensor<1, dim> w;
        for (unsigned int c = 0; c < dim; ++c)
          w[c] = solution(node.dofs[c]);
        const Tensor<1, dim> g = L * w - f;
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

  // $J_n(w) = \frac12 w\cdot K_0 w - \ell_n\cdot w + \sum_i m_i
  // [j_\nu(w_{i,\nu}) + F_b |w_{i,\tau}|]$, the function the line search
  // decreases.
  template <int dim>
  double
  DynamicContactProblem<dim>::energy(const Vector<double> &w) const
  {
    double J = 0.5 * stiffness_matrix.matrix_norm_square(w) - load * w;
    for (const ContactNode<dim> &node : contact_nodes)
      {
        Tensor<1, dim> v;
        for (unsigned int c = 0; c < dim; ++c)
          v[c] = w(node.dofs[c]);
        const double w_nu = v * node.normal;
        J +=
          node.mass * (data.law.potential(w_nu) +
                       data.friction_bound * (v - w_nu * node.normal).norm());
      }
    return J;
  }

  // @sect4{DynamicContactProblem::solve}

  // step-1's function, unchanged, and we keep all of it: the tolerance, the
  // second stopping rule, the limit of 50 iterations and the line search.
  // One time step is step-1's problem with $K_0$, $\ell_n$ and $w$ in place
  // of $K$, $F_n$ and $u$, and nothing in the iteration depends on what
  // the matrix and the vector stand for. Each step starts from the solution
  // of the step before, $w_{n-1}$, which is within $O(k)$ of $w_n$: the
  // iteration needs about three Newton steps (the column Newton of the
  // convergence table).
  //
  // The primal-dual active set iteration: compute the residual, update the
  // branches, stop when no branch changed and the nonsmooth residual is
  // below the tolerance (relative to $|\ell_n|$), else solve the Newton
  // system on the current branches with a direct solver and take the
  // step, halved until it does not raise $J$ (the full step if no length
  // lowers it; the rule is explained where it is coded).
  template <int dim>
  void
  DynamicContactProblem<dim>::solve()
  {
    // The tolerance is relative to the load $\ell_n$: the residual is a
    // force, and
    // $10^{-11}|\ell_n|$ lies well above the round-off of evaluating it while
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

        // The line search on $J_n$, step-1's rule: try $\theta = 1,
        // \frac12, \frac14, \dots, 2^{-10}$ and take the first step $w +
        // \theta d$ that does not raise $J_n$ beyond round-off (a relative
        // $10^{-12}$, since $J_n$ is a sum of terms of either sign and its
        // last digits are noise). In a time step the two quadratic terms
        // $\frac12 w\cdot K_0 w$ and $\ell_n\cdot w$ are large (they hold
        // $\rho/k$) and nearly cancel; the tolerance is relative to $|J_n|$
        // itself, which keeps it above the round-off of the difference
        // without a formula of its own. A full Newton step can raise $J_n$
        // because $j_\nu$ is not convex: the quadratic model of one branch
        // is wrong beyond that branch's segment of the law. If no step
        // length lowers $J_n$ (the direction is not one of descent, which
        // happens only while the branches are still wrong), the full step
        // is taken: a tiny step would leave the branches as they are and
        // stall the iteration, while the full step moves to the branches
        // the next update_active_set() corrects. In the default run of this
        // program (the block and four levels) one step is damped, once,
        // with $\theta = \frac12$ (the block at $t = 0.36$), and none
        // reaches the fallback.
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

  // @sect4{DynamicContactProblem::run}

  // One time step, $t_{n-1} \to t_n = t$: the left-point rule $u_n =
  // u_{n-1} + k w_{n-1}$ (the paper's choice: it makes $u_n$ known before
  // the step, so that each step is a problem in $w_n$ alone, with the same
  // matrix $K_0$ at every step), the old velocity kept for $\ell_n$, then
  // step-1's two lines: assemble at $t$ and solve, from $w_{n-1}$ (close
  // to $w_n$, since $w$ changes by $O(k)$).
  template <int dim>
  void
  DynamicContactProblem<dim>::run(const double t)
  {
    // solution still holds $w_{n-1}$ here: it moves the displacement on
    // by one step and is kept for the inertia term of $\ell_n$, and then
    // it is the start of the iteration for $w_n$
    displacement.add(time_step, solution);
    old_solution = solution;
    time         = t;
    assemble_system(clamped_constraints, stiffness_matrix, load);
    solve();
  }

  // @sect4{DynamicContactProblem::smallness_constant}

  // step-1's function, unchanged: with stiffness_matrix holding $K_0$, it
  // computes the constant of one time step. The uniqueness condition of
  // the introduction asks that
  // @f[
  //   \lambda_1 = \min_{v \ne 0}
  //     \frac{v\cdot K_0 v}{\sum_i m_i (v_i\cdot\nu_i)^2} > \alpha_\nu,
  // @f]
  // and then $J_n$ is strictly convex and the step has exactly one
  // solution. $K_0$ holds $\rho/k\,M$, but $\lambda_1$ does not grow like
  // $\rho/k$: the lowest mode lives in a layer along $\Gamma_3$ whose
  // depth shrinks with $k$, and $\lambda_1$ grows like $k^{-1/2}$ (the
  // introduction). This is why a short enough time step makes every step
  // uniquely solvable, where step-1 needed a stiff enough body.
  //
  // $\lambda_1$ is the smallest eigenvalue of the pencil $(K_0, M_\nu)$ with
  // the normal boundary mass $M_\nu = \sum_i m_i \nu_i\otimes\nu_i$ (nodal
  // quadrature of $\int_{\Gamma_3} v_\nu^2$). $M_\nu$ is singular (it sees only
  // the normal components on $\Gamma_3$), so we compute the largest
  // eigenvalue $1/\lambda_1$ of $K_0^{-1}M_\nu$ instead, by the power iteration
  // $x \leftarrow K_0^{-1} M_\nu x$: each step is one solve with the UMFPACK
  // factorisation of $K_0$, computed once. The Rayleigh quotient
  // $x\cdot K_0x / x\cdot M_\nu x$ of the iterate approaches $\lambda_1$ from
  // above, with an error of the square of the iterate's; we stop when it
  // changes by less than $10^{-12}$ relative. The start is the normal
  // field on $\Gamma_3$, which the lowest mode resembles. The full program
  // estimates the same number (by a preconditioned eigensolver) and warns
  // when $\alpha_\nu$ is not below it. Nothing here changes the solution.
  template <int dim>
  double
  DynamicContactProblem<dim>::smallness_constant() const
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
    // condensed $K_0$ (deal.II puts one there when it condenses), so $K_0$
    // is invertible, and the power iteration never sees them: $M_\nu$ vanishes
    // there.
    SparseDirectUMFPACK K_inverse;
    K_inverse.initialize(stiffness_matrix);
    Vector<double> x(dof_handler.n_dofs()), Mx(x), Kx(x);
    for (const ContactNode<dim> &node : contact_nodes)
      for (unsigned int c = 0; c < dim; ++c)
        x(node.dofs[c]) = node.normal[c];

    // The power iteration. Each step applies $K_0^{-1}M_\nu$ and normalises;
    // the iterate approaches the eigenvector of the largest eigenvalue of
    // $K_0^{-1}M_\nu$ at the rate of the ratio of the two largest, and the cap
    // of 1000 steps guards against a pair too close to separate.
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

  // @sect4{DynamicContactProblem::output_results}

  // step-1's four files per solution, their names ending in @p name, with
  // the velocity added: the displacement $u_n$ and the velocity $w_n$ for
  // ParaView (solution-NN.vtu), the contact quantities along $\Gamma_3$
  // (contact-NN.csv: $w_\nu$, $w_\tau$, $-\sigma_\nu$, $\sigma_\tau$ and
  // the branches; the traction is $-R_i/m_i$), the nodal displacement and,
  // after it, the nodal velocity in full double precision
  // (displacement-NN.txt: x, y, u_x, u_y, w_x, w_y, for the comparison with
  // the full program) and the cells with the displacement of their
  // vertices (body-NN.csv, the deformed mesh for a plot script). A short
  // summary line goes to the terminal.
  template <int dim>
  void
  DynamicContactProblem<dim>::output_results(const std::string &name) const
  {
    DataOut<dim> data_out;
    // The VTU file, as in step-8: the $d$ components together form one vector
    // field, so that ParaView can warp the mesh by it.
    data_out.attach_dof_handler(dof_handler);
    const std::vector<DataComponentInterpretation::DataComponentInterpretation>
      interpretation(dim,
                     DataComponentInterpretation::component_is_part_of_vector);
    // Both fields, so that ParaView can warp the mesh by the displacement
    // and colour it by the velocity (or the reverse).
    data_out.add_data_vector(displacement,
                             std::vector<std::string>(dim, "displacement"),
                             DataOut<dim>::type_dof_data,
                             interpretation);
    data_out.add_data_vector(solution,
                             std::vector<std::string>(dim, "velocity"),
                             DataOut<dim>::type_dof_data,
                             interpretation);
    data_out.build_patches();
    std::ofstream vtu("solution-" + name + ".vtu");
    data_out.write_vtu(vtu);

    // The picture of the body needs only what a plot library can draw: one
    // polygon per cell. We write each cell's vertices in counterclockwise
    // order (deal.II numbers the vertices of a quadrilateral
    // lexicographically, 0 1 / 2 3, so the order around it is 0, 1, 3, 2)
    // with the displacement $u_n$ there and, at a contact node, its two
    // branches
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
                body << ',' << displacement(cell->vertex_dof_index(v, c));
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
    // solve(): the column minus_sigma_nu is $s_\nu + p(w_\nu)$, the whole
    // normal traction, and sigma_tau the first component of the
    // multiplier $s_\tau$ (the tangent of the bottom is $e_x$).
    Vector<double> residual(dof_handler.n_dofs());
    stiffness_matrix.vmult(residual, solution);
    residual -= load;
    std::ofstream csv("contact-" + name + ".csv");
    csv << "x,w_nu,w_tau,minus_sigma_nu,sigma_tau,normal_branch,"
           "tangential_branch\n";
    unsigned int n_normal[3] = {0, 0, 0}, n_tangential[2] = {0, 0};
    for (const ContactNode<dim> &node : contact_nodes)
      {
        const NodeState m = node_state(node, residual);
        csv << std::setprecision(10) << node.position[0] << ',' << m.w_nu << ','
            << m.w_tau[0] << ',' << m.s_nu + data.law.remainder(m.w_nu) << ','
            << m.s_tau[0] << ',' << static_cast<int>(node.normal_branch) << ','
            << static_cast<int>(node.tangential_branch) << '\n';
        ++n_normal[static_cast<int>(node.normal_branch)];
        ++n_tangential[static_cast<int>(node.tangential_branch)];
      }

    // The nodal file: the coordinates and $u_n$ as step-1 writes them, then
    // $w_n$, each vertex once, in full double precision. The comparison
    // with the full program matches the nodes by their coordinates, so the
    // order of the vertices does not matter.
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
                           "%.17g ",
                           displacement(cell->vertex_dof_index(v, c)));
            for (unsigned int c = 0; c < dim; ++c)
              std::fprintf(nodal,
                           c + 1 < dim ? "%.17g " : "%.17g\n",
                           solution(cell->vertex_dof_index(v, c)));
          }
    std::fclose(nodal);

    // The summary line of step-1, with the time $t_n$ in place of the load
    // parameter: the Newton iterations of the step and how many contact
    // nodes are on each branch at its solution.
    std::cout << "t = " << std::fixed << std::setprecision(2) << time << ": "
              << newton_iterations
              << " Newton iterations, normal separating/stick/penetrating "
              << n_normal[0] << '/' << n_normal[1] << '/' << n_normal[2]
              << ", tangential stick/slip " << n_tangential[0] << '/'
              << n_tangential[1] << std::defaultfloat << std::endl;
  }

  // @sect4{DynamicContactProblem::compute_errors}

  // The three norms of the error at the current time $t_n$,
  // $\|w(t_n) - w_n\|_{L^2}$, $\|\varepsilon(w(t_n) - w_n)\|_{L^2}$ and
  // $\|\varepsilon(u(t_n) - u_n)\|_{L^2}$, from which main() forms $E^w_H$,
  // $E^w_V$ and $E_V$ over the steps (the columns Ew_H, Ew_V, E_V). As in
  // step-1 we integrate with a 4-point Gauss rule per direction, two points
  // more than the assembly of the matrix: the exact solution is not a
  // polynomial, and the quadrature error must stay below the error measured.
  // The exact values come from exact() of the data, at the time of the step.
  template <int dim>
  template <class Exact>
  std::array<double, 3>
  DynamicContactProblem<dim>::compute_errors(const Exact &exact) const
  {
    const QGauss<dim>                    quadrature(4);
    FEValues<dim>                        fe_values(fe,
                            quadrature,
                            update_values | update_gradients |
                              update_quadrature_points | update_JxW_values);
    const FEValuesExtractors::Vector     velocity(0);
    std::vector<Tensor<1, dim>>          values(quadrature.size());
    std::vector<SymmetricTensor<2, dim>> strains(quadrature.size()),
      strains_u(quadrature.size());
    double Ew_H2 = 0, Ew_V2 = 0, E_V2 = 0;
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        // We integrate the squared errors cell by cell, with the exact solution
        // at the quadrature points and the discrete one interpolated there by
        // FEValues.
        fe_values.reinit(cell);
        fe_values[velocity].get_function_values(solution, values);
        fe_values[velocity].get_function_symmetric_gradients(solution, strains);
        fe_values[velocity].get_function_symmetric_gradients(displacement,
                                                             strains_u);
        for (const unsigned int q : fe_values.quadrature_point_indices())
          {
            // the exact values at the point, at the time of the step; the
            // velocity in $L^2$ and both fields in the strain norm
            const auto e = exact.exact(fe_values.quadrature_point(q), time);
            Ew_H2 += (e.w - values[q]).norm_square() * fe_values.JxW(q);
            const SymmetricTensor<2, dim> e_w =
              symmetrize(e.grad_w) - strains[q];
            Ew_V2 += scalar_product(e_w, e_w) * fe_values.JxW(q);
            const SymmetricTensor<2, dim> e_u =
              symmetrize(e.grad_u) - strains_u[q];
            E_V2 += scalar_product(e_u, e_u) * fe_values.JxW(q);
          }
      }
    return {{std::sqrt(Ew_H2), std::sqrt(Ew_V2), std::sqrt(E_V2)}};
  }
} // namespace Step2

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
    "usage: step-2                        the block, then 4 levels of the\n"
    "                                     manufactured solution\n"
    "       step-2 block                  the block only\n"
    "       step-2 convergence [LEVELS]   LEVELS levels (1 to 5, default 4)\n"
    "                                     of the manufactured solution\n"
    "       step-2 --help                 this text\n"
    "exit codes: 0 done, 1 the computation failed, 2 a bad argument";

  const std::map<std::string, std::size_t> modes = {{"", 0},
                                                    {"block", 1},
                                                    {"convergence", 2},
                                                    {"--help", 1}};

  // Each level halves $h$ and $k$ together: four times the unknowns and twice
  // the steps of the level before, and with UMFPACK about ten times the time.
  // Level 5 (33,282 unknowns, 128 steps) ends the study: it took 219 s of
  // processor time and 0.27 GB (doc/results.md, "Running it"); a sixth level
  // would run for more than half an hour, so we refuse it rather than let a
  // typo occupy the machine.
  const unsigned int max_levels = 5;
} // namespace CommandLine

// @sect3{The main function}

// The program has two parts, step-1's first two. First the block over $0
// \le t \le 1$ in 25 time steps of $k = 0.04$, each started from the
// solution of the one before, as step-1's load values were; then the
// manufactured solution on the meshes $h = 1/8, \dots, 1/64$ with $k = h$
// (h and k halved together), with the errors over all steps and their
// observed orders in a ConvergenceTable. The modes "block" and
// "convergence LEVELS" run one of them. step-1's third part, the study of
// nonconvexity, has no counterpart here: with $k$ small enough every step
// has one solution (the introduction).
int
main(int argc, char **argv)
{
  using namespace Step2;
  const std::vector<std::string> arguments(argv + 1, argv + argc);
  const std::string              mode = arguments.empty() ? "" : arguments[0];
  const std::string levels = arguments.size() == 2 ? arguments[1] : "4";
  // A bad command line ends here, before any output file is opened, and
  // so does --help.
  if ((!arguments.empty() && mode.empty()) ||
      CommandLine::modes.count(mode) == 0 ||
      arguments.size() > CommandLine::modes.at(mode) || levels.empty() ||
      levels.size() > 3 ||
      levels.find_first_not_of("0123456789") != std::string::npos ||
      std::stoul(levels) < 1 || std::stoul(levels) > CommandLine::max_levels)
    {
      std::cerr << "step-2: cannot run";
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
          std::cout << "The block, 3 global refinements, k = 0.04:"
                    << std::endl;
          const BlockData block;
          // step-1's block and mesh (4 x 1 cells refined three times, 32 x
          // 8 cells), now with the time step $k = 0.04$ of the full
          // program's example
          DynamicContactProblem<2> block_problem(block, 3, 0.04);
          // The uniqueness condition of every step, checked before solving
          // ($K_0$ is the same at every step).
          const double lambda_1 = block_problem.smallness_constant();
          std::cout << "  " << block_problem.n_dofs()
                    << " dofs, alpha_nu = " << block.law.alpha
                    << ", lambda_1 = " << lambda_1
                    << (block.law.alpha < lambda_1 ?
                          " (alpha_nu < lambda_1: one solution)" :
                          " (alpha_nu >= lambda_1: maybe several solutions)")
                    << std::endl;
          // The time loop: step $n$ ends at $t_n = 0.04\,n$. Each run()
          // advances the displacement, solves for $w_n$ from $w_{n-1}$, and
          // output_results() writes the step's four files and prints its
          // line, so that the block of the results page is this loop's
          // output.
          for (unsigned int n = 1; n <= 25; ++n)
            {
              block_problem.run(0.04 * n);
              std::cout << "  ";
              block_problem.output_results(Utilities::int_to_string(n, 2));
            }
        }

      // The errors of the paper's estimates (the introduction): $E^w_H =
      // \max_n \|w(t_n) - w_n\|_{L^2}$, $E^w_V = (k \sum_n \|\varepsilon(w(t_n)
      // - w_n)\|_{L^2}^2)^{1/2}$ and $E_V = \max_n \|\varepsilon(u(t_n) -
      // u_n)\|_{L^2}$, gathered step by step; the column Newton is the mean
      // number of iterations per step.
      if (mode.empty() || mode == "convergence")
        {
          std::cout << (mode.empty() ? "\n" : "")
                    << "The manufactured solution, k = h:" << std::endl;
          const ManufacturedData manufactured;
          ConvergenceTable       table;
          for (unsigned int refinements = 3; refinements < 3 + n_levels;
               ++refinements)
            {
              const unsigned int       n_steps = 1u << refinements;
              DynamicContactProblem<2> problem(manufactured,
                                               refinements,
                                               1. / n_steps);
              // The time loop of one level: after each step we add the
              // step's errors to the maxima and to the sum of $(E^w_V)^2$; the
              // Newton iterations of all steps give the mean per step.
              double       Ew_H = 0, Ew_V = 0, E_V = 0;
              unsigned int newton_iterations = 0;
              for (unsigned int n = 1; n <= n_steps; ++n)
                {
                  problem.run(double(n) / n_steps);
                  newton_iterations += problem.newton_iterations;
                  const auto errors = problem.compute_errors(manufactured);
                  Ew_H              = std::max(Ew_H, errors[0]);
                  Ew_V =
                    std::sqrt(Ew_V * Ew_V + errors[1] * errors[1] / n_steps);
                  E_V = std::max(E_V, errors[2]);
                }
              // step-1's columns, with the velocity's errors $E^w_H$, $E^w_V$
              // in place of $E_H$; Newton is now a mean over the steps, and $h$
              // is the side of a cell, $1/h$ the number of cells along a side
              // of the square and of steps
              table.add_value("1/h", n_steps);
              table.add_value("dofs", problem.n_dofs());
              table.add_value("Newton", double(newton_iterations) / n_steps);
              table.set_precision("Newton", 2);
              table.add_value("lambda_1", problem.smallness_constant());
              table.set_precision("lambda_1", 1);
              table.add_value("Ew_H", Ew_H);
              table.add_value("Ew_V", Ew_V);
              table.add_value("E_V", E_V);
            }
          for (const std::string column : {"Ew_H", "Ew_V", "E_V"})
            {
              table.set_scientific(column, true);
              table.set_precision(column, 3);
              table.evaluate_convergence_rates(
                column, ConvergenceTable::reduction_rate_log2);
            }
          table.write_text(std::cout);
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
