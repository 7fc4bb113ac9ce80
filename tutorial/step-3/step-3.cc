/* ---------------------------------------------------------------------
 *
 * hemicontact tutorial, step-3: static contact with long memory.
 *
 * The static contact problem of step-1 (a nonmonotone piecewise-linear
 * normal compliance and Tresca friction, solved by the primal-dual active
 * set method) for a material and a foundation that remember: the stress
 * of the history-dependent elastic model
 *   sigma(t) = B eps(u(t)) + int_0^t ℛ(t - s) eps(u(s)) ds
 * with a Prony-series relaxation kernel ℛ, and a normal response that
 * grows with the time the foundation was penetrated,
 *   -sigma_nu in d j_nu(u_nu) + int_0^t kappa(t - s) (u_nu(s))_+ ds.
 * Each load value is still one static problem, the memory a known term
 * of its right-hand side.
 *
 * The introduction (doc/intro.md) states the model, the rule for the
 * memory integrals and the recursion that makes them cost the same at
 * every step; the results (doc/results.md) show what this program prints.
 * The program depends on deal.II alone. It computes the same discrete
 * solution as the full program hemicontact (problem/class = static with
 * relaxation/kernel = prony and normal memory/kernel = prony):
 * tests/tutorial/step_3_vs_hemicontact.sh compares the two.
 *
 * ---------------------------------------------------------------------
 */

// @sect3{Include files}

// The headers of step-1: a serial program with a direct solver.
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
#include <memory>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace Step3
{
  using namespace dealii;

  // @sect3{The normal law}

  // The normal compliance of step-1, unchanged: the response $\xi_\nu$ of
  // the foundation to a penetration $r = u_\nu > 0$ is continuous and
  // piecewise linear through breakpoints $(r_k, \xi_k)$, $r_0 = 0$,
  // constant after the last one, and the Clarke subdifferential fills the
  // jump at $r = 0$: $\partial j_\nu(0) = [0, a]$. As there, the law is
  // split into the convex jump and a Lipschitz remainder,
  // @f[
  //   \partial j_\nu(r) = \partial(a r_+)(r) + p(r),\qquad
  //   p(r) = \xi(r) - a \ (r > 0),\quad p(r) = 0 \ (r \le 0),
  // @f]
  // the jump becoming a complementarity condition, the remainder a force
  // that Newton's method linearises. The memory of the foundation (below)
  // is not part of the law: it is a pressure added to the law's response,
  // known before each load value is solved, so the law and the whole
  // active-set method stay those of step-1.
  //
  // The rest of the program sees the law only through these members,
  // which is all a new law has to supply:
  // - jump(): $a$, the height of the jump at $r = 0$;
  // - response(r): $\xi(r)$ for $r > 0$;
  // - remainder(r) and remainder_derivative(r): $p(r)$ and $p'(r)$;
  // - potential(r): $j_\nu(r) = \int_0^r \xi$, for the energy of the line
  //   search;
  // - alpha: $\alpha_\nu$, the relaxed monotonicity constant, for the
  //   uniqueness condition;
  // - steepest_rise: the largest $p'$, for the floor of the constants $c_i$
  //   (setup_contact_nodes()).
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
          alpha         = std::max(alpha, -slope(k));
          steepest_rise = std::max(steepest_rise, slope(k));
        }
    }

    double
    jump() const
    {
      return points[0].second;
    }

    // $\xi(r)$ for $r > 0$, $p(r)$ and $p'(r)$ (at a breakpoint, the slope
    // to its right).
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

    // $j_\nu(r) = \int_0^r \xi$, exact segment by segment.
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

  private:
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

  // @sect3{The memory kernels}

  // Two kernels, both Prony series (sums of decaying exponentials). The
  // kernel of the stress, the relaxation tensor $\mathcal R$ of the literature
  // (positive amplitudes stiffen the body, negative ones soften it), is
  // isotropic,
  // @f[
  //   \mathcal R(t)\varepsilon = \sum_m e^{-t/\tau_m}\bigl(2\mu_m\varepsilon +
  //   \lambda_m\,\mathrm{tr}(\varepsilon) I\bigr),
  // @f]
  // one RelaxationTerm $(\mu_m, \lambda_m, \tau_m)$ per exponential; the
  // kernel of the foundation's memory is scalar,
  // @f[
  //   \kappa(t) = \sum_m \kappa_m e^{-t/\tau_m},
  // @f]
  // one NormalMemoryTerm $(\kappa_m, \tau_m)$ per exponential. The program
  // never evaluates $\mathcal R(t)$ or $\kappa(t)$ themselves: the recursion of
  // the memory (advance_memory()) needs only the amplitudes and the decay
  // factor $e^{-k/\tau_m}$ of one step, and the manufactured solution the
  // convolution of one exponential with its time factor. That is the
  // whole interface of a kernel, and all a new one (more terms, other
  // times) has to supply. An empty list is no memory.
  struct RelaxationTerm
  {
    // The Lam\'e constants of one term of $\mathcal R$ and its decay time.
    double mu, lambda, tau;
  };

  struct NormalMemoryTerm
  {
    // The amplitude of one term of $\kappa$ and its decay time.
    double kappa, tau;
  };

  // The kernels of this program, written once: the block and the
  // manufactured solution share them, and tests/tutorial/step_3_block.prm
  // gives the full program the same numbers.
  const std::vector<RelaxationTerm>   relaxation_kernel    = {{20, 30, 0.25},
                                                              {10, 10, 2}};
  const std::vector<NormalMemoryTerm> normal_memory_kernel = {{10, 0.5},
                                                              {2, 2}};

  // The factor $e^{-k/\tau}$ by which a term's history decays over a step
  // of length $k$.
  double
  decay(const double tau, const double k)
  {
    return std::exp(-k / tau);
  }

  // @sect3{The problem data}

  // The boundary ids of step-1: GridGenerator::subdivided_hyper_rectangle()
  // with colorize = true numbers a rectangle's sides left 0, right 1,
  // bottom 2, top 3; the left side is clamped ($\Gamma_1$), the bottom in
  // contact ($\Gamma_3$), every other side loaded ($\Gamma_2$).
  namespace BoundaryIds
  {
    constexpr types::boundary_id clamped = 0;
    constexpr types::boundary_id contact = 2;
  } // namespace BoundaryIds

  // What defines one problem: step-1's ProblemData (the Lam\'e constants
  // of $B$, the friction bound, the law, the coarse mesh and the loads as
  // virtual functions of $x$ and the load parameter $t$) plus the two
  // kernels and the end $T$ of the load history. In step-1 the load
  // values were independent problems and main() chose them; here they are
  // a history, $t_n = n k$ for $n = 0, \dots, n_T = T/k$, and the problem
  // says how long it lasts.
  template <int dim>
  class ProblemData
  {
  public:
    ProblemData(const double                         mu,
                const double                         lambda,
                const double                         F_b,
                const double                         end_time,
                const std::vector<RelaxationTerm>   &relaxation,
                const std::vector<NormalMemoryTerm> &normal_memory)
      : mu(mu)
      , lambda(lambda)
      , friction_bound(F_b)
      , end_time(end_time)
      , law({{0, 1}, {0.02, 1.4}, {0.15, 1.3}})
      , relaxation(relaxation)
      , normal_memory(normal_memory)
    {}

    virtual ~ProblemData() = default;

    // What a problem supplies, in the way deal.II's Function class asks for
    // values: the coarse mesh with its boundary ids, and the two loads as
    // functions of the point and the time. The material, the laws and the
    // kernels are data members, the same for every problem of this program.
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

    // The instantaneous stress $B\varepsilon = 2\mu\varepsilon +
    // \lambda\,\mathrm{tr}(\varepsilon) I$, as in step-1.
    SymmetricTensor<2, dim>
    stress(const SymmetricTensor<2, dim> &eps) const
    {
      return 2 * mu * eps + lambda * trace(eps) * unit_symmetric_tensor<dim>();
    }

    const double                        mu, lambda;
    const double                        friction_bound;
    const double                        end_time;
    const PiecewiseLinearLaw            law;
    const std::vector<RelaxationTerm>   relaxation;
    const std::vector<NormalMemoryTerm> normal_memory;
  };

  // @sect4{The block}

  // step-1's block $[0,4]\times[0,1]$ (clamped on the left, free on the
  // right, on the foundation along its bottom, $\mu = 100$, $\lambda =
  // 150$, $F_b = 0.6$), now with memory: two relaxation terms with
  // $(\mu_m, \lambda_m, \tau_m) = (20, 30, 0.25)$ and $(10, 10, 2)$, and a
  // foundation that remembers with $\kappa(t) = 10 e^{-t/0.5} + 2 e^{-t/2}$.
  // Its top carries step-1's traction, pulling up left of $x = 1$,
  // pressing down right of it and shearing, times a load factor
  // @f[
  //   P(t) = \min(0.25 + t, 1):
  // @f]
  // a quarter of the load at $t = 0$ (so that the first state $u_0$ of
  // the memory is not zero), the full load from $t = 0.75$ on, and held
  // there until $T = 2$. Under the held load a body without memory would
  // not move; this one does, and that is what the block shows. The
  // constructor's flag gives the same block without memory, for the
  // comparison of doc/results.md. tests/tutorial/step_3_block.prm is this
  // problem for the full program.
  class BlockData : public ProblemData<2>
  {
  public:
    explicit BlockData(const bool with_memory = true)
      : ProblemData<2>(/*mu=*/100,
                       /*lambda=*/150,
                       /*F_b=*/0.6,
                       /*end_time=*/2,
                       with_memory ? relaxation_kernel :
                                     std::vector<RelaxationTerm>{},
                       with_memory ? normal_memory_kernel :
                                     std::vector<NormalMemoryTerm>{})
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

    // The load factor $P(t) = \min(0.25 + t, 1)$, static so that main() can
    // write it to history.csv without a problem object.
    static double
    load_factor(const double t)
    {
      return std::min(0.25 + t, 1.);
    }

    Tensor<1, 2>
    traction(const Point<2> &x,
             const Tensor<1, 2> &,
             const types::boundary_id id,
             const double             t) const override
    {
      if (id != 3) // the top; the right side is free
        return Tensor<1, 2>();
      // step-1's traction times the load factor: up left of $x = 1$, down right
      // of it, growing shear, so that the block has all three normal branches.
      const double P = load_factor(t);
      return Tensor<1, 2>({0.5 * P * x[0] / 4, -2.5 * P * (x[0] - 1) / 3});
    }
  };

  // @sect4{A manufactured solution}

  // step-1's exact solution on the unit square (clamped on the left,
  // $\Gamma_3$ the bottom with $\nu = (0,-1)$), now growing in time:
  // @f[
  //   u(x, y, t) = \varphi(t)\,U(x, y),\qquad \varphi(t) = 1 + t,\qquad
  //   U = (1 + y)\,\bigl(g_\tau(x),\; -g_\nu(x)\bigr),
  // @f]
  // @f[
  //   g_\tau(x) = (x - \tfrac34)_+^3,\qquad
  //   g_\nu(x) = 2 (x - \tfrac12)_+^3 - 8 x (\tfrac14 - x)_+^3,
  // @f]
  // for $0 \le t \le T = 1$. On $\Gamma_3$, $u_\nu = \varphi g_\nu$: separation
  // on $(0, \frac14)$, contact without penetration on $[\frac14,
  // \frac12]$, penetration beyond, up to $u_\nu = 0.5$ at $t = 1$, across
  // all three segments of the law; $u_\tau = \varphi g_\tau$: stick on $(0,
  // \frac34]$, slip beyond.
  //
  // Because the time factor is separate, both memory integrals of the
  // exact solution are closed forms. With
  // @f[
  //   I_\tau(t) = \int_0^t e^{-(t-s)/\tau}\varphi(s)\,ds
  //             = \tau t + (1 - \tau)\,\tau\,(1 - e^{-t/\tau}),
  // @f]
  // the stress is $\sigma = C(t)\varepsilon(U)$ with the isotropic tensor
  // of the Lam\'e constants
  // @f[
  //   \mu_C(t) = \varphi(t)\mu + \sum_m \mu_m I_{\tau_m}(t),\qquad
  //   \lambda_C(t) = \varphi(t)\lambda + \sum_m \lambda_m I_{\tau_m}(t),
  // @f]
  // so the data are step-1's with $\mu_C$, $\lambda_C$ for $\mu$,
  // $\lambda$: $f_0 = -\mathrm{Div}\,\sigma$, $f_2 = \sigma\nu$, and on
  // $\Gamma_3$
  // @f[
  //   f_3 = \sigma\nu + (\xi_\nu + N)\nu + \xi_\tau,\qquad
  //   N(x, t) = \int_0^t \kappa(t - s)\,(u_\nu(x, s))_+\,ds
  //           = g_\nu(x)_+ \sum_m \kappa_m I_{\tau_m}(t),
  // @f]
  // the extra traction the laws and the foundation's memory would have to
  // supply for $u$ to be in equilibrium. As in step-1, $\xi_\nu = a/2$
  // and $\xi_\tau = F_b/2$ where the exact $u_\nu$ or $u_\tau$ is zero,
  // strictly inside the intervals, and the points $\frac14, \frac12,
  // \frac34$ where $f_3$ jumps are mesh vertices. The kernels are those
  // of the block.
  class ManufacturedData : public ProblemData<2>
  {
  public:
    ManufacturedData()
      : ProblemData<2>(/*mu=*/100,
                       /*lambda=*/150,
                       /*F_b=*/0.6,
                       /*end_time=*/1,
                       relaxation_kernel,
                       normal_memory_kernel)
    {}

    void
    make_coarse_grid(Triangulation<2> &triangulation) const override
    {
      GridGenerator::subdivided_hyper_rectangle(
        triangulation, {1, 1}, Point<2>(0, 0), Point<2>(1, 1), true);
    }

    // The time factor $\varphi(t) = 1 + t$ of the exact solution: the
    // solution grows linearly in time, so that the memory sums have something
    // to remember from the first load value on, and the convolutions with
    // the exponentials have the closed form below.
    static double
    time_factor(const double t)
    {
      return 1 + t;
    }

    // $I_\tau(t) = \int_0^t e^{-(t-s)/\tau}(1 + s)\,ds$: the convolution of
    // one exponential with $\varphi$. std::expm1 avoids the cancellation
    // of $1 - e^{-t/\tau}$ for small $t/\tau$.
    static double
    convolution(const double tau, const double t)
    {
      return tau * t - (1 - tau) * tau * std::expm1(-t / tau);
    }

    // $z_+^3$ and its first two derivatives; $g_\tau$, $g_\nu$ and theirs.
    static std::array<double, 3>
    cube_plus(const double z)
    {
      const double zp = std::max(z, 0.);
      return {{zp * zp * zp, 3 * zp * zp, 6 * zp}};
    }

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
    exact_value(const Point<2> &p, const double t) const
    {
      const double phi = time_factor(t) * (1 + p[1]);
      return Tensor<1, 2>({phi * g_tau(p[0])[0], -phi * g_nu(p[0])[0]});
    }

    Tensor<2, 2>
    exact_gradient(const Point<2> &p, const double t) const
    {
      const double phi = time_factor(t) * (1 + p[1]);
      const auto   gt = g_tau(p[0]), gn = g_nu(p[0]);
      return Tensor<2, 2>({{phi * gt[1], time_factor(t) * gt[0]},
                           {-phi * gn[1], -time_factor(t) * gn[0]}});
    }

    // $\mu_C(t)$ and $\lambda_C(t)$, the Lam\'e constants of $C(t)$.
    std::pair<double, double>
    effective_lame(const double t) const
    {
      double mu_C = time_factor(t) * mu, lambda_C = time_factor(t) * lambda;
      for (const RelaxationTerm &term : relaxation)
        {
          mu_C += term.mu * convolution(term.tau, t);
          lambda_C += term.lambda * convolution(term.tau, t);
        }
      return {mu_C, lambda_C};
    }

    // $f_0 = -\mu_C\Delta U - (\mu_C + \lambda_C)\nabla\,\mathrm{div}\,U$,
    // with $\Delta U = (1+y)(g_\tau'', -g_\nu'')$ and
    // $\nabla\,\mathrm{div}\,U = ((1+y) g_\tau'' - g_\nu',\; g_\tau')$:
    // step-1's body force with $\mu_C$, $\lambda_C$.
    Tensor<1, 2>
    body_force(const Point<2> &p, const double t) const override
    {
      const auto [mu_C, lambda_C] = effective_lame(t);
      const double y1             = 1 + p[1];
      const auto   gt = g_tau(p[0]), gn = g_nu(p[0]);
      return Tensor<1, 2>(
        {-mu_C * y1 * gt[2] - (mu_C + lambda_C) * (y1 * gt[2] - gn[1]),
         mu_C * y1 * gn[2] - (mu_C + lambda_C) * gt[1]});
    }

    Tensor<1, 2>
    traction(const Point<2>          &p,
             const Tensor<1, 2>      &normal,
             const types::boundary_id id,
             const double             t) const override
    {
      const auto [mu_C, lambda_C] = effective_lame(t);
      const SymmetricTensor<2, 2> eps_U =
        symmetrize(exact_gradient(p, t)) / time_factor(t);
      // The traction of the exact solution is that of the effective material
      // $C(t)$: the instantaneous stress and the convolution of the kernel with
      // the time factor, both applied to the strain of the spatial shape $U$.
      const Tensor<1, 2> sigma_nu =
        (2 * mu_C * eps_U +
         lambda_C * trace(eps_U) * unit_symmetric_tensor<2>()) *
        normal;
      if (id != BoundaryIds::contact)
        return sigma_nu;
      const double u_nu   = exact_value(p, t) * normal;
      const double u_tau  = exact_value(p, t)[0]; // the tangent is e_x
      const double xi_nu  = u_nu < 0  ? 0. :
                            u_nu == 0 ? 0.5 * law.jump() :
                                        law.response(u_nu);
      const double xi_tau = u_tau == 0 ? 0.5 * friction_bound : friction_bound;
      // $N = (g_\nu)_+ \sum_m \kappa_m I_{\tau_m}(t)$: zero where the body
      // never penetrated ($g_\nu \le 0$, separation and the contact without
      // penetration), as the discrete rule gives at nodes that stay out,
      // so that the exact solution's branches are those of step-1.
      double N = 0;
      for (const NormalMemoryTerm &term : normal_memory)
        N += term.kappa * convolution(term.tau, t);
      N *= std::max(g_nu(p[0])[0], 0.);
      return sigma_nu + (xi_nu + N) * normal + Tensor<1, 2>({xi_tau, 0.});
    }
  };

  // @sect3{One contact node}

  // The contact conditions hold node by node (nodal quadrature on
  // $\Gamma_3$), with the branches of step-1:
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

  // Each node $x_i$ of $\Gamma_3$ keeps step-1's data (its degrees of
  // freedom, its weight $m_i = \int_{\Gamma_3}\varphi_i$, its normal
  // $\nu_i$, the constant $c_i$ and its branches) and, new, its memory:
  // one history value $H_{m,i}$ per term of $\kappa$ and the pressure $N_i$
  // they add up to at the current load value (advance_memory()). The
  // foundation's memory lives at the nodes because, with nodal
  // quadrature, the normal displacement it integrates is a nodal value.
  template <int dim>
  struct ContactNode
  {
    // step-1's members (position for the output, the dofs, $m_i$, $\nu_i$,
    // $c_i$ and the branches) and the memory of the foundation at the node:
    // memory_history holds the $H_{m,i}$, one per term of $\kappa$, and
    // memory_pressure their sum $N_i$ at the current load value.
    Point<dim>                               position;
    std::array<types::global_dof_index, dim> dofs;
    double                                   mass = 0;
    Tensor<1, dim>                           normal;
    double                                   c = 0;
    NormalBranch     normal_branch             = NormalBranch::separating;
    TangentialBranch tangential_branch         = TangentialBranch::stick;
    // (a history per node because the foundation's memory, with the nodal
    // quadrature, is a sum of nodal values)
    std::vector<double> memory_history;
    double              memory_pressure = 0;
  };

  // @sect3{The MemoryContactProblem class}

  // step-1's StaticContactProblem with the memory added: the same
  // make_grid(), setup_system(), assemble_system() for $K = B$ and the
  // load $F_n$, solve() and its helpers, output_results(); new are
  // assemble_memory_matrices() and advance_memory(), which turn the
  // history into the known part of each load value's right-hand side.
  // run(n) solves load value $n$; main() calls it for $n = 0, 1, \dots,
  // N$ in this order, since each load value needs the memory of those
  // before it.
  template <int dim>
  class MemoryContactProblem
  {
  public:
    MemoryContactProblem(const ProblemData<dim> &data,
                         const unsigned int      n_refinements,
                         const double            time_step);

    // Solve load value @p n at $t_n = n k$, after the memory of the load
    // values $0, \dots, n-1$; starts from the solution of load value
    // $n-1$.
    void
    run(const unsigned int n);

    void
    output_results(const unsigned int n) const;

    // $\|u(t_n) - u_n\|_{L^2}$ and $\|\varepsilon(u(t_n) - u_n)\|_{L^2}$ at
    // the current load value.
    // Exact is any class with exact_value() and exact_gradient(). A template
    // rather than virtual functions of ProblemData, because only the
    // manufactured solution has an exact solution to compare with.
    template <class Exact>
    std::pair<double, double>
    compute_errors(const Exact &exact) const;

    // The same two norms of $u_n - v_m$, the difference to the current
    // solution of @p other, a problem on the same mesh (for the order in
    // $k$ alone).
    std::pair<double, double>
    difference(const MemoryContactProblem<dim> &other) const;

    unsigned int
    n_dofs() const
    {
      return dof_handler.n_dofs();
    }

    unsigned int
    n_load_values() const
    {
      return 1 +
             static_cast<unsigned int>(std::llround(data.end_time / time_step));
    }

    // step-1's constant $\lambda_1$ of the smallness condition: the memory
    // changes the right-hand side of each load value, not its energy's
    // quadratic part, so the condition $\alpha_\nu < \lambda_1$ is step-1's.
    double
    smallness_constant() const;

    // The normal displacement $u_\nu$ and the memory pressure $N$ at the
    // contact node farthest to the right (for the block: its free end), for
    // the file history.csv.
    std::pair<double, double>
    right_end() const;

    // The Newton iterations of the last run().
    unsigned int newton_iterations = 0;

  private:
    void
    // The steps of the constructor: the mesh, the degrees of freedom with the
    // matrices and the contact nodes, and the two matrices of the memory.
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
    assemble_memory_matrices();
    void
    // What each load value does before it solves: turn the solutions of the
    // load values before into the known part $F_n - \ell_n$ of its right-hand
    // side.
    advance_memory();
    void
    solve();

    // step-1's pieces of solve(), unchanged: the state of a node, the
    // branches, the nonsmooth residual, the Newton system and the energy
    // $J_n$ of the line search.
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
    double
    energy(const Vector<double> &u) const;

    // The data, the time step and the current load value; then step-1's mesh,
    // element and numbering.
    const ProblemData<dim> &data;
    const double            time_step; // $k$
    double                  time = 0;  // $t_n$
    // The time step $k$ and the current load value: run() checks that the
    // load values come in order, since each needs the memory of those before.
    int load_step = -1; // $n$, -1 before the first

    // The finite element machinery of step-8: a mesh, $Q_1$ in each of the
    // $d$ components, and the numbering of the degrees of freedom.
    Triangulation<dim> triangulation;
    FESystem<dim>      fe;
    DoFHandler<dim>    dof_handler;

    // step-1's two sets of constraints: the clamped boundary alone, for $K$,
    // $F_n$ and the memory matrices, and the clamped boundary with the held
    // conditions of the current branches, for one Newton step.
    AffineConstraints<double> clamped_constraints;
    AffineConstraints<double> newton_constraints;

    // $K$, the two memory matrices $A_\mu$, $A_\lambda$ and the matrix of
    // one Newton step share one sparsity pattern.
    SparsityPattern      sparsity_pattern;
    SparseMatrix<double> stiffness_matrix;
    SparseMatrix<double> shear_matrix;      // $A_\mu$
    SparseMatrix<double> volumetric_matrix; // $A_\lambda$
    SparseMatrix<double> newton_matrix;

    Vector<double> solution; // $u_n$, the last load value's until solved
    // $\ell_n = F_n - (M_n, \varepsilon(\cdot)) - \sum_i m_i N_{n,i}\nu_i$: the
    // load minus the memory, the linear part of the energy of load value $n$
    Vector<double> load;
    // $(M_n, \varepsilon(\cdot)) + \sum_i m_i N_{n,i}\nu_i$, the memory's part
    // of $F_n - \ell_n$
    Vector<double> memory_load;
    Vector<double> newton_rhs;

    // The stress's history: one vector $h_m$ per relaxation term.
    std::vector<Vector<double>> stress_history;

    std::vector<ContactNode<dim>> contact_nodes;
  };

  // The constructor builds the mesh, the system and the memory matrices;
  // the solution and every history start at zero.
  template <int dim>
  MemoryContactProblem<dim>::MemoryContactProblem(
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
  }

  // @sect4{MemoryContactProblem::make_grid}

  // As in step-1: the coarse mesh from the data, refined globally.
  template <int dim>
  void
  MemoryContactProblem<dim>::make_grid(const unsigned int n_refinements)
  {
    data.make_coarse_grid(triangulation);
    triangulation.refine_global(n_refinements);
  }

  // @sect4{MemoryContactProblem::setup_system}

  // step-1's setup, plus the memory: the two matrices of the stress's
  // memory and the history vectors, all zero before the first load value.
  template <int dim>
  void
  MemoryContactProblem<dim>::setup_system()
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
    // which are coupled anyway). The two memory matrices couple the same
    // degrees of freedom as $K$ and share the pattern.
    DynamicSparsityPattern dsp(dof_handler.n_dofs());
    DoFTools::make_sparsity_pattern(dof_handler, dsp);
    sparsity_pattern.copy_from(dsp);
    stiffness_matrix.reinit(sparsity_pattern);
    shear_matrix.reinit(sparsity_pattern);
    volumetric_matrix.reinit(sparsity_pattern);
    newton_matrix.reinit(sparsity_pattern);

    solution.reinit(dof_handler.n_dofs());
    load.reinit(dof_handler.n_dofs());
    memory_load.reinit(dof_handler.n_dofs());
    newton_rhs.reinit(dof_handler.n_dofs());
    // One history vector per relaxation term, of the layout of $u$: the
    // recursion of advance_memory() adds $k u_{n-1}$ to it, so it must
    // share the numbering of the degrees of freedom.
    stress_history.assign(data.relaxation.size(),
                          Vector<double>(dof_handler.n_dofs()));

    assemble_system(clamped_constraints, stiffness_matrix, load);
    assemble_memory_matrices();
    setup_contact_nodes();
  }

  // @sect4{The contact nodes}

  // step-1's contact nodes: the weights $m_i$ and normals $\nu_i$
  // assembled like a right-hand side, the nodes of $\Gamma_1$ left out, and
  // $c_i$ the mean diagonal entry of $K$ at the node over $m_i$ with the
  // floor of twice the law's steepest rise (step-1 says why). Each node
  // also gets its foundation history, one zero per term of $\kappa$.
  template <int dim>
  void
  MemoryContactProblem<dim>::setup_contact_nodes()
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
            // at the node's first component and the normal's components at its
            // components.
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

    // step-1's second pass: every vertex of $\Gamma_3$ once (the flags), the
    // clamped corner left out (a degree of freedom carries one constraint
    // only), and the memory of each node sized by the number of terms of
    // $\kappa$.
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
              node.memory_history.assign(data.normal_memory.size(), 0.);
              contact_nodes.push_back(node);
            }
  }

  // @sect4{MemoryContactProblem::assemble_system}

  // step-1's assembly, unchanged: the stiffness $K$ of $B$ (Gauss, 2
  // points per direction) and the load $F_n$ of $f_0$ and the tractions
  // at $t_n$ (3 points per direction), condensed with the given
  // constraints.
  template <int dim>
  void
  MemoryContactProblem<dim>::assemble_system(
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

    // step-1's assembly: the constraints are applied while assembling, so the
    // matrix and the vector come out condensed. The load is that of $t_n$;
    // the memory is not a cell integral here, advance_memory() subtracts it
    // afterwards.
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

  // @sect3{The memory}

  // @sect4{MemoryContactProblem::assemble_memory_matrices}

  // The memory term of the stress enters load value $n$ as the functional
  // $(M_n, \varepsilon(v))$ with the discrete memory stress
  // (the introduction, "The rule")
  // @f[
  //   M_n = k\sum_{j=0}^{n-1} \mathcal R(t_n - t_j)\,\varepsilon(u_j).
  // @f]
  // $\mathcal R$ does not depend on $x$, so the sum can be taken of the
  // displacements instead of the strains: with $\mathcal R(t)\varepsilon =
  // 2\mu_R(t)\varepsilon + \lambda_R(t)\,\mathrm{tr}(\varepsilon) I$,
  // @f[
  //   (M_n, \varepsilon(v)) = a_\mu(S_\mu, v) + a_\lambda(S_\lambda, v),\qquad
  //   a_\mu(u, v) = 2(\varepsilon(u), \varepsilon(v)),\quad
  //   a_\lambda(u, v) = (\mathrm{div}\,u, \mathrm{div}\,v),
  // @f]
  // @f[
  //   S_\mu = k\sum_{j<n}\mu_R(t_n - t_j)\,u_j,\qquad
  //   S_\lambda = k\sum_{j<n}\lambda_R(t_n - t_j)\,u_j.
  // @f]
  // The two bilinear forms are fixed matrices $A_\mu$, $A_\lambda$,
  // assembled here once (condensed with the clamped constraints, like
  // $K$); each load value then costs two matrix-vector products, and no
  // history is kept at the quadrature points. Gauss with 2 points per
  // direction is exact for them on rectangles, as for $K$.
  template <int dim>
  void
  MemoryContactProblem<dim>::assemble_memory_matrices()
  {
    const FEValuesExtractors::Vector     displacement(0);
    const unsigned int                   n = fe.n_dofs_per_cell();
    FEValues<dim>                        fe_values(fe,
                            QGauss<dim>(2),
                            update_gradients | update_JxW_values);
    FullMatrix<double>                   shear(n, n), volumetric(n, n);
    std::vector<types::global_dof_index> dofs(n);
    // The two forms are integrated cell by cell like $K$: $a_\mu$ is the
    // shear part $2\,\varepsilon(\varphi_i):\varepsilon(\varphi_j)$ and
    // $a_\lambda$ the volumetric part $\mathrm{div}\,\varphi_i\,\mathrm{div}
    // \,\varphi_j$, so that $K = \mu A_\mu + \lambda A_\lambda$ and any
    // isotropic kernel is a combination of the two.
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        fe_values.reinit(cell);
        shear      = 0;
        volumetric = 0;
        for (const unsigned int q : fe_values.quadrature_point_indices())
          for (unsigned int i = 0; i < n; ++i)
            for (unsigned int j = 0; j < n; ++j)
              {
                shear(i, j) +=
                  2 *
                  (fe_values[displacement].symmetric_gradient(i, q) *
                   fe_values[displacement].symmetric_gradient(j, q)) *
                  fe_values.JxW(q);
                volumetric(i, j) += fe_values[displacement].divergence(i, q) *
                                    fe_values[displacement].divergence(j, q) *
                                    fe_values.JxW(q);
              }
        cell->get_dof_indices(dofs);
        clamped_constraints.distribute_local_to_global(shear,
                                                       dofs,
                                                       shear_matrix);
        clamped_constraints.distribute_local_to_global(volumetric,
                                                       dofs,
                                                       volumetric_matrix);
      }
  }

  // @sect4{MemoryContactProblem::advance_memory}

  // Called before load value $n \ge 1$ is solved, while the solution still
  // holds $u_{n-1}$. A direct evaluation of the sums above would keep every
  // past $u_j$ and cost $n$ vector operations at load value $n$: a run of
  // $n_T$ load values would cost $O(n_T^2)$ and store $n_T$ vectors. For a
  // Prony series each exponential has a history of one vector,
  // @f[
  //   h_{m,n} = k\sum_{j<n} e^{-(t_n - t_j)/\tau_m}\,u_j,
  // @f]
  // and since $e^{-(t_n - t_j)/\tau} = e^{-k/\tau} e^{-(t_{n-1} -
  // t_j)/\tau}$, the sum obeys the recursion
  // @f[
  //   h_{m,n} = e^{-k/\tau_m}\bigl(h_{m,n-1} + k\,u_{n-1}\bigr),\qquad
  //   h_{m,0} = 0,
  // @f]
  // which is the same sum, only rounded differently: one update per term
  // and load value, whatever $n$. Then $S_\mu = \sum_m \mu_m h_{m,n}$,
  // $S_\lambda = \sum_m\lambda_m h_{m,n}$.
  //
  // The foundation's memory is the same rule at each contact node,
  // @f[
  //   N_{n,i} = k\sum_{j<n} \kappa(t_n - t_j)\,(u_{\nu,j}(x_i))_+
  //           = \sum_m \kappa_m H_{m,n,i},\qquad
  //   H_{m,n,i} = e^{-k/\tau_m}\bigl(H_{m,n-1,i} + k\,(u_{\nu,n-1}(x_i))_+
  //   \bigr),
  // @f]
  // with the positive part: the foundation remembers how deep and how long
  // it was penetrated, and a node that separated keeps the pressure of its
  // past until it decays. $N_{n,i}$ is a pressure known before the solve;
  // with the nodal quadrature its force is $m_i N_{n,i}\nu_i$.
  //
  // Both memories together give the right-hand side of load value $n$,
  // @f[
  //   \ell_n = F_n - A_\mu S_\mu - A_\lambda S_\lambda
  //         - \sum_i m_i N_{n,i}\,\nu_i,
  // @f]
  // and nothing else changes: $K$, the laws, the branches, the Newton
  // method. Each load value is step-1's problem with another load.
  template <int dim>
  void
  MemoryContactProblem<dim>::advance_memory()
  {
    const double   k = time_step;
    Vector<double> S_mu(dof_handler.n_dofs()), S_lambda(dof_handler.n_dofs());
    for (unsigned int m = 0; m < data.relaxation.size(); ++m)
      {
        Vector<double> &h = stress_history[m];
        // $h \leftarrow e^{-k/\tau_m}(h + k u_{n-1})$: first the new
        // state joins the sum, then the whole sum decays by one step, so
        // that $u_{n-1}$ enters with the weight $k e^{-k/\tau_m}$, the
        // kernel at $t_n - t_{n-1} = k$ (never at 0).
        h.add(k, solution);
        h *= decay(data.relaxation[m].tau, k);
        S_mu.add(data.relaxation[m].mu, h);
        S_lambda.add(data.relaxation[m].lambda, h);
      }

    // The memory stress as a nodal force vector: $A_\mu S_\mu + A_\lambda
    // S_\lambda$, two products with the fixed matrices. memory_load collects
    // it together with the foundation's part below.
    Vector<double> product(dof_handler.n_dofs());
    shear_matrix.vmult(memory_load, S_mu);
    volumetric_matrix.vmult(product, S_lambda);
    memory_load += product;

    // The foundation's memory, node by node, from the normal displacement of
    // the last load value: the solution still holds $u_{n-1}$ here.
    for (ContactNode<dim> &node : contact_nodes)
      {
        double u_nu = 0;
        for (unsigned int c = 0; c < dim; ++c)
          u_nu += solution(node.dofs[c]) * node.normal[c];
        node.memory_pressure = 0;
        for (unsigned int m = 0; m < data.normal_memory.size(); ++m)
          {
            // the same recursion with $(u_{\nu,n-1})_+$: a separating node
            // adds nothing, but its history keeps decaying
            double &H = node.memory_history[m];
            H         = (H + k * std::max(u_nu, 0.)) *
                decay(data.normal_memory[m].tau, k);
            node.memory_pressure += data.normal_memory[m].kappa * H;
          }
        for (unsigned int c = 0; c < dim; ++c)
          memory_load(node.dofs[c]) +=
            node.mass * node.memory_pressure * node.normal[c];
      }
    // load held $F_n$ (run() assembled it just before); now it is $\ell_n$, the
    // only change the memory makes to the problem of load value $n$.
    load -= memory_load;
  }

  // @sect3{The active-set Newton method}

  // This part is step-1's, line for line but for one addition in
  // assemble_newton_system() (the memory's part of $\ell_n$ in the Newton
  // right-hand side): the memory is inside the vector load $= \ell_n$, and
  // so inside the residual $R = K u - \ell_n$ and the energy. What the solver
  // calls the nodal contact force, $G_i = -R_i$, is therefore the force of the
  // *laws*: the part of the contact traction that the foundation's memory does
  // not already supply.

  // @sect4{The state of a node}

  // From $G_i = -R_i$ the multipliers of the convex parts of the laws,
  // @f[
  //   s_\nu = G_i\cdot\nu/m_i - p(u_\nu),\qquad
  //   s_\tau = G_{i,\tau}/m_i,
  // @f]
  // and the complementarity functions
  // @f[
  //   C_\nu = s_\nu - P_{[0,a]}(s_\nu + c\,u_\nu),\qquad
  //   C_\tau = s_\tau - P_{|\cdot|\le F_b}(s_\tau + c\,u_\tau),
  // @f]
  // which vanish exactly at a solution of the nodal contact conditions
  // (step-1's introduction shows why).
  template <int dim>
  struct MemoryContactProblem<dim>::NodeState
  {
    double         u_nu;
    Tensor<1, dim> u_tau;
    double         s_nu;
    Tensor<1, dim> s_tau;
    double         q_nu;  // s_nu + c u_nu
    Tensor<1, dim> q_tau; // s_tau + c u_tau
  };

  template <int dim>
  typename MemoryContactProblem<dim>::NodeState
  MemoryContactProblem<dim>::node_state(const ContactNode<dim> &node,
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
    // the law's response $\xi$ and the friction bound $F_b$. The memory
    // pressure $N_i$ is not in it: $\ell_n$ holds $-m_i N_i\nu_i$, so the
    // residual is what the laws must add to the memory's pressure.
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

  // As in step-1: $q_\nu < 0$ separating, $0 \le q_\nu \le a$ stick,
  // $q_\nu > a$ penetrating; $|q_\tau| \le F_b$ stick, otherwise slip.
  // Returns the number of nodes whose branches changed.
  template <int dim>
  unsigned int
  MemoryContactProblem<dim>::update_active_set(const Vector<double> &residual)
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

  // The nonsmooth residual: equilibrium on the free degrees of freedom away
  // from $\Gamma_3$, the $m_i$-weighted complementarity functions at the
  // contact nodes.
  template <int dim>
  double
  MemoryContactProblem<dim>::nonsmooth_residual(
    const Vector<double> &residual) const
  {
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

  // step-1's Newton step: on the current branches, minimise the quadratic
  // model $\frac12 x\cdot(K + L)x - g\cdot x$ over the displacements that
  // satisfy the held conditions ($x_i\cdot\nu_i = 0$ at normal stick,
  // $x_i - (x_i\cdot\nu_i)\nu_i = 0$ at tangential stick), eliminated by
  // AffineConstraints as in step-41. The free branches add the nodal force
  // $f_i$ of the laws and its derivative $L_i$, $g_i = \ell_{n,i} + L_i u_i -
  // f_i$: penetrating $f_i = m_i(a + p(u_\nu))\nu$, $L_i = m_i p'(u_\nu)
  // \nu\otimes\nu$; slip $f_i = m_i F_b d + T_i u_\tau$, $L_i = T_i = m_i
  // F_b c/(|q_\tau| - F_b)(I - \nu\otimes\nu - d\otimes d)$, $d =
  // q_\tau/|q_\tau|$, zero in 2D, the denominator kept above
  // $|q_\tau|/100$ (step-1 derives both).
  template <int dim>
  void
  MemoryContactProblem<dim>::assemble_newton_system(
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
        // Three cases: both directions held fix the node; the normal alone ties
        // component $k$ to the others, so that the displacement stays in the
        // tangent plane; the tangent alone keeps the node on its normal line.
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

    // The cell terms, $K$ and $F_n$, condensed with the Newton
    // constraints; the memory part of $\ell_n$ is a vector, not a cell
    // integral, and is condensed by the same constraints, so that
    // newton_rhs is the condensed $\ell_n$.
    assemble_system(newton_constraints, newton_matrix, newton_rhs);
    Vector<double> memory_part(memory_load);
    newton_constraints.condense(memory_part);
    newton_rhs -= memory_part;

    // Then step-1's nodal terms of the free branches: the law's force at the
    // iterate and its derivative, added through the same constraints. The
    // memory pressure is not among them: it is a known force of this load
    // value, already inside $\ell_n$.
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
        // (The tangential part has no remainder: Tresca's bound does not depend
        // on the displacement, and the memory acts on the normal direction
        // only.)
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

  // $J_n(u) = \frac12 u\cdot K u - \ell_n\cdot u + \sum_i m_i
  // [j_\nu(u_{i,\nu}) + F_b |u_{i,\tau}|]$, the function the line search
  // decreases: step-1's energy with $\ell_n$ for $F_n$. The memory adds a
  // linear term, so $J_n$ is convex exactly when step-1's is.
  template <int dim>
  double
  MemoryContactProblem<dim>::energy(const Vector<double> &u) const
  {
    // matrix_norm_square() is $u\cdot Ku$, and load is $\ell_n$, the load minus
    // the memory: the memory enters the energy as a linear term. The clamped
    // rows of $K$ are decoupled and $u$ vanishes there, so they add nothing.
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

  // @sect4{MemoryContactProblem::solve}

  // step-1's iteration: residual, branches, stop when no branch changed
  // and the nonsmooth residual is below $10^{-11}|\ell_n|$ (or a hundredth
  // of that whatever the branches do: a node within round-off of a switch
  // may flip without changing the solution), else the Newton step by
  // UMFPACK and the line search.
  template <int dim>
  void
  MemoryContactProblem<dim>::solve()
  {
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
        // iteration. On the meshes of this program UMFPACK does this quickly,
        // and a direct solver keeps the iteration count a property of the
        // nonsmooth method alone, with no inner tolerance to tune.
        SparseDirectUMFPACK direct_solver;
        direct_solver.initialize(newton_matrix);
        Vector<double> trial(newton_rhs);
        direct_solver.solve(trial);
        newton_constraints.distribute(trial);

        // The line search on $J_n$, the rule of step-1 and step-2: the
        // first of $\theta = 1, \frac12, \dots, 2^{-10}$ whose step $u +
        // \theta d$ does not raise $J_n$ beyond round-off (a relative
        // $10^{-12}$). A full Newton step can raise $J_n$ because $j_\nu$
        // is not convex: the quadratic model of one branch is wrong beyond
        // its segment of the law. The fallback: if no step length lowers
        // $J_n$, the direction is not one of descent (which happens only
        // while the branches are still wrong), and the full step is taken,
        // since a tiny step would leave the branches as they are and stall
        // the iteration, while the full step moves to the branches the next
        // update_active_set() corrects.
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

  // @sect4{MemoryContactProblem::run}

  // One load value: the load $F_n$ at $t_n$, then (from $n = 1$ on) the
  // memory of the load values before, then the solve. Load value 0 has no
  // memory ($M_0 = 0$, $N_0 = 0$): its solution is the first state $u_0$
  // of the sums, the problem without memory at $t = 0$. The history must
  // be read in order, which the assertion checks.
  template <int dim>
  void
  MemoryContactProblem<dim>::run(const unsigned int n)
  {
    AssertThrow(static_cast<int>(n) == load_step + 1,
                ExcMessage("The load values must be solved in order."));
    load_step = n;
    time      = n * time_step;
    // One function computes $K$ and $F_n$ (as in step-1): $K$ comes out
    // the same at every load value, the load is that of $t_n$, and
    // advance_memory() then turns $F_n$ into $\ell_n$.
    assemble_system(clamped_constraints, stiffness_matrix, load);
    if (n > 0)
      advance_memory();
    solve();
  }

  // @sect4{MemoryContactProblem::smallness_constant}

  // step-1's power iteration for $\lambda_1$, the smallest eigenvalue of
  // the pencil $(K, M_\nu)$ with $M_\nu = \sum_i m_i\nu_i\otimes\nu_i$: the
  // largest eigenvalue $1/\lambda_1$ of $K^{-1}M_\nu$, one UMFPACK solve per
  // iteration, until the Rayleigh quotient changes by less than
  // $10^{-12}$ relative. The memory does not enter: it changes $\ell_n$, not
  // the quadratic part of $J_n$.
  template <int dim>
  double
  MemoryContactProblem<dim>::smallness_constant() const
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

  // @sect4{MemoryContactProblem::right_end}

  template <int dim>
  std::pair<double, double>
  MemoryContactProblem<dim>::right_end() const
  {
    // The block's free end is its rightmost contact node; the clamped
    // corner at the left is not a contact node.
    const auto node = std::max_element(contact_nodes.begin(),
                                       contact_nodes.end(),
                                       [](const ContactNode<dim> &x,
                                          const ContactNode<dim> &y) {
                                         return x.position[0] < y.position[0];
                                       });
    double     u_nu = 0;
    for (unsigned int c = 0; c < dim; ++c)
      u_nu += solution(node->dofs[c]) * node->normal[c];
    return {u_nu, node->memory_pressure};
  }

  // @sect4{MemoryContactProblem::output_results}

  // step-1's four files per load value, numbered by $n$: solution-NN.vtu,
  // contact-NN.csv, displacement-NN.txt (the nodal displacement in full
  // precision, which tests/tutorial/step_3_vs_hemicontact.sh compares with
  // the full program's) and body-NN.csv (the picture of the body). The contact
  // table gains the column N, the foundation's memory pressure $N_{n,i}$, and
  // its column minus_sigma_nu is the whole normal traction $s + p(u_\nu) + N$:
  // the laws' part, read from the residual, plus the memory's. The terminal
  // line adds the largest penetration and the largest $N$.
  template <int dim>
  void
  MemoryContactProblem<dim>::output_results(const unsigned int n) const
  {
    char suffix[16];
    std::snprintf(suffix, sizeof(suffix), "%02u", n);

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
    std::ofstream vtu(std::string("solution-") + suffix + ".vtu");
    data_out.write_vtu(vtu);

    // The contact quantities come from the residual at the solution, as in
    // solve(); the residual is $Ku - \ell_n$ here, so the traction read from it
    // is the laws' part, and we add the memory pressure $N$ for the whole
    // normal traction.
    Vector<double> residual(dof_handler.n_dofs());
    stiffness_matrix.vmult(residual, solution);
    residual -= load;
    std::ofstream csv(std::string("contact-") + suffix + ".csv");
    csv << "x,u_nu,u_tau,minus_sigma_nu,sigma_tau,N,normal_branch,"
           "tangential_branch\n";
    // The branch counts, the largest penetration and the largest memory
    // pressure over the nodes, for the terminal line.
    unsigned int n_normal[3] = {0, 0, 0}, n_tangential[2] = {0, 0};
    double       largest_u_nu = 0, largest_N = 0;
    for (const ContactNode<dim> &node : contact_nodes)
      {
        const NodeState m = node_state(node, residual);
        csv << std::setprecision(10) << node.position[0] << ',' << m.u_nu << ','
            << m.u_tau[0] << ','
            << m.s_nu + data.law.remainder(m.u_nu) + node.memory_pressure << ','
            << m.s_tau[0] << ',' << node.memory_pressure << ','
            << static_cast<int>(node.normal_branch) << ','
            << static_cast<int>(node.tangential_branch) << '\n';
        ++n_normal[static_cast<int>(node.normal_branch)];
        ++n_tangential[static_cast<int>(node.tangential_branch)];
        largest_u_nu = std::max(largest_u_nu, m.u_nu);
        largest_N    = std::max(largest_N, node.memory_pressure);
      }

    // The nodal file uses printf's %.17g, which prints a double so that it
    // reads back bit for bit: the comparison with the full program at
    // $10^{-10}$ must not be limited by the output.
    std::FILE *nodal =
      std::fopen((std::string("displacement-") + suffix + ".txt").c_str(), "w");
    AssertThrow(nodal != nullptr, ExcIO());
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

    // The picture of the body (doc/plot_body.py): each cell's vertices in
    // counterclockwise order (0, 1, 3, 2 in deal.II's lexicographic
    // numbering of a quadrilateral's vertices) with the displacement there
    // and, at a contact node, its two branches (-1 elsewhere), as step-1
    // writes them to body-NN.csv.
    std::map<types::global_dof_index, const ContactNode<dim> *> node_at;
    for (const ContactNode<dim> &node : contact_nodes)
      node_at[node.dofs[0]] = &node;
    std::ofstream body(std::string("body-") + suffix + ".csv");
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
            body << ',' << static_cast<int>(node->second->normal_branch) << ','
                 << static_cast<int>(node->second->tangential_branch) << '\n';
        }

    // The line the results page shows for every load value; printf keeps its
    // columns aligned, which makes the evolution readable down the page.
    std::printf("t = %.3f: %u Newton, normal sep/stick/pen %u/%u/%u, "
                "tangential stick/slip %u/%u, max u_nu %.4f, max N %.4f\n",
                time,
                newton_iterations,
                n_normal[0],
                n_normal[1],
                n_normal[2],
                n_tangential[0],
                n_tangential[1],
                largest_u_nu,
                largest_N);
  }

  // @sect4{MemoryContactProblem::compute_errors}

  // step-1's errors at the current load value, with a 4-point Gauss rule
  // per direction (the exact solution is a cubic in $x$).
  template <int dim>
  template <class Exact>
  std::pair<double, double>
  MemoryContactProblem<dim>::compute_errors(const Exact &exact) const
  {
    // Four Gauss points per direction: two more than the assembly, since the
    // exact solution is a cubic in $x$ and its quadrature error must stay
    // below the discretisation error on the finest mesh.
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
        fe_values.reinit(cell);
        fe_values[displacement].get_function_values(solution, values);
        fe_values[displacement].get_function_symmetric_gradients(solution,
                                                                 strains);
        for (const unsigned int q : fe_values.quadrature_point_indices())
          {
            const Point<dim> &x = fe_values.quadrature_point(q);
            E_H2 += (exact.exact_value(x, time) - values[q]).norm_square() *
                    fe_values.JxW(q);
            const SymmetricTensor<2, dim> e =
              symmetrize(exact.exact_gradient(x, time)) - strains[q];
            E_V2 += scalar_product(e, e) * fe_values.JxW(q);
          }
      }
    return {std::sqrt(E_H2), std::sqrt(E_V2)};
  }

  // @sect4{MemoryContactProblem::difference}

  // The norms of compute_errors() for the difference of two discrete
  // solutions on the same mesh: both problems number their degrees of
  // freedom alike (the same mesh, the same distribute_dofs()), so the
  // difference of the vectors is the difference of the fields.
  template <int dim>
  std::pair<double, double>
  MemoryContactProblem<dim>::difference(
    const MemoryContactProblem<dim> &other) const
  {
    // The same number of unknowns is a necessary condition for the same mesh,
    // and the cheap one to check; the convergence study builds both problems
    // from the same coarse mesh and number of refinements.
    AssertThrow(other.n_dofs() == n_dofs(),
                ExcMessage("The two problems must share their mesh."));
    Vector<double> d(solution);
    d -= other.solution;
    const QGauss<dim> quadrature(2);
    FEValues<dim>     fe_values(
      fe, quadrature, update_values | update_gradients | update_JxW_values);
    const FEValuesExtractors::Vector     displacement(0);
    std::vector<Tensor<1, dim>>          values(quadrature.size());
    std::vector<SymmetricTensor<2, dim>> strains(quadrature.size());
    double                               D_H2 = 0, D_V2 = 0;
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        // The difference is a discrete field, so the 2-point rule integrates
        // its square exactly on these rectangles.
        fe_values.reinit(cell);
        fe_values[displacement].get_function_values(d, values);
        fe_values[displacement].get_function_symmetric_gradients(d, strains);
        for (const unsigned int q : fe_values.quadrature_point_indices())
          {
            D_H2 += values[q].norm_square() * fe_values.JxW(q);
            D_V2 += scalar_product(strains[q], strains[q]) * fe_values.JxW(q);
          }
      }
    return {std::sqrt(D_H2), std::sqrt(D_V2)};
  }
} // namespace Step3

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
    "usage: step-3                        the block, then 4 levels of the\n"
    "                                     manufactured solution\n"
    "       step-3 block                  the block only\n"
    "       step-3 convergence [LEVELS]   LEVELS levels (1 to 5, default 4)\n"
    "                                     of the manufactured solution\n"
    "       step-3 --help                 this text\n"
    "exit codes: 0 done, 1 the computation failed, 2 a bad argument";

  const std::map<std::string, std::size_t> modes = {{"", 0},
                                                    {"block", 1},
                                                    {"convergence", 2},
                                                    {"--help", 1}};

  // Each level halves $h$ and $k$ together: four times the unknowns, twice the
  // load values, and with UMFPACK about ten times the time of the level
  // before. Five levels (8,450 unknowns, 65 load values) took 42 s and 0.19
  // GB; a sixth would take about ten times as long, so we refuse it.
  const unsigned int max_levels = 5;
} // namespace CommandLine

// @sect3{The main function}

// The block with memory at the load values $t_n = n/8$, $n = 0, \dots,
// 16$, each solved after the memory of those before it; the same block
// without memory beside it, for the file history.csv (the right end's
// $u_\nu$ with and without memory, and its $N$). Then the manufactured
// solution on the meshes $h = 1/4, 1/8, \dots$ with $k = h$ (the memory
// rule is first order in $k$, the mesh in $h$: refined together, the
// energy error should fall like $h$), the errors being the largest over
// the load values, with their observed orders in a ConvergenceTable.
int
main(int argc, char **argv)
{
  using namespace Step3;
  const std::vector<std::string> arguments(argv + 1, argv + argc);
  const std::string              mode = arguments.empty() ? "" : arguments[0];
  // The default of the convergence study: four levels, $h = k = 1/4$ to
  // $1/32$, a few seconds.
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
      std::cerr << "step-3: cannot run";
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
  const unsigned int n_levels        = std::stoul(levels);
  const bool         run_block       = mode.empty() || mode == "block";
  const bool         run_convergence = mode.empty() || mode == "convergence";

  try
    {
      if (run_block)
        {
          // The block's time step $k = 1/8$: 17 load values up to $T = 2$,
          // enough to follow the rise of the load and the slow decay of the
          // memory.
          const double            k = 0.125;
          const BlockData         block, elastic_block(/*with_memory=*/false);
          MemoryContactProblem<2> problem(block, 3, k),
            elastic(elastic_block, 3, k);
          const double lambda_1 = problem.smallness_constant();
          std::cout << "The block with memory, 3 global refinements, k = " << k
                    << ":\n  " << problem.n_dofs()
                    << " dofs, alpha_nu = " << block.law.alpha
                    << ", lambda_1 = " << lambda_1
                    << (block.law.alpha < lambda_1 ?
                          " (alpha_nu < lambda_1: one solution)" :
                          " (alpha_nu >= lambda_1: maybe several solutions)")
                    << std::endl;
          // The block without memory runs beside the block with memory, one
          // load value each in turn; its load values are independent
          // problems (empty kernels, no memory), and only its free end is
          // written, to history.csv, for the figure of doc/results.md.
          std::ofstream history("history.csv");
          AssertThrow(history, ExcIO());
          history << "t,load_factor,u_nu_memory,N_memory,u_nu_elastic\n";
          for (unsigned int n = 0; n < problem.n_load_values(); ++n)
            {
              // Both blocks solve load value $n$; only the one with memory
              // writes its files and its line, the other gives history.csv its
              // column without memory.
              problem.run(n);
              elastic.run(n);
              std::cout << "  ";
              problem.output_results(n);
              const auto [u_nu, N] = problem.right_end();
              history << std::setprecision(10) << n * k << ','
                      << BlockData::load_factor(n * k) << ',' << u_nu << ','
                      << N << ',' << elastic.right_end().first << '\n';
            }
        }

      if (run_convergence)
        {
          std::cout << (run_block ? "\n" : "")
                    << "The manufactured solution, k = h:" << std::endl;
          // The manufactured solution on successively refined meshes, with $k =
          // h$, a new problem per level: each runs the whole history $t = 0,
          // \dots, 1$ and records the largest errors over the load values.
          const ManufacturedData manufactured;
          ConvergenceTable       table;
          for (unsigned int level = 0; level < n_levels; ++level)
            {
              const unsigned int refinements = 2 + level;
              // $k = h$: the memory rule is of first order in $k$, the mesh in
              // $h$ (in the energy norm), so refining both together should give
              // first order in $E_V$.
              const double            k = 1. / (1u << refinements);
              MemoryContactProblem<2> problem(manufactured, refinements, k);
              double                  E_H = 0, E_V = 0;
              unsigned int            newton = 0;
              for (unsigned int n = 0; n < problem.n_load_values(); ++n)
                {
                  problem.run(n);
                  newton += problem.newton_iterations;
                  // the largest errors over the load values, $t_0$ included:
                  // $u_0$ is the first state of every memory sum, and its
                  // error is carried into all the later load values
                  const auto [e_H, e_V] = problem.compute_errors(manufactured);
                  E_H                   = std::max(E_H, e_H);
                  E_V                   = std::max(E_V, e_V);
                }
              // One row per level: the mesh, the number of load values, the
              // mean Newton iterations per load value, and the largest errors
              // over the history.
              table.add_value("1/h", 1u << refinements);
              table.add_value("dofs", problem.n_dofs());
              table.add_value("loads", problem.n_load_values());
              table.add_value("Newton",
                              double(newton) / problem.n_load_values());
              table.set_precision("Newton", 2);
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

          // The order in $k$ alone: on one mesh ($h = 1/16$) the solution at
          // $T = 1$ for $k = 1/4, 1/8, \dots$, each compared with the next.
          // The spatial error is the same in both and cancels: what is left
          // is the error of the memory rule, $D(k) \approx C k$ if the rule
          // is first order, so that $D$ halves with $k$. (Against the exact
          // solution the mesh's error, which does not fall with $k$, would
          // soon hide it.)
          std::cout << "\nThe memory rule alone, 1/h = 16, u at T = 1 for k "
                       "against k/2:"
                    << std::endl;
          // The mesh is coarse on purpose: the difference measures the
          // rule in time on whatever mesh, and 578 unknowns keep the
          // finest $k$ cheap (129 load values at five levels).
          // We keep the previous problem alive, since its solution at $T$ is
          // what the next one is compared with; unique_ptr hands it on without
          // a copy.
          ConvergenceTable                         k_table;
          std::unique_ptr<MemoryContactProblem<2>> coarser;
          for (unsigned int level = 0; level <= n_levels; ++level)
            {
              const unsigned int n_steps = 4u << level;
              auto               finer =
                std::make_unique<MemoryContactProblem<2>>(manufactured,
                                                          4,
                                                          1. / n_steps);
              for (unsigned int n = 0; n < finer->n_load_values(); ++n)
                finer->run(n);
              if (coarser)
                {
                  const auto [D_H, D_V] = coarser->difference(*finer);
                  k_table.add_value("1/k", n_steps / 2);
                  k_table.add_value("D_H", D_H);
                  k_table.add_value("D_V", D_V);
                }
              coarser = std::move(finer);
            }
          for (const std::string column : {"D_H", "D_V"})
            {
              k_table.set_scientific(column, true);
              k_table.set_precision(column, 3);
              k_table.evaluate_convergence_rates(
                column, ConvergenceTable::reduction_rate_log2);
            }
          k_table.write_text(std::cout);
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
