/* ---------------------------------------------------------------------
 *
 * hemicontact tutorial, step-2: the paper's step.
 *
 * Problem 4.4 of D. Han and W. Han, "Numerical analysis of an
 * evolutionary variational-hemivariational inequality with application to
 * a dynamic contact problem", Journal of Computational and Applied
 * Mathematics, 2019: a Kelvin-Voigt body in dynamic contact with a
 * foundation, a nonmonotone (exponential) normal damped response and
 * Tresca friction on $\Gamma_3$, backward Euler in the velocity $w$ and
 * the left-point rule for the displacement $u$, linear elements, nodal
 * quadrature on $\Gamma_3$. Each time step is the minimisation of a
 * nonsmooth step energy, solved by a primal-dual active set (semismooth
 * Newton) method, as step-1 solves its static problem. A manufactured
 * solution measures $E_H$, $E_V$ and $E_u$ against $k$ and $h$.
 *
 * The introduction (doc/intro.md) states the model, the scheme and the
 * algorithm; the results (doc/results.md) show what this program prints.
 * It computes the same discrete solution as the full program hemicontact
 * (problem/class = dynamic, time scheme = left point, the exponential law,
 * Tresca): tests/tutorial/step_2_vs_hemicontact.sh compares the two.
 *
 * --------------------------------------------------------------------- */

// @sect3{Include files}
//
// Only deal.II: the mesh, Q1 vector elements, matrices and a direct
// solver, and the output classes.
#include <deal.II/base/convergence_table.h>
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
#include <deal.II/lac/sparse_direct.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/vector.h>
#include <deal.II/numerics/data_out.h>
#include <deal.II/numerics/vector_tools.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <limits>
#include <map>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

namespace Step2
{
  using namespace dealii;

  // @sect3{The material}
  //
  // A Kelvin-Voigt material adds a viscous stress to the elastic one,
  // @f[
  //   \sigma = A\varepsilon(w) + B\varepsilon(u),\qquad w = \dot u,
  // @f]
  // with the viscosity $A$ and the elasticity $B$ both isotropic, each given
  // by a pair of Lam\'e constants: $C\varepsilon = 2\mu\varepsilon +
  // \lambda\,\mathrm{tr}(\varepsilon) I$. The viscous term is what makes the
  // velocity the natural unknown of a time step: $A$ enters the step matrix
  // $K_0$, while the elastic term, evaluated at the displacement $u_n$ that
  // is already known, moves to the right-hand side. step-1 had $B$ alone
  // (its ProblemData::stress()).
  struct LamePair
  {
    double mu;
    double lambda;

    template <int dim>
    SymmetricTensor<2, dim>
    stress(const SymmetricTensor<2, dim> &eps) const
    {
      return 2 * mu * eps + lambda * trace(eps) * unit_symmetric_tensor<dim>();
    }

    // $\mathrm{Div}(C\varepsilon(v)) = \mu\Delta v + (\mu + \lambda)\nabla\,
    // \mathrm{div}\,v$, from the Hessians hessian[c][i][j] $= \partial_i
    // \partial_j v_c$. Only the manufactured solution needs it, for its body
    // force $f_0 = \rho\dot w - \mathrm{Div}\,\sigma$.
    template <int dim>
    Tensor<1, dim>
    stress_divergence(const Tensor<3, dim> &hessian) const
    {
      Tensor<1, dim> result;
      for (unsigned int c = 0; c < dim; ++c)
        for (unsigned int j = 0; j < dim; ++j)
          result[c] += mu * hessian[c][j][j] + (mu + lambda) * hessian[j][j][c];
      return result;
    }
  };

  struct Material
  {
    double   density;
    LamePair viscosity;  // $A$
    LamePair elasticity; // $B$
  };

  // @sect3{The contact laws}
  //
  // The normal damped response $-\sigma_\nu \in \partial j_\nu(w_\nu)$ of the
  // paper, with its exponential law
  // @f[
  //   \partial j_\nu(r) = 0 \ (r < 0),\qquad [0, a] \ (r = 0),\qquad
  //   (a - b) e^{-\beta r} + b \ (r > 0).
  // @f]
  // The response falls from $a$ to $b$ as the penetration rate grows, so
  // $j_\nu$ is not convex; its relaxed monotonicity constant is the steepest
  // descent slope, $\alpha_\nu = \beta(a - b)$ at $r = 0^+$ (step-1's
  // introduction defines both). As in step-1 the law is split into the convex
  // jump $\partial(a r_+)$, which becomes a complementarity condition, and the
  // Lipschitz remainder
  // @f[
  //   p(r) = (a - b)(e^{-\beta r} - 1) \ (r > 0),\qquad p(r) = 0 \ (r \le 0),
  // @f]
  // a force that Newton's method linearises; with its primitive $P$ the
  // potential is $j_\nu(r) = a r_+ + P(r)$. The members play the roles of
  // step-1's: the remainder and its derivative for the Newton step, the
  // potential for the line search, the response for the manufactured data
  // (the jump is the field $a$).
  struct ExponentialLaw
  {
    double a, b, beta;

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
    // $j_\nu(r) = a r + P(r)$, $P(r) = (a - b)\bigl((1 - e^{-\beta r})/\beta
    // - r\bigr)$ for $r > 0$. std::expm1 computes $e^{-\beta r} - 1$
    // without the cancellation of $1 - e^{-\beta r}$ for small $\beta r$,
    // where the line search compares energies that differ in their last
    // digits.
    double
    potential(const double r) const
    {
      if (r <= 0)
        return 0.;
      return a * r + (a - b) * (-std::expm1(-beta * r) / beta - r);
    }
    // The response where $w_\nu > 0$, $\xi_\nu = a + p(r)$.
    double
    response(const double r) const
    {
      return a + remainder(r);
    }
    // The relaxed monotonicity constant $\alpha_\nu = \beta(a - b)$.
    double
    alpha() const
    {
      return beta * (a - b);
    }
  };

  // Tresca friction, $-\sigma_\tau \in \partial(F_b|\cdot|)(w_\tau)$, is given
  // by its bound $F_b$ alone (a number in this program): the shear stress
  // stays in the disk $|\sigma_\tau| \le F_b$, and $-\sigma_\tau = F_b
  // w_\tau/|w_\tau|$ where the body slips. It is convex, so it needs no
  // remainder.

  // @sect3{The problem data}
  //
  // Everything that defines one problem, with the interface of step-1's
  // ProblemData and time added: the material, the laws and the final time
  // as constants; the coarse mesh, the body force $f_0(x, t)$ and the
  // traction at a boundary point (its id says whether that is $f_2$ on
  // $\Gamma_2$ or an extra $f_3$ on $\Gamma_3$) as virtual functions; new
  // are the initial values $u_0$, $w_0$ and, where one is known, the exact
  // solution with the derivatives the errors and the manufactured loads
  // need. The tractions take the outward normal, since a manufactured
  // traction is $\sigma\nu$. The boundary is split by boundary id, as in
  // step-1: $\Gamma_1$ (clamped) and $\Gamma_3$ (contact) have one id
  // each, every other boundary is $\Gamma_2$. Unlike step-1 the two ids
  // are members, since the block and the manufactured solution clamp
  // different sides.
  template <int dim>
  struct ExactValues
  {
    Tensor<1, dim> u, w, w_dot, div_sigma;
    Tensor<2, dim> grad_u, grad_w;
  };

  template <int dim>
  class ProblemData
  {
  public:
    ProblemData(const Material          &material,
                const ExponentialLaw    &normal_law,
                const double             F_b,
                const double             end_time,
                const types::boundary_id clamped_boundary,
                const types::boundary_id contact_boundary)
      : material(material)
      , normal_law(normal_law)
      , friction_bound(F_b)
      , end_time(end_time)
      , clamped_boundary(clamped_boundary)
      , contact_boundary(contact_boundary)
    {}

    virtual ~ProblemData() = default;

    virtual void
    make_coarse_grid(Triangulation<dim> &triangulation) const = 0;

    // $f_0(x, t)$: zero unless a problem has one.
    virtual Tensor<1, dim>
    body_force(const Point<dim> &, const double) const
    {
      return Tensor<1, dim>();
    }

    // The prescribed traction at $x$ on the boundary with id @p id and
    // outward normal @p normal: $f_2$, or $f_3$ on $\Gamma_3$.
    virtual Tensor<1, dim>
    traction(const Point<dim>        &x,
             const Tensor<1, dim>    &normal,
             const types::boundary_id id,
             const double             t) const = 0;

    // $u_0$ and $w_0$: the body at rest unless a problem says otherwise.
    virtual Tensor<1, dim>
    initial_displacement(const Point<dim> &) const
    {
      return Tensor<1, dim>();
    }

    virtual Tensor<1, dim>
    initial_velocity(const Point<dim> &) const
    {
      return Tensor<1, dim>();
    }

    // The exact solution and its derivatives, for the errors; only a
    // manufactured solution has one.
    virtual bool
    has_exact_solution() const
    {
      return false;
    }

    virtual ExactValues<dim>
    exact(const Point<dim> &, const double) const
    {
      AssertThrow(false, ExcMessage("This problem has no exact solution."));
      return ExactValues<dim>();
    }

    const Material           material;
    const ExponentialLaw     normal_law;
    const double             friction_bound;
    const double             end_time;
    const types::boundary_id clamped_boundary, contact_boundary;
  };

  // @sect4{The block}
  //
  // The block $[0,4]\times[0,1]$ of the full program's prm/block_2d.prm:
  // clamped on the left (id 0), pressed and sheared on its top (id 3), in
  // contact with the foundation at its bottom (id 2), free on the right.
  // Its boundary sees every branch of the laws during $0 \le t \le 1$:
  // separation, normal stick, damped penetration, tangential stick and
  // slip. Young's modulus $E = 100$ and Poisson's ratio $0.3$ are converted
  // to the Lam\'e constants of $B$; $A$ has $\mu = \lambda = 1$, the law
  // $a = 1$, $b = 0.5$, $\beta = 10$.
  class BlockData : public ProblemData<2>
  {
  public:
    BlockData()
      : ProblemData<2>({1.,
                        {1., 1.},
                        {E / (2 * (1 + nu)),
                         E * nu / ((1 + nu) * (1 - 2 * nu))}},
                       {1., 0.5, 10.},
                       /*F_b=*/0.6,
                       /*end_time=*/1,
                       /*clamped_boundary=*/0,
                       /*contact_boundary=*/2)
    {}

    void
    make_coarse_grid(Triangulation<2> &triangulation) const override
    {
      GridGenerator::subdivided_hyper_rectangle(
        triangulation, {4, 1}, Point<2>(0, 0), Point<2>(4, 1), true);
    }

    // On the top a pressure rising to the right and in time, then a lift
    // (the sine changes sign at $t = 1/2$), and a shear growing in time;
    // nothing elsewhere.
    Tensor<1, 2>
    traction(const Point<2> &p,
             const Tensor<1, 2> &,
             const types::boundary_id id,
             const double             t) const override
    {
      if (id != 3)
        return Tensor<1, 2>();
      const double P = 3, S = 2;
      return Tensor<1, 2>(
        {S * std::sin(numbers::PI * t) * p[0] / 4,
         -P * std::sin(2 * numbers::PI * t) * (0.25 + p[0] / 4)});
    }

  private:
    static constexpr double E = 100, nu = 0.3; // Young's modulus, Poisson's
  };

  // @sect3{The manufactured solution}
  //
  // The exact displacement of the full program's
  // prm/verification/mms_2d_quad_exponential.prm,
  // @f[
  //   u(x, t) = \sin(t)\,\phi_1(x) + t^2\,\phi_2(x),
  // @f]
  // @f[
  //   \phi_1 = (1 - y)\,A\,\bigl((x - 0.4)_+^3,\ (0.3 - x)_+^3 - (x - 0.7)_+^3
  //   \bigr),\qquad
  //   \phi_2 = 0.2\,y(1 - y)\,(\sin\pi x,\ \cos\pi x),\qquad A = 4,
  // @f]
  // on $[0,1]^2$, clamped on top, in contact at the bottom ($\nu = -e_y$).
  // Along the bottom $w_\tau = 0$ (stick) for $x < 0.4$ and the body slips
  // beyond; $w_\nu < 0$ (separating) for $x < 0.3$, $w_\nu = 0$ (normal
  // stick) on $[0.3, 0.7]$ and $w_\nu > 0$ (damped) for $x > 0.7$: the error
  // measures every branch. The cubes $(\cdot)_+^3$ switch the branches on and
  // off while keeping $u$ twice continuously differentiable, so that $f_0$
  // is continuous. Each $\phi_k = Y(y) X(x)$ is given with its gradient and
  // Hessian (hessian[c][i][j] $= \partial_i\partial_j \phi_{k,c}$), each time
  // factor with two derivatives.
  void
  shape(const unsigned int k,
        const Point<2>    &p,
        Tensor<1, 2>      &value,
        Tensor<2, 2>      &gradient,
        Tensor<3, 2>      &hessian)
  {
    const double x = p[0], y = p[1], A = 4, pi = numbers::PI;
    const auto   pos = [](const double s) { return std::max(s, 0.); };
    std::array<std::array<double, 3>, 2> X; // X_c, X_c', X_c''
    std::array<double, 3>                Y; // Y, Y', Y''
    if (k == 0)
      {
        const double r = pos(x - 0.4), l = pos(0.3 - x), q = pos(x - 0.7);
        X[0] = {{A * r * r * r, 3 * A * r * r, 6 * A * r}};
        X[1] = {{A * (l * l * l - q * q * q),
                 -3 * A * (l * l + q * q),
                 6 * A * (l - q)}};
        Y    = {{1 - y, -1., 0.}};
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

  // The data follow from the equations. With $w = \dot u$ and $\sigma =
  // A\varepsilon(w) + B\varepsilon(u)$ of the exact solution,
  // @f[
  //   f_0 = \rho\dot w - \mathrm{Div}\,\sigma,\qquad
  //   f_2 = \sigma\nu \text{ on } \Gamma_2,\qquad
  //   f_3 = \sigma\nu + \xi_\nu\nu + \xi_\tau \text{ on } \Gamma_3,
  // @f]
  // $\xi_\nu \in \partial j_\nu(w_\nu)$, $\xi_\tau \in \partial(F_b|\cdot|)
  // (w_\tau)$: $f_3$ is the force the laws would have to supply for $u$ to be
  // in equilibrium. Where $w_\nu = 0$ and $w_\tau = 0$ we choose the
  // multipliers $0.5$ (inside $[0, a]$) and $(F_b/2, 0)$ (inside the disk),
  // so that the exact solution sits in the middle of its branch, not at a
  // switch where round-off could flip the discrete branch. "Zero" means
  // below $10^{-13}(1 + |w|)$: the exact $w_\nu$, computed from sines and
  // cubes, vanishes only up to round-off.
  class ManufacturedData : public ProblemData<2>
  {
  public:
    ManufacturedData()
      : ProblemData<2>({1., {1., 1.}, {2., 1.}},
                       {1., 0.5, 2.},
                       /*F_b=*/0.5,
                       /*end_time=*/1,
                       /*clamped_boundary=*/3,
                       /*contact_boundary=*/2)
    {}

    void
    make_coarse_grid(Triangulation<2> &triangulation) const override
    {
      GridGenerator::subdivided_hyper_rectangle(
        triangulation, {1, 1}, Point<2>(0, 0), Point<2>(1, 1), true);
    }

    bool
    has_exact_solution() const override
    {
      return true;
    }

    // $u = \sin(t)\phi_1 + t^2\phi_2$ and its derivatives: each shape
    // times its time factor, summed; $\mathrm{Div}\,\sigma$ from the
    // Hessians.
    ExactValues<2>
    exact(const Point<2> &p, const double t) const override
    {
      const double   time[2][3] = {{std::sin(t), std::cos(t), -std::sin(t)},
                                   {t * t, 2 * t, 2.}};
      ExactValues<2> e;
      Tensor<3, 2>   hessian_u, hessian_w;
      for (unsigned int k = 0; k < 2; ++k)
        {
          Tensor<1, 2> value;
          Tensor<2, 2> gradient;
          Tensor<3, 2> hessian;
          shape(k, p, value, gradient, hessian);
          e.u += time[k][0] * value;
          e.w += time[k][1] * value;
          e.w_dot += time[k][2] * value;
          e.grad_u += time[k][0] * gradient;
          e.grad_w += time[k][1] * gradient;
          hessian_u += time[k][0] * hessian;
          hessian_w += time[k][1] * hessian;
        }
      e.div_sigma = material.viscosity.stress_divergence(hessian_w) +
                    material.elasticity.stress_divergence(hessian_u);
      return e;
    }

    Tensor<1, 2>
    body_force(const Point<2> &p, const double t) const override
    {
      const ExactValues<2> e = exact(p, t);
      return material.density * e.w_dot - e.div_sigma;
    }

    Tensor<1, 2>
    traction(const Point<2>          &p,
             const Tensor<1, 2>      &normal,
             const types::boundary_id id,
             const double             t) const override
    {
      const ExactValues<2> e = exact(p, t);
      if (id != contact_boundary)
        return stress(e) * normal;
      const double       w_nu  = e.w * normal;
      const Tensor<1, 2> w_tau = e.w - w_nu * normal;
      const double       zero  = 1e-13 * (1 + e.w.norm());
      const double       xi_nu = std::abs(w_nu) <= zero ? 0.5 :
                                 w_nu < 0               ? 0. :
                                            normal_law.response(w_nu);
      const double       F_b   = friction_bound;
      Tensor<1, 2>       xi_tau({F_b / 2, 0.});
      if (w_tau.norm() <= zero)
        xi_tau -= (xi_tau * normal) * normal;
      else
        xi_tau = F_b * w_tau / w_tau.norm();
      return stress(e) * normal + xi_nu * normal + xi_tau;
    }

    Tensor<1, 2>
    initial_displacement(const Point<2> &p) const override
    {
      return exact(p, 0).u;
    }

    Tensor<1, 2>
    initial_velocity(const Point<2> &p) const override
    {
      return exact(p, 0).w;
    }

  private:
    // $\sigma = A\varepsilon(w) + B\varepsilon(u)$ of the exact solution.
    SymmetricTensor<2, 2>
    stress(const ExactValues<2> &e) const
    {
      return material.viscosity.stress(symmetrize(e.grad_w)) +
             material.elasticity.stress(symmetrize(e.grad_u));
    }
  };

  // @sect3{Contact nodes and their branches}
  //
  // With nodal quadrature on $\Gamma_3$ the contact conditions hold node by
  // node, as in step-1. A node $x_i$ of $\Gamma_3$ carries its degrees of
  // freedom, its weight $m_i = \int_{\Gamma_3}\varphi_i$, its normal
  // $\nu_i$, the constant $c_i$ of the complementarity functions and the
  // branches the active-set method assigns to it (doc/intro.md, "The
  // algorithm"):
  // - normal: separating ($q = s + c\,w_\nu < 0$: no force, $w_\nu$ free),
  //   stick ($0 \le q \le a$: $w_\nu = 0$) or damped ($q > a$: the force
  //   $a + p(w_\nu)$);
  // - tangential: stick ($|\lambda + c\,w_\tau| \le F_b$: $w_\tau = 0$) or
  //   slip ($\lambda = F_b q/|q|$, $q = \lambda + c\,w_\tau$).
  //
  // The names follow the velocity, as the law does: "separating" means that
  // the node moves away from the foundation, $w_\nu < 0$, whatever its
  // displacement.
  enum class NormalBranch
  {
    separating,
    stick,
    damped
  };

  // The tangential branches, as in step-1.
  enum class TangentialBranch
  {
    stick,
    slip
  };

  // The state at an iterate: $w$ split into $w_\nu$ and $w_\tau$, and the
  // multipliers of the laws' convex parts from the nodal contact force
  // $G_i = -(K_0 w - \ell_n)_i$: $s = G_i\cdot\nu_i/m_i - p(w_\nu)$, $\lambda =
  // G_{i,\tau}/m_i$. step-1 computes the same numbers in its NodeState; here
  // they are stored in the node, since solve_linearized() and
  // nonsmooth_residual() read them after update_branches() has set
  // them.
  template <int dim>
  struct ContactNode
  {
    std::array<types::global_dof_index, dim> dofs;
    Tensor<1, dim>                           normal;
    double                                   mass = 0, c = 1;
    NormalBranch     normal_branch     = NormalBranch::separating;
    TangentialBranch tangential_branch = TangentialBranch::stick;
    double           w_nu = 0, s = 0;
    Tensor<1, dim>   w_tau, lambda;
  };

  // @sect3{The KelvinVoigtContact class}
  //
  // The structure of deal.II's tutorial programs, and of step-1's
  // StaticContactProblem: make_grid(), setup_system(), assemble_system() (the
  // constant matrices $\rho M$, $A$, $B$, $K_0$ and the contact nodes),
  // assemble_rhs() (the right-hand side of one step), solve() (the
  // active-set Newton method for one step), output_results() and run() (the
  // time loop, which step-1 did not have). The errors against an exact
  // solution are accumulated along the way, since the solution of every step
  // enters $E_H$ and $E_V$.
  template <int dim>
  class KelvinVoigtContact
  {
  public:
    KelvinVoigtContact(const ProblemData<dim> &data,
                       const unsigned int      refinements,
                       const double            time_step,
                       const std::string      &output_directory = "");
    void
    run();

    // The errors over the steps $n = 1, \dots, N$:
    // $E_H = \max_n \|w(t_n) - w_n\|_{L^2}$,
    // $E_V = (k \sum_n \|\varepsilon(w(t_n) - w_n)\|_{L^2}^2)^{1/2}$,
    // $E_u = \max_n \|\varepsilon(u(t_n) - u_n)\|_{L^2}$.
    double E_H = 0, E_V = 0, E_u = 0;
    // $\lambda_1$ of the smallness condition (smallness_constant()).
    double       lambda_1  = 0;
    double       mesh_size = 0;
    unsigned int n_dofs = 0, n_steps = 0, newton_iterations = 0;

  private:
    void
    make_grid();
    void
    setup_system();
    void
    assemble_system();
    void
    assemble_rhs(const double time);
    unsigned int
    solve();
    void
    output_results(const unsigned int step) const;
    void
    accumulate_errors(const double time);

    // pieces of solve()
    unsigned int
    update_branches(const unsigned int iteration);
    double
    nonsmooth_residual() const;
    void
    solve_linearized(Vector<double> &trial);
    double
    nodal_energy(const Vector<double> &v) const;

    // The constant $\lambda_1$ of the smallness condition of one step:
    // $J_n$ is strictly convex, and each step has one solution, when
    // $\alpha_\nu < \lambda_1$.
    double
    smallness_constant() const;

    const ProblemData<dim> &data;
    const unsigned int      refinements;
    const double            time_step;
    const std::string       output_directory;

    Triangulation<dim>        triangulation;
    const FESystem<dim>       fe;
    DoFHandler<dim>           dof_handler;
    AffineConstraints<double> clamped_constraints;

    SparsityPattern      sparsity_pattern;
    SparseMatrix<double> mass_matrix;    // $\rho M$
    SparseMatrix<double> elastic_matrix; // $B$
    SparseMatrix<double> step_matrix;    // $K_0 = \rho/k\,M + A$
    SparseMatrix<double> newton_matrix;

    Vector<double> velocity;     // $w_n$
    Vector<double> old_velocity; // $w_{n-1}$
    Vector<double> displacement; // $u_n = u_0 + k\sum_{i<n} w_i$
    Vector<double> step_rhs;     // $\ell_n = \rho/k\,M w_{n-1} - B u_n + F_n$
    Vector<double> residual;     // $K_0 w - \ell_n$

    std::vector<ContactNode<dim>> contact_nodes;

    // Newton stops when no branch changes and the nonsmooth residual is below
    // $10^{-12}|\ell_n|$, the full program's tolerance in the comparison test
    // (so that the two agree to round-off over all steps), plus an absolute
    // floor for a step whose $\ell_n$ vanishes (a body at rest and unloaded).
    // 50 iterations are far more than a step needs (three on average, see the
    // results): more means that the branches cycle, and the program stops
    // with a message instead of looping.
    static constexpr double       tolerance          = 1e-12;
    static constexpr double       absolute_tolerance = 1e-14;
    static constexpr unsigned int max_iterations     = 50;
  };

  template <int dim>
  KelvinVoigtContact<dim>::KelvinVoigtContact(
    const ProblemData<dim> &data,
    const unsigned int      refinements,
    const double            time_step,
    const std::string      &output_directory)
    : data(data)
    , refinements(refinements)
    , time_step(time_step)
    , output_directory(output_directory)
    , fe(FE_Q<dim>(1), dim)
    , dof_handler(triangulation)
  {}

  // @sect4{KelvinVoigtContact::make_grid}
  //
  // A subdivided rectangle whose sides carry the boundary ids 0 (left),
  // 1 (right), 2 (bottom) and 3 (top) (colorize = true), refined globally.
  // The largest cell diameter is the $h$ of the convergence table.
  template <int dim>
  void
  KelvinVoigtContact<dim>::make_grid()
  {
    data.make_coarse_grid(triangulation);
    triangulation.refine_global(refinements);
    for (const auto &cell : triangulation.active_cell_iterators())
      mesh_size = std::max(mesh_size, cell->diameter());
  }

  // @sect4{KelvinVoigtContact::setup_system}
  //
  // $Q_1$ vector fields, zero on $\Gamma_1$: the clamped degrees of freedom
  // are the only constraints of the matrices. The active set adds its own
  // constraints in each Newton iteration (solve_linearized()); they tie the
  // components of one node together, entries the sparsity pattern holds
  // already, since the components of a vertex couple in every cell.
  template <int dim>
  void
  KelvinVoigtContact<dim>::setup_system()
  {
    dof_handler.distribute_dofs(fe);
    n_dofs = dof_handler.n_dofs();

    clamped_constraints.clear();
    VectorTools::interpolate_boundary_values(dof_handler,
                                             data.clamped_boundary,
                                             Functions::ZeroFunction<dim>(dim),
                                             clamped_constraints);
    clamped_constraints.close();

    DynamicSparsityPattern dsp(n_dofs);
    DoFTools::make_sparsity_pattern(dof_handler,
                                    dsp,
                                    clamped_constraints,
                                    true);
    sparsity_pattern.copy_from(dsp);
    for (SparseMatrix<double> *m :
         {&mass_matrix, &elastic_matrix, &step_matrix, &newton_matrix})
      m->reinit(sparsity_pattern);
    for (Vector<double> *v :
         {&velocity, &old_velocity, &displacement, &step_rhs, &residual})
      v->reinit(n_dofs);
  }

  // @sect4{KelvinVoigtContact::assemble_system}
  //
  // The matrices that do not change in time: $\rho M$, $A$, $B$ (two-point
  // Gauss, exact for $Q_1$ on rectangles) and the step matrix
  // @f[
  //   K_0 = \frac{\rho}{k} M + A.
  // @f]
  // Backward Euler in $w$ turns the inertia $\rho\dot w$ into $\rho(w_n -
  // w_{n-1})/k$, whose $w_n$ part is $\rho/k\,M$; the viscous stress adds
  // $A$. $B$ acts on $u_n$, which the left-point rule makes known before the
  // step, so it stays on the right-hand side. The constant $\rho/k$ in $K_0$
  // is also why a small enough $k$ makes each step uniquely solvable: it
  // lifts $\lambda_1$ of the smallness condition above $\alpha_\nu$
  // (smallness_constant(); like $k^{-1/2}$, not like $1/k$). Then the
  // contact nodes.
  template <int dim>
  void
  KelvinVoigtContact<dim>::assemble_system()
  {
    const QGauss<dim> quadrature(2);
    FEValues<dim>     fe_values(
      fe, quadrature, update_values | update_gradients | update_JxW_values);
    const unsigned int n = fe.n_dofs_per_cell();
    FullMatrix<double> cell_mass(n, n), cell_viscous(n, n), cell_elastic(n, n);
    std::vector<types::global_dof_index> dofs(n);
    const FEValuesExtractors::Vector     v(0);
    const Material                      &material = data.material;

    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        fe_values.reinit(cell);
        cell_mass    = 0;
        cell_viscous = 0;
        cell_elastic = 0;
        for (const unsigned int q : fe_values.quadrature_point_indices())
          for (unsigned int i = 0; i < n; ++i)
            {
              const SymmetricTensor<2, dim> eps_i =
                fe_values[v].symmetric_gradient(i, q);
              const SymmetricTensor<2, dim> a_i =
                material.viscosity.stress(eps_i);
              const SymmetricTensor<2, dim> b_i =
                material.elasticity.stress(eps_i);
              for (unsigned int j = 0; j < n; ++j)
                {
                  const double JxW = fe_values.JxW(q);
                  cell_mass(i, j) +=
                    material.density *
                    (fe_values[v].value(i, q) * fe_values[v].value(j, q)) * JxW;
                  cell_viscous(i, j) +=
                    (a_i * fe_values[v].symmetric_gradient(j, q)) * JxW;
                  cell_elastic(i, j) +=
                    (b_i * fe_values[v].symmetric_gradient(j, q)) * JxW;
                }
            }
        cell->get_dof_indices(dofs);
        clamped_constraints.distribute_local_to_global(cell_mass,
                                                       dofs,
                                                       mass_matrix);
        clamped_constraints.distribute_local_to_global(cell_elastic,
                                                       dofs,
                                                       elastic_matrix);
        cell_viscous.add(1. / time_step, cell_mass);
        clamped_constraints.distribute_local_to_global(cell_viscous,
                                                       dofs,
                                                       step_matrix);
      }

    // The contact nodes: the vertices of $\Gamma_3$ that are not clamped,
    // with $m_i = \int_{\Gamma_3}\varphi_i$ as the sum of $|F|/(\text{vertices
    // of } F)$ over the faces $F$ at the node (exact for $Q_1$ on flat faces,
    // and the same number step-1 integrates with FEFaceValues), the normal
    // averaged with the same weights, and $c_i = (\text{mean diagonal of }
    // K_0 \text{ at the node})/m_i$, which makes $c_i w_\nu$ and $s$ tractions
    // of the same size. The exponential law rises nowhere, so $c_i$ needs no
    // floor (step-1's floor is twice the steepest rise).
    FEFaceValues<dim> fe_face(fe, QGauss<dim - 1>(1), update_normal_vectors);
    std::map<types::global_dof_index, ContactNode<dim>> nodes;
    for (const auto &cell : dof_handler.active_cell_iterators())
      for (const auto &face : cell->face_iterators())
        if (face->at_boundary() && face->boundary_id() == data.contact_boundary)
          {
            fe_face.reinit(cell, face);
            const double share = face->measure() / face->n_vertices();
            for (const unsigned int v : face->vertex_indices())
              {
                ContactNode<dim> &node = nodes[face->vertex_dof_index(v, 0)];
                for (unsigned int c = 0; c < dim; ++c)
                  node.dofs[c] = face->vertex_dof_index(v, c);
                node.mass += share;
                node.normal += share * fe_face.normal_vector(0);
              }
          }
    contact_nodes.clear();
    for (auto &[dof, node] : nodes)
      if (!clamped_constraints.is_constrained(dof))
        {
          double diagonal = 0;
          for (unsigned int c = 0; c < dim; ++c)
            diagonal += step_matrix.diag_element(node.dofs[c]) / dim;
          node.c = diagonal / node.mass;
          node.normal /= node.normal.norm();
          contact_nodes.push_back(node);
        }
  }

  // @sect4{KelvinVoigtContact::assemble_rhs}
  //
  // The right-hand side of step $n$,
  // @f[
  //   \ell_n = \frac{\rho}{k} M w_{n-1} - B u_n + F_n,\qquad
  //   F_n\cdot v = \int_\Omega f_0(t_n)\cdot v + \int_{\Gamma_2} f_2(t_n)
  //   \cdot v \ \Bigl(+ \int_{\Gamma_3} f_3(t_n)\cdot v\Bigr),
  // @f]
  // the loads by three-point Gauss rules (the data are not polynomials, and
  // their quadrature error must stay below the discretisation error). The
  // clamped entries of $\ell_n$ are set to zero, the value the constraints give
  // them.
  template <int dim>
  void
  KelvinVoigtContact<dim>::assemble_rhs(const double time)
  {
    const QGauss<dim>                    quadrature(3);
    const QGauss<dim - 1>                face_quadrature(3);
    FEValues<dim>                        fe_values(fe,
                            quadrature,
                            update_values | update_quadrature_points |
                              update_JxW_values);
    FEFaceValues<dim>                    fe_face(fe,
                              face_quadrature,
                              update_values | update_quadrature_points |
                                update_normal_vectors | update_JxW_values);
    const FEValuesExtractors::Vector     v(0);
    const unsigned int                   n = fe.n_dofs_per_cell();
    Vector<double>                       cell_rhs(n);
    std::vector<types::global_dof_index> dofs(n);
    Vector<double>                       load(n_dofs);

    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        cell_rhs = 0;
        fe_values.reinit(cell);
        for (const unsigned int q : fe_values.quadrature_point_indices())
          {
            const Tensor<1, dim> f0 =
              data.body_force(fe_values.quadrature_point(q), time);
            for (unsigned int i = 0; i < n; ++i)
              cell_rhs(i) += f0 * fe_values[v].value(i, q) * fe_values.JxW(q);
          }
        // every boundary but $\Gamma_1$: the data's traction() knows $f_2$
        // and $f_3$ apart by the boundary id, as step-1's does
        for (const auto &face : cell->face_iterators())
          if (face->at_boundary() &&
              face->boundary_id() != data.clamped_boundary)
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
                    cell_rhs(i) += f * fe_face[v].value(i, q) * fe_face.JxW(q);
                }
            }
        cell->get_dof_indices(dofs);
        clamped_constraints.distribute_local_to_global(cell_rhs, dofs, load);
      }

    Vector<double> tmp(n_dofs);
    mass_matrix.vmult(step_rhs, old_velocity);
    step_rhs /= time_step;
    elastic_matrix.vmult(tmp, displacement);
    step_rhs -= tmp;
    step_rhs += load;
    clamped_constraints.set_zero(step_rhs);
  }

  // @sect3{The active-set Newton method}
  //
  // Step $n$ minimises the step energy
  // @f[
  //   J_n(w) = \frac12 w\cdot K_0 w - \ell_n\cdot w
  //            + \sum_i m_i \bigl[ j_\nu(w_{i,\nu}) + F_b |w_{i,\tau}| \bigr],
  // @f]
  // whose nodal sum is the nodal quadrature of the $\Gamma_3$ integrals. Its
  // stationarity condition at node $i$ is $G_i = m_i\xi_i$, with the nodal
  // contact force $G_i = -(K_0 w - \ell_n)_i$ and $\xi_i \in \partial
  // j_\nu(w_\nu) \nu + \partial(F_b|\cdot|)(w_\tau)$: step-1's problem with
  // $K_0$ for $K$, $\ell_n$ for $F_n$ and $w$ for $u$. The functions below
  // evaluate the node states, choose the branches from the complementarity
  // functions, linearise and solve, and damp the update by backtracking on
  // $J_n$.

  // @sect4{KelvinVoigtContact::update_branches}
  //
  // The complementarity functions
  // @f[
  //   C_\nu = s - P_{[0,a]}(s + c\,w_\nu),\qquad
  //   C_\tau = \lambda - P_{|\cdot| \le F_b}(\lambda + c\,w_\tau)
  // @f]
  // vanish exactly at the solution; their projections decide the branches
  // (see ContactNode). After the first iteration of a step a node does not
  // jump between separating and damped directly but passes through normal
  // stick, the branch between them: groups of nodes at the edge of a lifting
  // contact zone would otherwise alternate between the two, each iteration
  // undoing the last. Returns the number of nodes whose branches
  // changed.
  template <int dim>
  unsigned int
  KelvinVoigtContact<dim>::update_branches(const unsigned int iteration)
  {
    const double a         = data.normal_law.a;
    unsigned int n_changed = 0;
    for (ContactNode<dim> &node : contact_nodes)
      {
        Tensor<1, dim> w, traction;
        for (unsigned int c = 0; c < dim; ++c)
          {
            w[c]        = velocity(node.dofs[c]);
            traction[c] = -residual(node.dofs[c]) / node.mass;
          }
        node.w_nu  = w * node.normal;
        node.w_tau = w - node.w_nu * node.normal;
        node.s = traction * node.normal - data.normal_law.remainder(node.w_nu);
        node.lambda = traction - (traction * node.normal) * node.normal;

        const double q_nu   = node.s + node.c * node.w_nu;
        NormalBranch normal = q_nu < 0  ? NormalBranch::separating :
                              q_nu <= a ? NormalBranch::stick :
                                          NormalBranch::damped;
        if (iteration > 0 && a > 0 &&
            ((node.normal_branch == NormalBranch::separating &&
              normal == NormalBranch::damped) ||
             (node.normal_branch == NormalBranch::damped &&
              normal == NormalBranch::separating)))
          normal = NormalBranch::stick;
        const TangentialBranch tangential =
          (node.lambda + node.c * node.w_tau).norm() > data.friction_bound ?
            TangentialBranch::slip :
            TangentialBranch::stick;

        if (normal != node.normal_branch ||
            tangential != node.tangential_branch)
          ++n_changed;
        node.normal_branch     = normal;
        node.tangential_branch = tangential;
      }
    return n_changed;
  }

  // @sect4{KelvinVoigtContact::nonsmooth_residual}
  //
  // Equilibrium on the free degrees of freedom away from $\Gamma_3$, and the
  // complementarity functions, as nodal forces $m_i C$, at the contact nodes:
  // every term is a force, so one norm measures them together.
  template <int dim>
  double
  KelvinVoigtContact<dim>::nonsmooth_residual() const
  {
    Vector<double> free_part(residual);
    for (const ContactNode<dim> &node : contact_nodes)
      for (unsigned int c = 0; c < dim; ++c)
        free_part(node.dofs[c]) = 0;
    double sum = free_part.norm_sqr();

    const double a = data.normal_law.a, F_b = data.friction_bound;
    for (const ContactNode<dim> &node : contact_nodes)
      {
        const double C_nu =
          node.s - std::clamp(node.s + node.c * node.w_nu, 0., a);
        const Tensor<1, dim> q = node.lambda + node.c * node.w_tau;
        const Tensor<1, dim> C_tau =
          node.lambda - (q.norm() <= F_b ? q : F_b / q.norm() * q);
        sum += node.mass * node.mass * (C_nu * C_nu + C_tau.norm_square());
      }
    return std::sqrt(sum);
  }

  // @sect4{KelvinVoigtContact::solve_linearized}
  //
  // One Newton step on the current branches: minimise
  // @f[
  //   \frac12 x\cdot\Bigl(K_0 + \sum_i L_i\Bigr) x - g\cdot x
  // @f]
  // over the fields that satisfy the constraints of the stick branches, with
  // the free branches' nodal forces linearised about the iterate $w_k$,
  // $G_i \approx f_i + L_i(x - w_k)$:
  // - damped: $f_i = m_i(a + p(w_\nu))\nu$, $L_i = m_i p'(w_\nu)\,\nu\otimes
  //   \nu$ (negative: the exponential law falls);
  // - slip: $f_i = m_i F_b d + T_i w_\tau$, $L_i = T_i$, with $d = q/|q|$,
  //   $q = \lambda + c\,w_\tau$ and the semismooth Newton tangent of the
  //   friction disk $T_i = m_i F_b c/(|q| - F_b)\,(I - \nu\otimes\nu -
  //   d\otimes d)$, zero in 2D; the floor on $|q| - F_b$ bounds it for nodes
  //   that barely slip. The term $T_i w_\tau$ is step-1's $T_i u_\tau$: the
  //   Newton step of $C_\tau = 0$ gives the new multiplier $F_b d + T_i
  //   x/m_i$, and written as $f_i + L_i(x - w_k)$ that needs $f_i = m_i F_b
  //   d + T_i w_k = m_i F_b d + T_i w_\tau$ ($T_i\nu = 0$);
  // - separating: no force; stick branches: a constraint instead.
  //
  // The constraints $w\cdot\nu = 0$ (normal stick) and $w_\tau = 0$
  // (tangential stick) are rows of an AffineConstraints object (with the
  // clamped degrees of freedom). step-1 hands its constraints to
  // distribute_local_to_global() while it assembles; here the matrix $K_0$
  // is assembled once for all steps, so it is copied and condensed, and the
  // system is solved by UMFPACK, as the active set of deal.II's step-41
  // is.
  template <int dim>
  void
  KelvinVoigtContact<dim>::solve_linearized(Vector<double> &trial)
  {
    newton_matrix.copy_from(step_matrix);
    Vector<double>            newton_rhs(step_rhs);
    AffineConstraints<double> constraints;
    constraints.merge(clamped_constraints);

    const double a = data.normal_law.a, F_b = data.friction_bound;
    for (const ContactNode<dim> &node : contact_nodes)
      {
        const Tensor<1, dim> &nu = node.normal;

        Tensor<2, dim> L;
        Tensor<1, dim> f;
        if (node.normal_branch == NormalBranch::damped)
          {
            f += node.mass * (a + data.normal_law.remainder(node.w_nu)) * nu;
            L += node.mass * data.normal_law.remainder_derivative(node.w_nu) *
                 outer_product(nu, nu);
          }
        if (node.tangential_branch == TangentialBranch::slip)
          {
            const Tensor<1, dim> q = node.lambda + node.c * node.w_tau;
            const Tensor<1, dim> d = q / q.norm();
            const double   excess  = std::max(q.norm() - F_b, 1e-2 * q.norm());
            Tensor<2, dim> T       = unit_symmetric_tensor<dim>();
            T -= outer_product(nu, nu) + outer_product(d, d);
            T *= node.mass * F_b * node.c / excess;
            L += T;
            f += node.mass * F_b * d + T * node.w_tau;
          }

        // $K_0 + L_i$, and $g_i = b_i + L_i w_k - f_i$
        Tensor<1, dim> w_k;
        for (unsigned int c = 0; c < dim; ++c)
          w_k[c] = velocity(node.dofs[c]);
        const Tensor<1, dim> g = L * w_k - f;
        for (unsigned int c = 0; c < dim; ++c)
          {
            newton_rhs(node.dofs[c]) += g[c];
            for (unsigned int e = 0; e < dim; ++e)
              if (L[c][e] != 0)
                newton_matrix.add(node.dofs[c], node.dofs[e], L[c][e]);
          }

        // The stick constraints, written on the component $p$ where $|\nu_p|$
        // is largest (dividing by it is safest): $w\cdot\nu = 0$ is $w_p =
        // -\sum_{c \ne p} \nu_c/\nu_p\,w_c$, and $w_\tau = 0$ ($w$ parallel to
        // $\nu$) is $w_c = \nu_c/\nu_p\,w_p$ for $c \ne p$.
        const bool normal_stick = node.normal_branch == NormalBranch::stick;
        const bool tangential_stick =
          node.tangential_branch == TangentialBranch::stick;
        if (!normal_stick && !tangential_stick)
          continue;
        unsigned int p = 0;
        for (unsigned int c = 1; c < dim; ++c)
          if (std::abs(nu[c]) > std::abs(nu[p]))
            p = c;
        for (unsigned int c = 0; c < dim; ++c)
          {
            if (normal_stick && tangential_stick) // w = 0
              constraints.add_line(node.dofs[c]);
            else if (normal_stick && c == p)
              {
                constraints.add_line(node.dofs[p]);
                for (unsigned int e = 0; e < dim; ++e)
                  if (e != p && nu[e] != 0)
                    constraints.add_entry(node.dofs[p],
                                          node.dofs[e],
                                          -nu[e] / nu[p]);
              }
            else if (tangential_stick && c != p)
              {
                constraints.add_line(node.dofs[c]);
                if (nu[c] != 0)
                  constraints.add_entry(node.dofs[c],
                                        node.dofs[p],
                                        nu[c] / nu[p]);
              }
          }
      }
    constraints.close();
    constraints.condense(newton_matrix, newton_rhs);

    SparseDirectUMFPACK direct_solver;
    direct_solver.initialize(newton_matrix);
    direct_solver.vmult(trial, newton_rhs);
    constraints.distribute(trial);
  }

  // @sect4{The step energy for the line search}
  //
  // Along the Newton direction $d$,
  // @f[
  //   J_n(w + \theta d) - J_n(w) = \theta\,d\cdot(K_0 w - \ell_n)
  //     + \frac{\theta^2}2\,d\cdot K_0 d + (\text{change of the nodal part}),
  // @f]
  // with the nodal part $\sum_i m_i [j_\nu(w_{i,\nu}) + F_b|w_{i,\tau}|]$
  // computed here. The line search evaluates this change, not $J_n$ itself:
  // $J_n$ is a sum of large terms of both signs, and its difference at two
  // nearby points would lose its digits to cancellation, while the slope and
  // the curvature of the quadratic part are computed once and exactly.
  template <int dim>
  double
  KelvinVoigtContact<dim>::nodal_energy(const Vector<double> &v) const
  {
    double energy = 0;
    for (const ContactNode<dim> &node : contact_nodes)
      {
        Tensor<1, dim> w;
        for (unsigned int c = 0; c < dim; ++c)
          w[c] = v(node.dofs[c]);
        const double w_nu = w * node.normal;
        energy +=
          node.mass * (data.normal_law.potential(w_nu) +
                       data.friction_bound * (w - w_nu * node.normal).norm());
      }
    return energy;
  }

  // @sect4{KelvinVoigtContact::solve}
  //
  // The active-set Newton method for one step, started from $w_{n-1}$ (the
  // previous step's solution is close, since $w$ changes by $O(k)$): the
  // branches from the complementarity functions; stop when no branch changed
  // and the nonsmooth residual is below the tolerance (or far below it,
  // whatever the branches do); else a Newton step on the branches, damped by
  // halving $\theta$ from 1 to $2^{-10}$ until it does not raise $J_n$ beyond
  // round-off (the full step if no length does: step-1's rule). Returns the
  // number of Newton steps.
  template <int dim>
  unsigned int
  KelvinVoigtContact<dim>::solve()
  {
    const double   target = tolerance * step_rhs.l2_norm() + absolute_tolerance;
    Vector<double> trial(n_dofs), direction(n_dofs), K_d(n_dofs),
      candidate(n_dofs);

    step_matrix.vmult(residual, velocity);
    residual -= step_rhs;
    for (unsigned int iteration = 0;; ++iteration)
      {
        const unsigned int n_changed = update_branches(iteration);
        const double       res       = nonsmooth_residual();
        if ((n_changed == 0 && res <= target) || res <= 1e-2 * target)
          return iteration;
        AssertThrow(iteration < max_iterations,
                    ExcMessage("Newton did not converge in " +
                               std::to_string(max_iterations) +
                               " iterations."));

        solve_linearized(trial);

        // the line search on $J_n$ along $d$ = trial $- w$; $K_0$ is linear, so
        // the residual at $w + \theta d$ is updated from $K_0 d$ without a
        // product
        direction = trial;
        direction -= velocity;
        step_matrix.vmult(K_d, direction);
        const double slope     = direction * residual;
        const double curvature = direction * K_d;
        const double nodal_0   = nodal_energy(velocity);
        const double scale =
          std::abs(slope) + std::abs(curvature) + std::abs(nodal_0) + 1e-300;
        const auto change = [&](const double theta) {
          candidate = velocity;
          candidate.add(theta, direction);
          return theta * slope + 0.5 * theta * theta * curvature +
                 nodal_energy(candidate) - nodal_0;
        };
        // The rule of step-1: the first of $\theta = 1, \frac12, \dots,
        // 2^{-10}$ that does not raise $J_n$ beyond round-off, and the full
        // step if none does (the direction is then not one of descent, which
        // happens only while the branches are still wrong; the full step moves
        // to branches the next update_branches() corrects, where a tiny step
        // would stall). The block and the first three levels of the
        // manufactured solution never reach that fallback.
        double theta = 1;
        for (; theta >= 1. / 1024; theta /= 2)
          if (change(theta) <= 1e-12 * scale)
            break;
        if (theta < 1. / 1024)
          theta = 1;
        velocity.add(theta, direction);
        residual.add(theta, K_d); // $K_0$ is linear
      }
  }

  // @sect4{KelvinVoigtContact::smallness_constant}
  //
  // step-1's smallness condition with $K_0$ for $K$: $J_n$ is strictly
  // convex when
  // @f[
  //   \alpha_\nu < \lambda_1 = \min_{v \ne 0}
  //     \frac{v\cdot K_0 v}{\sum_i m_i (v_i\cdot\nu_i)^2},
  // @f]
  // the smallest eigenvalue of $K_0 x = \lambda N x$, $N = \sum_i m_i
  // \nu_i\otimes\nu_i$. We compute it as step-1, step-3 and step-4 do: the
  // power iteration $x \leftarrow K_0^{-1} N x$ for the largest eigenvalue
  // $1/\lambda_1$ of $K_0^{-1} N$, one UMFPACK solve per iteration, until
  // the Rayleigh quotient changes by less than $10^{-12}$ relative. $K_0$
  // holds $\rho/k\,M$, but $\lambda_1$ does not grow like $\rho/k$: the
  // lowest mode lives in a layer along $\Gamma_3$ whose depth shrinks with
  // $k$ (the introduction, "One step is a minimisation").
  template <int dim>
  double
  KelvinVoigtContact<dim>::smallness_constant() const
  {
    const auto apply_N = [&](const Vector<double> &v, Vector<double> &Nv) {
      Nv = 0;
      for (const ContactNode<dim> &node : contact_nodes)
        {
          double v_nu = 0;
          for (unsigned int c = 0; c < dim; ++c)
            v_nu += v(node.dofs[c]) * node.normal[c];
          for (unsigned int c = 0; c < dim; ++c)
            Nv(node.dofs[c]) = node.mass * v_nu * node.normal[c];
        }
    };

    SparseDirectUMFPACK K0_inverse;
    K0_inverse.initialize(step_matrix);
    Vector<double> x(n_dofs), Nx(x), Kx(x);
    for (const ContactNode<dim> &node : contact_nodes)
      for (unsigned int c = 0; c < dim; ++c)
        x(node.dofs[c]) = node.normal[c];

    double lambda = std::numeric_limits<double>::max();
    for (unsigned int iteration = 0; iteration < 1000; ++iteration)
      {
        apply_N(x, Nx);
        K0_inverse.vmult(x, Nx);
        x /= x.l2_norm();
        step_matrix.vmult(Kx, x);
        apply_N(x, Nx);
        const double quotient = (x * Kx) / (x * Nx);
        if (std::abs(quotient - lambda) <= 1e-12 * quotient)
          return quotient;
        lambda = quotient;
      }
    AssertThrow(false,
                ExcMessage("The power iteration for the smallness constant "
                           "did not converge in 1000 steps."));
    return lambda;
  }

  // @sect4{KelvinVoigtContact::output_results}
  //
  // A VTU file of $w_n$ and $u_n$ for ParaView, and the nodal values in full
  // double precision (x, y, w, u per vertex, "%.17g"): the file the
  // comparison with the full program reads, at a precision that lets it
  // check agreement to $10^{-10}$.
  template <int dim>
  void
  KelvinVoigtContact<dim>::output_results(const unsigned int step) const
  {
    char number[16];
    std::snprintf(number, sizeof(number), "%05u", step);

    DataOut<dim> data_out;
    data_out.attach_dof_handler(dof_handler);
    const std::vector<DataComponentInterpretation::DataComponentInterpretation>
      vector(dim, DataComponentInterpretation::component_is_part_of_vector);
    data_out.add_data_vector(velocity,
                             std::vector<std::string>(dim, "velocity"),
                             DataOut<dim>::type_dof_data,
                             vector);
    data_out.add_data_vector(displacement,
                             std::vector<std::string>(dim, "displacement"),
                             DataOut<dim>::type_dof_data,
                             vector);
    data_out.build_patches();
    std::ofstream vtu(output_directory + "/solution_" + number + ".vtu");
    data_out.write_vtu(vtu);

    std::FILE *nodal =
      std::fopen((output_directory + "/nodal_" + number + ".txt").c_str(), "w");
    AssertThrow(nodal != nullptr, ExcIO());
    std::fprintf(nodal,
                 "# step %u, t = %.17g; x[dim] w[dim] u[dim]\n",
                 step,
                 step * time_step);
    std::set<types::global_dof_index> written;
    for (const auto &cell : dof_handler.active_cell_iterators())
      for (const unsigned int v : cell->vertex_indices())
        if (written.insert(cell->vertex_dof_index(v, 0)).second)
          {
            for (unsigned int d = 0; d < dim; ++d)
              std::fprintf(nodal, "%.17g ", cell->vertex(v)[d]);
            for (const Vector<double> *field : {&velocity, &displacement})
              for (unsigned int c = 0; c < dim; ++c)
                std::fprintf(nodal,
                             "%.17g ",
                             (*field)(cell->vertex_dof_index(v, c)));
            std::fprintf(nodal, "\n");
          }
    std::fclose(nodal);
  }

  // @sect4{KelvinVoigtContact::accumulate_errors}
  //
  // $\|w(t_n) - w_n\|_{L^2}$, $\|\varepsilon(w(t_n) - w_n)\|_{L^2}$ and
  // $\|\varepsilon(u(t_n) - u_n)\|_{L^2}$ by a three-point Gauss rule, into
  // the maxima $E_H$, $E_u$ and the sum of $E_V$. The exact solution is not a
  // polynomial: one point more than the assembly keeps the quadrature error
  // below the error measured.
  template <int dim>
  void
  KelvinVoigtContact<dim>::accumulate_errors(const double time)
  {
    const QGauss<dim>                quadrature(3);
    FEValues<dim>                    fe_values(fe,
                            quadrature,
                            update_values | update_gradients |
                              update_quadrature_points | update_JxW_values);
    const FEValuesExtractors::Vector v(0);
    std::vector<Tensor<1, dim>>      w_h(quadrature.size());
    std::vector<Tensor<2, dim>>      grad_w_h(quadrature.size()),
      grad_u_h(quadrature.size());
    double w_L2 = 0, w_V = 0, u_V = 0;
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        fe_values.reinit(cell);
        fe_values[v].get_function_values(velocity, w_h);
        fe_values[v].get_function_gradients(velocity, grad_w_h);
        fe_values[v].get_function_gradients(displacement, grad_u_h);
        for (const unsigned int q : fe_values.quadrature_point_indices())
          {
            const ExactValues<dim> e =
              data.exact(fe_values.quadrature_point(q), time);
            const SymmetricTensor<2, dim> eps_w =
              symmetrize(Tensor<2, dim>(e.grad_w - grad_w_h[q]));
            const SymmetricTensor<2, dim> eps_u =
              symmetrize(Tensor<2, dim>(e.grad_u - grad_u_h[q]));
            w_L2 += (e.w - w_h[q]).norm_square() * fe_values.JxW(q);
            w_V += eps_w * eps_w * fe_values.JxW(q);
            u_V += eps_u * eps_u * fe_values.JxW(q);
          }
      }
    E_H = std::max(E_H, std::sqrt(w_L2));
    E_u = std::max(E_u, std::sqrt(u_V));
    E_V = std::sqrt(E_V * E_V + time_step * w_V);
  }

  // @sect4{KelvinVoigtContact::run}
  //
  // The time loop of Problem 4.4: $w_0$ and $u_0$ interpolated, then for $n =
  // 1, \dots, N$ the left-point rule $u_n = u_{n-1} + k\,w_{n-1}$, the
  // right-hand side with $w_{n-1}$ and $u_n$, and the step problem for $w_n$.
  // The left-point rule is the paper's choice: it makes $u_n$ known before
  // step $n$, so that each step is a problem in $w_n$ alone, with the same
  // matrix $K_0$ at every step.
  template <int dim>
  void
  KelvinVoigtContact<dim>::run()
  {
    make_grid();
    setup_system();
    assemble_system();
    lambda_1 = smallness_constant();

    // nodal interpolation of $u_0$ and $w_0$ (their values at the vertices
    // are the $Q_1$ coefficients)
    for (const auto &cell : dof_handler.active_cell_iterators())
      for (const unsigned int v : cell->vertex_indices())
        {
          const Tensor<1, dim> u_0 = data.initial_displacement(cell->vertex(v));
          const Tensor<1, dim> w_0 = data.initial_velocity(cell->vertex(v));
          for (unsigned int c = 0; c < dim; ++c)
            {
              displacement(cell->vertex_dof_index(v, c)) = u_0[c];
              velocity(cell->vertex_dof_index(v, c))     = w_0[c];
            }
        }
    clamped_constraints.distribute(velocity);
    clamped_constraints.distribute(displacement);

    n_steps =
      static_cast<unsigned int>(std::llround(data.end_time / time_step));
    const bool write = !output_directory.empty();
    if (write)
      {
        // The smallness condition of the steps, printed as step-1 prints
        // it: $K_0$ is the same at every step.
        const double alpha_nu = data.normal_law.alpha();
        std::cout << "alpha_nu = " << alpha_nu << ", lambda_1 = " << lambda_1
                  << (alpha_nu < lambda_1 ?
                        " (alpha_nu < lambda_1: one solution per step)" :
                        " (alpha_nu >= lambda_1: maybe several solutions)")
                  << std::endl;
        std::filesystem::create_directories(output_directory);
        output_results(0);
      }
    for (unsigned int step = 1; step <= n_steps; ++step)
      {
        const double time = step * time_step;
        displacement.add(time_step, velocity); // $u_n = u_{n-1} + k w_{n-1}$
        old_velocity = velocity;
        assemble_rhs(time);
        const unsigned int iterations = solve();
        newton_iterations += iterations;

        if (data.has_exact_solution())
          accumulate_errors(time);
        if (write)
          {
            unsigned int count[5] = {0, 0, 0, 0, 0};
            for (const ContactNode<dim> &node : contact_nodes)
              {
                ++count[static_cast<int>(node.normal_branch)];
                ++count[3 + static_cast<int>(node.tangential_branch)];
              }
            std::printf("step %3u  t = %.4f  Newton %u  separating %u  "
                        "normal stick %u  damped %u  stick %u  slip %u\n",
                        step,
                        time,
                        iterations,
                        count[0],
                        count[1],
                        count[2],
                        count[3],
                        count[4]);
            output_results(step);
          }
      }
  }
} // namespace Step2

// @sect3{The command line}
//
// As in step-1, every argument is checked before anything is computed,
// and a bad one stops the program with a one-paragraph message and the
// exit code 2 (1 is kept for a run that fails). Without the check,
// std::stoi() reads "3x" as 3, and "-1" read into an unsigned int is
// 4294967295 levels: a run that never ends.
namespace CommandLine
{
  constexpr int exit_bad_arguments = 2;

  // Each level halves h and k together: four times the unknowns, twice
  // the time steps, and with the direct solver UMFPACK about fifteen times
  // the time of the level before. Five levels end at $h = 0.011$, $k =
  // 1/128$ with 33,282 unknowns: measured, 6 min 16 s and 0.28 GB on one
  // core for the whole study (doc/results.md, "Running it"). A sixth level
  // would run for more than an hour: the program refuses it rather than
  // let a typo occupy the machine.
  constexpr unsigned int max_levels = 5;

  const char *const usage =
    "usage: step-2                        the block into output-block/, then\n"
    "                                     4 levels of the manufactured solution\n"
    "       step-2 block [DIR]            the block, output into DIR\n"
    "                                     (default output-block)\n"
    "       step-2 convergence [LEVELS]   LEVELS levels (1 to 5, default 4)\n"
    "                                     of the manufactured solution\n"
    "       step-2 --help                 this text\n"
    "exit codes: 0 done, 1 the computation failed, 2 a bad argument";

  // The error of a bad command line: its message names the argument.
  struct BadArguments : public std::runtime_error
  {
    using std::runtime_error::runtime_error;
  };

  // A number of levels: decimal digits only (no sign, no blanks, nothing
  // after the number), from 1 to max_levels. Reading the digits ourselves
  // rejects "-1", "+2", "abc", "3x" and " 3" alike; at most three digits
  // keep the conversion far from overflow.
  unsigned int
  parse_levels(const std::string &text)
  {
    const bool digits_only =
      !text.empty() && text.size() <= 3 &&
      std::all_of(text.begin(), text.end(), [](const char c) {
        return c >= '0' && c <= '9';
      });
    const unsigned int levels = digits_only ? std::stoul(text) : 0;
    if (!digits_only || levels < 1 || levels > max_levels)
      throw BadArguments(
        "the number of levels must be a whole number "
        "from 1 to " +
        std::to_string(max_levels) + ", not '" + text +
        "' (the five levels take 6 minutes, a sixth more than an hour)");
    return levels;
  }
} // namespace CommandLine

// @sect3{The main function}
//
// "step-2 block DIR" runs the block of the full program's example and
// writes its output to DIR; "step-2 convergence L" runs the manufactured
// solution on L levels of coupled refinement (h and k halved together,
// from 8 x 8 cells and k = 1/8) and prints the errors with their observed
// orders. Without arguments: both, with output-block/ and four levels.
int
main(int argc, char **argv)
{
  using namespace Step2;
  bool         run_block = true, run_convergence = true;
  std::string  directory = "output-block";
  unsigned int n_levels  = 4;
  try
    {
      const std::vector<std::string> arguments(argv + 1, argv + argc);
      const std::string mode = arguments.empty() ? "" : arguments[0];
      const bool        help = mode == "--help" || mode == "-h";
      if (help)
        run_block = run_convergence = false;
      else if (mode == "block")
        run_convergence = false;
      else if (mode == "convergence")
        run_block = false;
      else if (!arguments.empty())
        throw CommandLine::BadArguments("unknown mode '" + mode +
                                        "' (the modes are block and "
                                        "convergence)");
      // how many arguments the mode takes, itself included
      const std::size_t n_allowed = mode.empty() ? 0 : help ? 1 : 2;
      if (arguments.size() > n_allowed)
        throw CommandLine::BadArguments("too many arguments: '" +
                                        arguments[n_allowed] + "' after '" +
                                        arguments[n_allowed - 1] + "'");
      if (help)
        {
          std::cout << CommandLine::usage << std::endl;
          return 0;
        }
      if (mode == "block" && arguments.size() == 2)
        {
          // An empty name would mean "write nothing" to the class (its
          // output_directory), and a name that starts with '-' is almost
          // always a misplaced option.
          if (arguments[1].empty() || arguments[1][0] == '-')
            throw CommandLine::BadArguments(
              "the output directory must be a name that does not start "
              "with '-', not '" +
              arguments[1] + "'");
          directory = arguments[1];
        }
      if (mode == "convergence" && arguments.size() == 2)
        n_levels = CommandLine::parse_levels(arguments[1]);
    }
  catch (const CommandLine::BadArguments &error)
    {
      std::cerr << "step-2: " << error.what() << ".\n"
                << CommandLine::usage << std::endl;
      return CommandLine::exit_bad_arguments;
    }

  try
    {
      if (run_block)
        {
          const BlockData       block;
          KelvinVoigtContact<2> problem(block, 3, 0.04, directory);
          std::cout << "The block of prm/block_2d.prm, 32 x 8 cells, k = 0.04"
                    << std::endl;
          problem.run();
          std::cout << "Output in " << directory << "/" << std::endl
                    << std::endl;
        }
      if (run_convergence)
        {
          const ManufacturedData exact;
          ConvergenceTable       table;
          for (unsigned int level = 0; level < n_levels; ++level)
            {
              KelvinVoigtContact<2> problem(exact,
                                            3 + level,
                                            0.125 / (1 << level));
              problem.run();
              table.add_value("level", level);
              table.add_value("h", problem.mesh_size);
              table.add_value("k", 0.125 / (1 << level));
              table.add_value("dofs", problem.n_dofs);
              table.add_value("E_H", problem.E_H);
              table.add_value("E_V", problem.E_V);
              table.add_value("E_u", problem.E_u);
              table.add_value("Newton",
                              double(problem.newton_iterations) /
                                problem.n_steps);
              table.add_value("lambda_1", problem.lambda_1);
            }
          for (const std::string column : {"h", "k", "E_H", "E_V", "E_u"})
            {
              table.set_precision(column, 3);
              table.set_scientific(column, true);
            }
          table.set_precision("Newton", 2);
          table.set_precision("lambda_1", 2);
          for (const std::string column : {"E_H", "E_V", "E_u"})
            table.evaluate_convergence_rates(
              column, ConvergenceTable::reduction_rate_log2);
          std::cout << "Manufactured solution, coupled refinement k = h/sqrt(2)"
                    << " (Newton: mean iterations per step; lambda_1 against"
                    << " alpha_nu = " << exact.normal_law.alpha() << ")"
                    << std::endl;
          table.write_text(std::cout);
        }
    }
  catch (std::exception &exc)
    {
      std::cerr << "step-2: " << exc.what() << std::endl;
      return 1;
    }
  return 0;
}
