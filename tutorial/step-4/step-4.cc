/* ---------------------------------------------------------------------
 *
 * hemicontact tutorial, step-4: adapting the mesh to an error estimate.
 * step-1's static contact problem (a nonmonotone normal compliance and
 * Tresca friction, solved by the primal-dual active set method) on an
 * L-shaped body, whose re-entrant corner makes the solution singular; a
 * residual error estimator with a contact term, and refinement driven by
 * it in the manner of deal.II's step-6.
 *
 * The introduction (doc/intro.md) states the estimator and the
 * refinement loop and says what is new since step-1; the results
 * (doc/results.md) show what this program prints. The program depends on
 * deal.II alone.
 *
 * ---------------------------------------------------------------------
 */

// @sect3{Include files}

// step-1's headers, and those of step-6 for adaptive meshes: the marking
// (GridRefinement), the transfer of the solution to the refined mesh
// (SolutionTransfer), the hanging node constraints (DoFTools) and the
// values of shape functions on the children of a face (FESubfaceValues,
// in fe_values.h).
#include <deal.II/base/function.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>
#include <deal.II/base/timer.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_refinement.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/sparse_direct.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/vector.h>
#include <deal.II/numerics/data_out.h>
#include <deal.II/numerics/solution_transfer.h>
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

namespace Step4
{
  using namespace dealii;

  // @sect3{The normal law}

  // The law of step-1, unchanged: a continuous piecewise-linear response
  // $\xi(r)$ given by breakpoints $(r_k, \xi_k)$, $r_0 = 0$, split into the
  // convex jump $a = \xi_0$ at $r = 0$ and a Lipschitz remainder,
  // @f[
  //   \partial j_\nu(r) = \partial(a r_+)(r) + p(r),\qquad
  //   p(r) = \xi(r) - a \ (r > 0),\quad p(r) = 0 \ (r \le 0).
  // @f]
  // step-1's introduction explains the split, the Clarke subdifferential
  // and the constant $\alpha_\nu$ of relaxed monotonicity (the steepest
  // descent slope of $\xi$); the members are the seven that step-1 lists.
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

  // @sect3{The problem data}

  // The boundary ids are those of the full program's L-shaped mesh
  // (prm/gmsh/l_shape.geo), so that the two programs can be given the
  // same problem: $\Gamma_1$ (clamped) has id 1, $\Gamma_3$ (contact) id
  // 2, the loaded part of $\Gamma_2$ id 3, and the rest of the boundary,
  // free of traction (also a part of $\Gamma_2$, with $f_2 = 0$), id 4.
  namespace BoundaryIds
  {
    constexpr types::boundary_id clamped = 1;
    constexpr types::boundary_id contact = 2;
    constexpr types::boundary_id loaded  = 3;
    constexpr types::boundary_id free    = 4;
  } // namespace BoundaryIds

  // What defines the problem, as in step-1: the Lam&eacute; constants of
  // $B$, the friction bound, the law, the coarse mesh, and the loads $f_0$
  // in $\Omega$ and $f$ on the boundary. Unlike step-1 there is no load
  // parameter $t$: each mesh of the adaptive loop solves the same static
  // problem.
  template <int dim>
  class ProblemData
  {
  public:
    ProblemData(const double mu, const double lambda, const double F_b)
      : mu(mu)
      , lambda(lambda)
      , friction_bound(F_b)
      , law({{0, 1}, {0.02, 1.4}, {0.15, 1.3}})
    {}

    virtual ~ProblemData() = default;

    // What a problem supplies, in the way deal.II's Function class asks for
    // values: the coarse mesh with its boundary ids, and the two loads as
    // functions of the point. The material and the law are data members; the
    // stress and its divergence below are the two things the solver and the
    // estimator ask of the material.
    virtual void
    make_coarse_grid(Triangulation<dim> &triangulation) const = 0;

    // $f_0(x)$ and the prescribed traction at $x$ on the boundary with id
    // @p id and outward normal @p normal ($f_2$ on $\Gamma_2$; on
    // $\Gamma_3$ an extra traction $f_3$, zero here, which a manufactured
    // solution would set).
    virtual Tensor<1, dim>
    body_force(const Point<dim> &x) const = 0;

    virtual Tensor<1, dim>
    traction(const Point<dim>        &x,
             const Tensor<1, dim>    &normal,
             const types::boundary_id id) const = 0;

    // $\sigma = B\varepsilon = 2\mu\varepsilon + \lambda\,\mathrm{tr}
    // (\varepsilon) I$.
    SymmetricTensor<2, dim>
    stress(const SymmetricTensor<2, dim> &eps) const
    {
      return 2 * mu * eps + lambda * trace(eps) * unit_symmetric_tensor<dim>();
    }

    // $\mathrm{div}\,\sigma(u) = \mu\Delta u + (\mu + \lambda)\nabla\,
    // \mathrm{div}\,u$ from the Hessian $H_{ijk} = \partial_j\partial_k
    // u_i$; it does not vanish for $Q_1$ functions, which hold the
    // product $xy$.
    Tensor<1, dim>
    stress_divergence(const Tensor<3, dim> &hessian) const
    {
      Tensor<1, dim> result;
      for (int i = 0; i < dim; ++i)
        for (int j = 0; j < dim; ++j)
          result[i] += mu * hessian[i][j][j] + (mu + lambda) * hessian[j][i][j];
      return result;
    }

    const double             mu, lambda;
    const double             friction_bound;
    const PiecewiseLinearLaw law;
  };

  // @sect4{The L-shaped body}

  // $\Omega = [0,2]^2 \setminus (1,2]\times(1,2]$ with its re-entrant
  // corner at $(1,1)$ (GridGenerator::hyper_L() with left $= 0$ and right
  // $= 2$: three unit squares), clamped on $x = 0$, on the foundation along
  // $y = 0$, pressed down and sideways by a constant traction on the top
  // of its left arm, $y = 2$. The two sides that meet at the corner are
  // free, and there the stress of the exact solution is infinite: it grows
  // like $r^{\gamma - 1}$ in the distance $r$ from the corner, $\gamma
  // \approx 0.544$ (the introduction, "Where the solution is singular").
  // The material and the law are step-1's; $\lambda_1 \gg \alpha_\nu$
  // (printed by the program) keeps the solution unique.
  class LShapeData : public ProblemData<2>
  {
  public:
    LShapeData()
      // step-1's material, friction bound and law, in step-1's units: only the
      // body and its load are new.
      : ProblemData<2>(/*mu=*/100, /*lambda=*/150, /*F_b=*/0.6)
    {}

    // The boundary ids by the position of each face's centre: hyper_L()
    // gives every face id 0.
    void
    make_coarse_grid(Triangulation<2> &triangulation) const override
    {
      GridGenerator::hyper_L(triangulation, 0., 2.);
      for (const auto &cell : triangulation.active_cell_iterators())
        for (const auto &face : cell->face_iterators())
          if (face->at_boundary())
            {
              const Point<2> c = face->center();
              face->set_boundary_id(c[0] < 1e-12 ? BoundaryIds::clamped :
                                    c[1] < 1e-12 ? BoundaryIds::contact :
                                    (c[1] > 2 - 1e-12 && c[0] < 1) ?
                                                   BoundaryIds::loaded :
                                                   BoundaryIds::free);
            }
    }

    Tensor<1, 2>
    body_force(const Point<2> &) const override
    {
      return Tensor<1, 2>();
    }

    Tensor<1, 2>
    traction(const Point<2> &,
             const Tensor<1, 2> &,
             const types::boundary_id id) const override
    {
      // Only the top of the left arm is loaded; the traction is constant, so
      // the load vector is exact with any quadrature, and the jump of the
      // traction at the ends of the loaded edge is a singular point of its own.
      if (id != BoundaryIds::loaded)
        return Tensor<1, 2>();
      return Tensor<1, 2>({load[0], load[1]});
    }

    // The traction on the top of the left arm: down and to the left. It
    // presses most of $\Gamma_3$ into the foundation beyond the jump $a$
    // (the branch "penetrating"), holds the rest at $u_\nu = 0$, and shears
    // enough that part of $\Gamma_3$ slips: every branch but "separating"
    // occurs on the adapted meshes (the program prints the counts).
    static constexpr std::array<double, 2> load = {{-4, -8}};
  };

  // @sect3{One contact node}

  // As in step-1: each node $x_i$ of $\Gamma_3$ keeps its degrees of
  // freedom, its weight $m_i = \int_{\Gamma_3}\varphi_i$, its normal
  // $\nu_i$, the constant $c_i$ of the complementarity functions, and its
  // current branches. On an adapted mesh $\Gamma_3$ also has hanging
  // nodes; they are not contact nodes (setup_contact_nodes() says why).
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

  // @sect3{The error estimate}

  // The four parts of $\eta_K^2$ of every cell (the introduction, "The
  // residual estimator"), kept apart so that each can be reported alone:
  // the cell residual, the jumps of the traction across interior faces,
  // the traction residual on $\Gamma_2$ and on $\Gamma_3$. The factor
  // $1/(2\mu)$ puts $\eta$ in the energy norm $|||v||| = a_B(v,
  // v)^{1/2}$ (since $2\mu\|\varepsilon(v)\|^2 \le a_B(v, v)$), so that it
  // can be compared with the error, whatever the units of the moduli.
  struct ErrorEstimate
  {
    // One vector per part, one entry per active cell, and the factor
    // $1/(2\mu)$; the parts are kept squared, so that adding them cell by cell
    // gives
    // $\eta_K^2$ and adding a part over the cells its share of $\eta^2$.
    Vector<double> interior, jumps, neumann, contact;
    double         scale = 1;

    // $\eta_K$, the refinement indicator. Single precision as deal.II's
    // own estimators deliver it (step-6's KellyErrorEstimator): the
    // marking only compares the values with each other.
    Vector<float>
    cell_values() const
    {
      Vector<float> eta(interior.size());
      for (unsigned int i = 0; i < eta.size(); ++i)
        eta[i] =
          std::sqrt(scale * (interior[i] + jumps[i] + neumann[i] + contact[i]));
      return eta;
    }

    // $\eta = (\sum_K \eta_K^2)^{1/2}$, and one part of it alone:
    // $(s\sum_K \eta_{K,\text{part}}^2)^{1/2}$.
    double
    part(const Vector<double> &values) const
    {
      return std::sqrt(scale * values.l1_norm());
    }

    double
    total() const
    {
      return std::sqrt(scale * (interior.l1_norm() + jumps.l1_norm() +
                                neumann.l1_norm() + contact.l1_norm()));
    }
  };

  // @sect3{The AdaptiveContactProblem class}

  // step-1's StaticContactProblem with the functions of step-6 added:
  // setup_system() now also makes the hanging node constraints,
  // estimate_error() evaluates the estimator, and refine_mesh() marks,
  // refines and moves the solution to the new mesh. solve() is step-1's
  // active set Newton method, on the mesh at hand and started from the
  // solution moved from the mesh before.
  template <int dim>
  class AdaptiveContactProblem
  {
  public:
    AdaptiveContactProblem(const ProblemData<dim> &data,
                           const unsigned int      n_refinements);

    void
    // step-1's active set Newton method on the current mesh, from the current
    // solution (zero on the first mesh, the moved solution on the later ones).
    solve();

    ErrorEstimate
    // The residual estimator of the introduction: the four parts of every
    // cell's $\eta_K^2$, from the current solution.
    estimate_error() const;

    // Refine the cells with the largest indicators, a @p fraction of all
    // cells (the introduction, "The adaptive loop").
    void
    // (after this call the solution lives on the new mesh, and the system is
    // set up anew)
    refine_mesh(const Vector<float> &indicators, const double fraction);

    void
    // The files of one cycle, numbered by @p cycle: the VTU for ParaView, the
    // nodal displacement for the comparison with the full program, and the
    // cells for the picture of the adapted meshes.
    output_results(const unsigned int cycle, const ErrorEstimate &e) const;

    // $J_h(u_h)$, the energy at the solution: the error measure of the
    // introduction ("Measuring the error") compares it with that of a
    // reference solution.
    double
    energy() const
    {
      return energy(solution);
    }

    unsigned int
    n_dofs() const
    {
      return dof_handler.n_dofs();
    }

    unsigned int
    n_cells() const
    {
      return triangulation.n_active_cells();
    }

    // The constant $\lambda_1$ of step-1's smallness condition: $J_h$ is
    // strictly convex, and the discrete problem has one solution, when
    // $\alpha_\nu < \lambda_1$.
    double
    smallness_constant() const;

    // The Newton iterations of the last solve() and the branch counts
    // (normal separating/stick/penetrating, tangential stick/slip).
    unsigned int newton_iterations = 0;
    std::array<unsigned int, 5>
    branch_counts() const;

  private:
    void
    setup_system();
    void
    setup_contact_nodes();
    void
    assemble_system(const AffineConstraints<double> &constraints,
                    SparseMatrix<double>            &matrix,
                    Vector<double>                  &rhs) const;
    void
    // $R = Ku - F$ with the hanging nodes handled (see its definition): every
    // function that needs the residual calls this one, so that the solver,
    // the estimator and the output read the same contact forces.
    compute_residual(const Vector<double> &u, Vector<double> &residual) const;

    // step-1's pieces of solve().
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

    const ProblemData<dim> &data;

    // The mesh smoothing limit_level_difference_at_vertices: two cells
    // that share a vertex differ by at most one level. deal.II only
    // requires it across faces; across vertices too, the meshes are those
    // of a p4est mesh (parallel::distributed::Triangulation, whose 2:1
    // balance includes corners), on which the full program adapts.
    Triangulation<dim> triangulation;
    FESystem<dim>      fe;
    DoFHandler<dim>    dof_handler;

    // Two sets of constraints, as in step-1, but the first now holds the
    // hanging nodes besides the clamped boundary (step-6): $V^h$ are the
    // continuous $Q_1$ fields, and a node in the middle of a face of a
    // coarser neighbour takes the mean of that face's end nodes. $K$ and
    // $F$ are assembled with them; the Newton constraints add the held
    // conditions of the current branches.
    AffineConstraints<double> constraints;
    AffineConstraints<double> newton_constraints;

    SparsityPattern      sparsity_pattern;
    SparseMatrix<double> stiffness_matrix;
    SparseMatrix<double> newton_matrix;

    Vector<double> solution;   // $u$, moved from mesh to mesh
    Vector<double> load;       // $F$
    Vector<double> newton_rhs; // $g$ of the Newton step, condensed

    std::vector<ContactNode<dim>> contact_nodes;
  };

  // The constructor builds the mesh and the system; the solution starts
  // at zero.
  template <int dim>
  AdaptiveContactProblem<dim>::AdaptiveContactProblem(
    const ProblemData<dim> &data,
    const unsigned int      n_refinements)
    : data(data)
    , triangulation(Triangulation<dim>::limit_level_difference_at_vertices)
    , fe(FE_Q<dim>(1), dim)
    , dof_handler(triangulation)
  {
    // We build the starting mesh here, with no make_grid(): the later meshes
    // come from refine_mesh(), not from the data. The solution is sized once;
    // refine_mesh() gives it the size of each new mesh.
    data.make_coarse_grid(triangulation);
    triangulation.refine_global(n_refinements);
    dof_handler.distribute_dofs(fe);
    solution.reinit(dof_handler.n_dofs());
    setup_system();
  }

  // @sect4{AdaptiveContactProblem::setup_system}

  // The constraints of $V^h$ (hanging nodes, then the clamped boundary;
  // after close() a hanging node on $\Gamma_1$'s edge is resolved to the
  // zero of its clamped parents), the sparsity pattern, $K$ and $F$, and
  // the contact nodes. The pattern is made with the constraints, so that
  // it holds the entries that condensing a hanging node onto its parents
  // creates; it couples every component of a node with every component
  // of its neighbours, and so also holds the entries of the held
  // conditions of solve() (they tie the components of one node, or of a
  // hanging node's parents, together).
  template <int dim>
  void
  AdaptiveContactProblem<dim>::setup_system()
  {
    constraints.clear();
    DoFTools::make_hanging_node_constraints(dof_handler, constraints);
    VectorTools::interpolate_boundary_values(dof_handler,
                                             BoundaryIds::clamped,
                                             Functions::ZeroFunction<dim>(dim),
                                             constraints);
    constraints.close();

    // keep_constrained_dofs = true keeps the rows and columns of the
    // constrained degrees of freedom in the pattern:
    // distribute_local_to_global() puts their diagonal entry there, which keeps
    // the condensed matrices invertible.
    DynamicSparsityPattern dsp(dof_handler.n_dofs());
    DoFTools::make_sparsity_pattern(dof_handler,
                                    dsp,
                                    constraints,
                                    /*keep_constrained_dofs=*/true);
    sparsity_pattern.copy_from(dsp);
    stiffness_matrix.reinit(sparsity_pattern);
    newton_matrix.reinit(sparsity_pattern);

    // The solution is not touched here: on a refined mesh it holds the moved
    // solution, the start of the next Newton iteration.
    load.reinit(dof_handler.n_dofs());
    newton_rhs.reinit(dof_handler.n_dofs());

    assemble_system(constraints, stiffness_matrix, load);
    setup_contact_nodes();
  }

  // @sect4{The contact nodes}

  // step-1's nodal weights $m_i = \int_{\Gamma_3}\varphi_i$ and normals
  // $\nu_i = \int_{\Gamma_3}\varphi_i\nu / |\cdot|$, now condensed with
  // the constraints like a right-hand side: a hanging node's share of
  // $\int_{\Gamma_3}\varphi_i$ goes to its two parents, half each, since
  // in $V^h$ the hanging node's basis function is not a degree of freedom
  // of its own but half of each parent's. A hanging node is then no
  // contact node: its displacement is fixed by its parents, and a degree
  // of freedom can carry only one constraint (the same reason that keeps
  // the nodes of $\Gamma_1$ out, as in step-1). The nodal quadrature of
  // the contact terms runs over the free nodes of $\Gamma_3$ with these
  // weights. The constant $c_i$ is step-1's: the mean diagonal of $K$ at
  // the node over $m_i$, and at least twice the law's steepest rise.
  template <int dim>
  void
  AdaptiveContactProblem<dim>::setup_contact_nodes()
  {
    Vector<double> mass(dof_handler.n_dofs()), normal(dof_handler.n_dofs());
    const QGauss<dim - 1>                face_quadrature(2);
    FEFaceValues<dim>                    fe_face_values(fe,
                                     face_quadrature,
                                     update_values | update_normal_vectors |
                                       update_JxW_values);
    const unsigned int                   n = fe.n_dofs_per_cell();
    Vector<double>                       cell_mass(n), cell_normal(n);
    std::vector<types::global_dof_index> dofs(n);

    // The face integrals, one face at a time, added into the global
    // vectors through the constraints: a share that belongs to a hanging
    // node lands on its parents, a share of a clamped node nowhere (its
    // entry stays zero and it is no contact node anyway).
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
            cell_mass   = 0;
            cell_normal = 0;
            for (const unsigned int q :
                 fe_face_values.quadrature_point_indices())
              for (unsigned int i = 0; i < n; ++i)
                {
                  const unsigned int c = fe.system_to_component_index(i).first;
                  const double       phi_JxW =
                    fe_face_values.shape_value_component(i, q, c) *
                    fe_face_values.JxW(q);
                  cell_mass(i) += phi_JxW;
                  cell_normal(i) +=
                    phi_JxW * fe_face_values.normal_vector(q)[c];
                }
            cell->get_dof_indices(dofs);
            constraints.distribute_local_to_global(cell_mass, dofs, mass);
            constraints.distribute_local_to_global(cell_normal, dofs, normal);
          }

    // Every vertex of $\Gamma_3$ is met once per face it belongs to: the
    // flags keep the first meeting. The constrained vertices (the corner on
    // $\Gamma_1$, and the hanging nodes) are skipped; every other vertex of
    // $\Gamma_3$ has a positive weight, since it is the end of at least one
    // active face of $\Gamma_3$.
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
                  constraints.is_constrained(node.dofs[0]))
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
              // $c_i$ from the condensed diagonal: next to a hanging node it
              // holds the hanging node's share too, as the condensed $K$ does.
              node.c =
                std::max(diagonal / node.mass, 2 * data.law.steepest_rise);
              contact_nodes.push_back(node);
            }
  }

  // @sect4{AdaptiveContactProblem::assemble_system}

  // step-1's assembly of the stiffness $\int_K B\varepsilon(\varphi_j) :
  // \varepsilon(\varphi_i)$ (Gauss, 2 points per direction) and the load
  // $\int_K f_0\cdot\varphi_i + \int_{\partial K\cap(\Gamma_2\cup
  // \Gamma_3)} f\cdot\varphi_i$ (3 points per direction), condensed with
  // the given constraints. With the hanging nodes among them, the
  // condensed matrix acts on the values at the free nodes; its rows of
  // constrained degrees of freedom hold a diagonal entry only
  // (distribute_local_to_global() keeps the matrix invertible that way),
  // and the right-hand side is zero there.
  template <int dim>
  void
  AdaptiveContactProblem<dim>::assemble_system(
    const AffineConstraints<double> &constraints,
    SparseMatrix<double>            &matrix,
    Vector<double>                  &rhs) const
  {
    // Three evaluators: the gradients for the stiffness (2 points per
    // direction), and the values for the load on the cells and on the faces
    // (3 points).
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
    // condensed, as in step-6. The load uses one Gauss point more than the
    // matrix, as in step-1: there the data were not polynomials; here they
    // are constant, and the extra point costs little.
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
              data.body_force(fe_load.quadrature_point(q));
            for (unsigned int i = 0; i < n; ++i)
              cell_rhs(i) +=
                f0 * fe_load[displacement].value(i, q) * fe_load.JxW(q);
          }
        for (const auto &face : cell->face_iterators())
          // Every boundary face that is not clamped carries a traction: $f_2$
          // on the loaded part of $\Gamma_2$, zero on its free part and on
          // $\Gamma_3$, where the contact forces come from the laws alone. One
          // function covers all, the same that the estimator evaluates.
          if (face->at_boundary() &&
              face->boundary_id() != BoundaryIds::clamped)
            {
              fe_face.reinit(cell, face);
              for (const unsigned int q : fe_face.quadrature_point_indices())
                {
                  const Tensor<1, dim> f =
                    data.traction(fe_face.quadrature_point(q),
                                  fe_face.normal_vector(q),
                                  face->boundary_id());
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

  // @sect4{The residual}

  // $R = K u - F$ on the free degrees of freedom, zero on the constrained
  // ones. The vector $u$ holds the values at every node, the hanging ones
  // included (as the output and the estimator need them); the condensed
  // $K$ expects zeros there, since its constrained rows and columns carry
  // only their diagonal. So $u$ is multiplied with those entries set to
  // zero: then $Ku$ at a free node is the force of the whole field, the
  // hanging nodes' share condensed onto their parents.
  template <int dim>
  void
  AdaptiveContactProblem<dim>::compute_residual(const Vector<double> &u,
                                                Vector<double> &residual) const
  {
    Vector<double> free_values(u);
    constraints.set_zero(free_values);
    stiffness_matrix.vmult(residual, free_values);
    residual -= load;
    constraints.set_zero(residual);
  }

  // @sect3{The active-set Newton method}

  // This section is step-1's, and its comments are shortened to what
  // changes; step-1 derives every formula.

  // @sect4{The state of a node}

  // The traction $G_i/m_i = -R_i/m_i$ of a contact node, split into the
  // multipliers $s_\nu = G_i\cdot\nu/m_i - p(u_\nu)$ and $s_\tau =
  // G_{i,\tau}/m_i$ of the convex parts of the laws, and the arguments
  // $q_\nu = s_\nu + c\,u_\nu$, $q_\tau = s_\tau + c\,u_\tau$ of the
  // projections in the complementarity functions
  // @f[
  //   C_\nu = s_\nu - P_{[0,a]}(s_\nu + c\,u_\nu),\qquad
  //   C_\tau = s_\tau - P_{|\cdot|\le F_b}(s_\tau + c\,u_\tau).
  // @f]
  template <int dim>
  // The members, in the order of the formulas: the normal displacement and
  // the slip, the two multipliers, and the arguments of the projections.
  // They change with every iterate and are recomputed from the residual
  // when needed, never stored.
  struct AdaptiveContactProblem<dim>::NodeState
  {
    double         u_nu;
    Tensor<1, dim> u_tau;
    double         s_nu;
    Tensor<1, dim> s_tau;
    double         q_nu;  // s_nu + c u_nu
    Tensor<1, dim> q_tau; // s_tau + c u_tau
  };

  template <int dim>
  typename AdaptiveContactProblem<dim>::NodeState
  AdaptiveContactProblem<dim>::node_state(const ContactNode<dim> &node,
                                          const Vector<double> &residual) const
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
  // (inside the disk $q$ itself, outside its radial projection)
  project_on_disk(const Tensor<1, dim> &q, const double F_b)
  {
    return q.norm() <= F_b ? q : F_b / q.norm() * q;
  }

  // @sect4{The branches}

  // $q_\nu < 0$ separating, $0 \le q_\nu \le a$ stick, $q_\nu > a$
  // penetrating; $|q_\tau| \le F_b$ stick, otherwise slip. Returns the
  // number of nodes whose branches changed.
  template <int dim>
  unsigned int
  AdaptiveContactProblem<dim>::update_active_set(const Vector<double> &residual)
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

  template <int dim>
  std::array<unsigned int, 5>
  // The branch counts for the line printed after the adaptive loop: three
  // normal branches, then two tangential ones.
  AdaptiveContactProblem<dim>::branch_counts() const
  {
    std::array<unsigned int, 5> counts = {{0, 0, 0, 0, 0}};
    for (const ContactNode<dim> &node : contact_nodes)
      {
        ++counts[static_cast<int>(node.normal_branch)];
        ++counts[3 + static_cast<int>(node.tangential_branch)];
      }
    return counts;
  }

  // The nonsmooth residual: $R$ on the free degrees of freedom away from
  // $\Gamma_3$, and the complementarity functions weighted by $m_i$ at the
  // contact nodes. $R$ is zero on the constrained degrees of freedom
  // (compute_residual()), the hanging nodes among them.
  template <int dim>
  double
  AdaptiveContactProblem<dim>::nonsmooth_residual(
    const Vector<double> &residual) const
  {
    // At a contact node the residual is not expected to vanish (it is the
    // contact force); there the complementarity functions take its place.
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

  // step-1's Newton system: the quadratic model $\frac12 x\cdot(K + L)x -
  // g\cdot x$ of the current branches, minimised over the displacements
  // that satisfy the held conditions ($x_i\cdot\nu_i = 0$ at normal stick,
  // $x_i - (x_i\cdot\nu_i)\nu_i = 0$ at tangential stick), with the forces
  // $f_i$ and derivatives $L_i$ of the free branches (penetrating: $f_i =
  // m_i(a + p(u_\nu))\nu$, $L_i = m_i p'(u_\nu)\nu\otimes\nu$; slip: $f_i =
  // m_i F_b d + T_i u_\tau$, $L_i = T_i$ the condensed tangent of the
  // friction disk, zero in 2D) and $g_i = F_i + L_i u_i - f_i$. The held
  // conditions join the constraints of $V^h$; AffineConstraints resolves
  // the chains where a hanging node's parent is itself held.
  template <int dim>
  void
  AdaptiveContactProblem<dim>::assemble_newton_system(
    const Vector<double> &residual)
  {
    // Each held condition is solved for one component of the node: the one
    // of largest $|\nu_c|$, so that the division by $\nu_k$ is safe (on the
    // flat $\Gamma_3$ of this program, $\nu = (0, -1)$ and $k$ is $y$).
    newton_constraints.clear();
    for (const ContactNode<dim> &node : contact_nodes)
      {
        const bool normal_held = node.normal_branch == NormalBranch::stick;
        const bool tangent_held =
          node.tangential_branch == TangentialBranch::stick;
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
    // The contact nodes are free in $V^h$, so the two sets of constraints
    // never hold the same degree of freedom and merge without conflict.
    newton_constraints.merge(constraints);
    newton_constraints.close();

    assemble_system(newton_constraints, newton_matrix, newton_rhs);

    // The nodal terms of the free branches, added through the same
    // constraints as the cell terms, so that a node's held directions
    // drop out of its own $L_i$ too.
    FullMatrix<double>                   node_matrix(dim, dim);
    Vector<double>                       node_rhs(dim);
    std::vector<types::global_dof_index> node_dofs(dim);
    for (const ContactNode<dim> &node : contact_nodes)
      {
        const NodeState m = node_state(node, residual);
        // The force $f$ and the derivative $L$ of the node's free branches; a
        // held direction contributes nothing, its constraint removes it.
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

  // $J_h(u) = \frac12 u\cdot K u - F\cdot u + \sum_i m_i
  // [j_\nu(u_{i,\nu}) + F_b |u_{i,\tau}|]$, with the quadratic part taken,
  // as the residual, from the values at the free nodes: this is the
  // energy of the field in $V^h$ that $u$ holds.
  template <int dim>
  double
  AdaptiveContactProblem<dim>::energy(const Vector<double> &u) const
  {
    // As in compute_residual(): the quadratic part from the free values, the
    // contact part from the nodal values, which are free by construction.
    Vector<double> free_values(u);
    constraints.set_zero(free_values);
    double J = 0.5 * stiffness_matrix.matrix_norm_square(free_values) -
               load * free_values;
    // The nodal quadrature of the boundary terms: $m_i$ weighs each node's
    // potential and friction.
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

  // @sect4{AdaptiveContactProblem::solve}

  // step-1's iteration with step-1's tolerances: stop when no branch
  // changed and the nonsmooth residual is below $10^{-11}|F|$, or when it
  // is a hundred times below that (a node within round-off of a switch
  // may flip its label without changing the solution); at most 50
  // iterations; and step-1's line search: the first $\theta$ of $1,
  // \frac12, \dots, 2^{-10}$ that does not raise $J_h$ beyond a relative
  // $10^{-12}$, and the full step if none does (a direction that is not
  // one of descent occurs only while the branches are still wrong, and the
  // full step moves to the branches that the next update corrects, where a
  // tiny step would stall). On the meshes of the default run the fallback
  // is never taken. The iteration starts from the solution moved from the
  // mesh before, which is close to the new one: the later cycles take few
  // iterations.
  template <int dim>
  void
  AdaptiveContactProblem<dim>::solve()
  {
    // The tolerance is relative to the load: the residual is a force, and
    // $10^{-11}|F|$ lies well above the round-off of evaluating it while
    // being tight enough for the comparison with the full program at
    // $10^{-10}$. The load does not change between the meshes, but its
    // vector does (it has an entry per node), and so does the tolerance.
    const double   tolerance = 1e-11 * load.l2_norm();
    Vector<double> residual(dof_handler.n_dofs());
    newton_iterations = 0;
    for (unsigned int iteration = 0;; ++iteration)
      {
        // The residual of the current iterate decides everything else: the
        // branches, the stopping test and the right-hand side of the Newton
        // step.
        compute_residual(solution, residual);
        const unsigned int n_changed = update_active_set(residual);
        const double       r         = nonsmooth_residual(residual);
        if ((n_changed == 0 && r <= tolerance) || r <= 1e-2 * tolerance)
          break;
        AssertThrow(iteration < 50,
                    ExcMessage("The active set Newton method did not "
                               "converge in 50 iterations."));

        // The Newton system on the current branches, with the constraints of
        // $V^h$ and the held conditions of the contact nodes together.
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

        // The line search on $J_h$. A full Newton step can raise $J_h$
        // because $j_\nu$ is not convex: the quadratic model of one branch
        // is wrong beyond that branch's segment of the law. The bound
        // $10^{-12}$ on the rise is relative, since $J_h$ is a sum of terms
        // of either sign whose last digits are noise. The trial points
        // satisfy the constraints of $V^h$ (distribute() above), and so does
        // every point on the segment to them.
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

  // @sect3{The error estimator}

  // @sect4{AdaptiveContactProblem::estimate_error}

  // The residual estimator of the introduction. With $\sigma_h =
  // B\varepsilon(u_h)$ and $\xi_h$ the piecewise-linear interpolant on
  // $\Gamma_3$ of the nodal contact tractions $\xi_i = -R_i/m_i$, for every
  // cell $K$
  // @f{align*}{
  //   \eta_K^2 = \frac1{2\mu}\Bigl(& h_K^2\|f_0 + \mathrm{div}\,\sigma_h\|_K^2
  //     + \tfrac12\sum_{E\subset\partial K\cap\Omega}
  //       h_E\|[\sigma_h\nu_E]\|_E^2
  //     \\ &+ \sum_{E\subset\partial K\cap\Gamma_2} h_E\|f_2 -
  //     \sigma_h\nu\|_E^2
  //     + \sum_{E\subset\partial K\cap\Gamma_3}
  //       h_E\|f_3 - \sigma_h\nu - \xi_h\|_E^2\Bigr),
  // @f}
  // $h_K$ and $h_E$ the diameters, nothing on $\Gamma_1$. The last term is
  // the contact term: $-\sigma\nu = \xi$ is the law on $\Gamma_3$, and
  // $\xi_h$ is what the discrete solution says the foundation supplies.
  //
  // The integrals use Gauss rules of 2 points per direction, enough for
  // the polynomial parts (the data here are constant). A face between two
  // cells is visited once: from the finer side's parent where a neighbour
  // is finer (each child face with FESubfaceValues on the coarse cell and
  // FEFaceValues on the child, and $h_E$ the child face's diameter),
  // between cells of one level from the cell of lower index, and half of
  // $h_E\|[\sigma_h\nu_E]\|^2_E$ goes to each side. This is the order in which
  // the full program's ErrorEstimator visits a serial mesh, so that the
  // two give the same numbers to round-off.
  template <int dim>
  ErrorEstimate
  AdaptiveContactProblem<dim>::estimate_error() const
  {
    // $\xi$ at the contact nodes, zero elsewhere; at a hanging node of
    // $\Gamma_3$ the mean of its parents, by the hanging node constraints
    // (distribute()), so that $\xi_h$ is the continuous interpolant along
    // $\Gamma_3$. The nodes of $\Gamma_1$ keep $\xi = 0$.
    // (The contact tractions are the laws' forces at the solution, read from
    // the residual exactly as the solver reads them.)
    Vector<double> residual(dof_handler.n_dofs()), xi(dof_handler.n_dofs());
    compute_residual(solution, residual);
    for (const ContactNode<dim> &node : contact_nodes)
      for (unsigned int c = 0; c < dim; ++c)
        xi(node.dofs[c]) = -residual(node.dofs[c]) / node.mass;
    constraints.distribute(xi);

    // Two Gauss points per direction integrate every square of the estimate
    // exactly on the rectangles of these meshes: with $f_0 = 0$ the cell
    // residual $\mathrm{div}\,\sigma_h$ is constant on a cell (the only second
    // derivative of a $Q_1$ field is $\partial_x\partial_y$), and the face
    // residuals are linear along a face.
    const QGauss<dim>     cell_quadrature(2);
    const QGauss<dim - 1> face_quadrature(2);
    const UpdateFlags     face_flags =
      update_gradients | update_normal_vectors | update_JxW_values;
    FEValues<dim>     fe_values(fe,
                            cell_quadrature,
                            update_hessians | update_quadrature_points |
                              update_JxW_values);
    FEFaceValues<dim> fe_face(fe,
                              face_quadrature,
                              face_flags | update_values |
                                update_quadrature_points);
    FEFaceValues<dim> fe_face_other(fe, face_quadrature, update_gradients);
    // A face between a cell and two finer neighbours is integrated from the
    // coarse side, one child face at a time: FESubfaceValues gives the coarse
    // cell's values on a child face, FEFaceValues the fine cell's on the same.
    FESubfaceValues<dim> fe_subface(fe, face_quadrature, face_flags);
    const FEValuesExtractors::Vector v(0);
    const unsigned int               n_f = face_quadrature.size();
    std::vector<Tensor<3, dim>>      hessians(cell_quadrature.size());
    std::vector<Tensor<2, dim>>      gradients(n_f), other_gradients(n_f);
    std::vector<Tensor<1, dim>>      xi_values(n_f);

    // Four vectors with one entry per active cell, indexed by
    // active_cell_index(), which numbers the active cells in the order of
    // the iteration below.
    ErrorEstimate e;
    for (Vector<double> *part : {&e.interior, &e.jumps, &e.neumann, &e.contact})
      part->reinit(triangulation.n_active_cells());
    // The factor $1/(2\mu)$ of the introduction, which puts $\eta$ in the
    // energy norm; it multiplies the parts only when they are summed.
    e.scale = 1. / (2 * data.mu);

    // $\int_E |[\sigma_h\nu_E]|^2$ from the gradients on the two sides, with
    // the normal of the cell at hand.
    const auto jump = [&](const FEFaceValuesBase<dim> &here,
                          const FEFaceValuesBase<dim> &there) {
      here[v].get_function_gradients(solution, gradients);
      there[v].get_function_gradients(solution, other_gradients);
      double integral = 0;
      for (unsigned int q = 0; q < n_f; ++q)
        integral +=
          ((Tensor<2, dim>(data.stress(symmetrize(gradients[q]))) -
            Tensor<2, dim>(data.stress(symmetrize(other_gradients[q])))) *
           here.normal_vector(q))
            .norm_square() *
          here.JxW(q);
      return integral;
    };

    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        // Each cell adds its own terms: the cell residual, its boundary faces,
        // and its share of each interior face's jump, from whichever side the
        // face is integrated.
        const unsigned int i = cell->active_cell_index();

        // The cell residual $h_K^2\|f_0 + \mathrm{div}\,\sigma_h\|_K^2$.
        fe_values.reinit(cell);
        fe_values[v].get_function_hessians(solution, hessians);
        double cell_residual = 0;
        for (const unsigned int q : fe_values.quadrature_point_indices())
          cell_residual += (data.stress_divergence(hessians[q]) +
                            data.body_force(fe_values.quadrature_point(q)))
                             .norm_square() *
                           fe_values.JxW(q);
        e.interior[i] = std::pow(cell->diameter(), 2) * cell_residual;

        for (const unsigned int f : cell->face_indices())
          {
            const auto face = cell->face(f);
            if (face->at_boundary())
              {
                // The traction residual $h_E\|f - \sigma_h\nu - \xi_h\|^2_E$
                // on $\Gamma_2$ and $\Gamma_3$, $\xi_h$ on $\Gamma_3$ only.
                if (face->boundary_id() == BoundaryIds::clamped)
                  continue;
                // data.traction() is $f_2$ on the loaded part of $\Gamma_2$,
                // zero on its free part, and $f_3$ (zero here) on
                // $\Gamma_3$: the same function as in the assembly, so
                // that the estimate sees the load that was solved for.
                const bool on_contact =
                  face->boundary_id() == BoundaryIds::contact;
                // The gradients of the solution on the face and the contact
                // traction
                // $\xi_h$, interpolated along $\Gamma_3$.
                fe_face.reinit(cell, f);
                fe_face[v].get_function_gradients(solution, gradients);
                if (on_contact)
                  fe_face[v].get_function_values(xi, xi_values);
                double boundary_residual = 0;
                for (unsigned int q = 0; q < n_f; ++q)
                  {
                    Tensor<1, dim> r =
                      data.traction(fe_face.quadrature_point(q),
                                    fe_face.normal_vector(q),
                                    face->boundary_id()) -
                      Tensor<2, dim>(data.stress(symmetrize(gradients[q]))) *
                        fe_face.normal_vector(q);
                    if (on_contact)
                      r -= xi_values[q];
                    boundary_residual += r.norm_square() * fe_face.JxW(q);
                  }
                (on_contact ? e.contact : e.neumann)[i] +=
                  face->diameter() * boundary_residual;
              }
            else if (face->has_children())
              // The neighbour is finer: each child face once, from here.
              for (unsigned int sf = 0; sf < face->n_children(); ++sf)
                {
                  const auto child = cell->neighbor_child_on_subface(f, sf);
                  fe_subface.reinit(cell, f, sf);
                  fe_face_other.reinit(child, cell->neighbor_face_no(f));
                  const double half = 0.5 * face->child(sf)->diameter() *
                                      jump(fe_subface, fe_face_other);
                  e.jumps[i] += half;
                  e.jumps[child->active_cell_index()] += half;
                }
            // The three cases of an interior face: a finer neighbour (above), a
            // neighbour of the same level, and a coarser one, whose face this
            // cell's face is a child of; every face is integrated exactly once.
            else if (!cell->neighbor_is_coarser(f) &&
                     cell->neighbor(f)->active_cell_index() > i)
              // A neighbour of the same level, visited from the lower index
              // (a coarser neighbour visits the face itself).
              {
                const auto neighbor = cell->neighbor(f);
                fe_face.reinit(cell, f);
                fe_face_other.reinit(neighbor, cell->neighbor_of_neighbor(f));
                const double half =
                  0.5 * face->diameter() * jump(fe_face, fe_face_other);
                e.jumps[i] += half;
                e.jumps[neighbor->active_cell_index()] += half;
              }
          }
      }
    return e;
  }

  // @sect3{Refining the mesh}

  // @sect4{AdaptiveContactProblem::refine_mesh}

  // step-6's four steps. Mark:
  // GridRefinement::refine_and_coarsen_fixed_number() flags the $\lfloor\zeta
  // n_K\rfloor$ cells with the largest indicators
  // ($n_K$ cells, $\zeta$ = @p fraction; $\theta$ stays the step length of
  // the line search; a cell tied with the last one is
  // flagged too) and coarsens none. Refine: the triangulation refines the
  // flagged cells, and then more where the smoothing asks (no two cells
  // at a vertex two levels apart). Move the solution: SolutionTransfer
  // interpolates it to the new mesh, exactly, since the old $V^h$ lies in
  // the new one; it is the start of the next Newton iteration. Constrain:
  // setup_system() makes the new hanging node constraints and the new
  // system, and distribute() sets the new hanging nodes to the mean of
  // their parents (the interpolated values are those already, to
  // round-off).
  template <int dim>
  void
  AdaptiveContactProblem<dim>::refine_mesh(const Vector<float> &indicators,
                                           const double         fraction)
  {
    // The flags first; prepare_coarsening_and_refinement() then adds the
    // flags that the smoothing needs, and SolutionTransfer must see the
    // final flags, so it is prepared after that call.
    // A fixed fraction of the cells, not a fraction of $\sum_K\eta_K^2$
    // (Dörfler's marking): each cycle then grows the mesh by about the same
    // factor, which makes the cycles of the table comparable.
    GridRefinement::refine_and_coarsen_fixed_number(triangulation,
                                                    indicators,
                                                    fraction,
                                                    0.);
    SolutionTransfer<dim> transfer(dof_handler);
    triangulation.prepare_coarsening_and_refinement();
    transfer.prepare_for_coarsening_and_refinement(solution);
    // After this call the cells are new and the old degrees of freedom are
    // gone; only the transfer remembers the old solution.
    triangulation.execute_coarsening_and_refinement();
    // The new numbering; the transfer keeps the old one, with which it reads
    // the old vector.
    dof_handler.distribute_dofs(fe);
    // The old vector is read by the transfer while the new one is written:
    // two vectors, the old one replaced afterwards.
    Vector<double> interpolated(dof_handler.n_dofs());
    transfer.interpolate(solution, interpolated);
    solution = interpolated;
    setup_system();
    constraints.distribute(solution);
  }

  // @sect3{Output and the smallness constant}

  // @sect4{AdaptiveContactProblem::smallness_constant}

  // step-1's power iteration $x \leftarrow K^{-1}M_\nu x$ for the largest
  // eigenvalue $1/\lambda_1$ of $K^{-1}M_\nu$, $M_\nu = \sum_i m_i\nu_i\otimes
  // \nu_i$; its Rayleigh quotient approaches $\lambda_1$ from above, and
  // the iteration stops when it changes by less than $10^{-12}$ relative.
  // The iterate vanishes on the constrained degrees of freedom (their rows
  // of the condensed $K$ are diagonal, and $M_\nu x$ is zero there), so the
  // quotient is that of the field in $V^h$.
  template <int dim>
  double
  AdaptiveContactProblem<dim>::smallness_constant() const
  {
    // We never assemble $M_\nu$ as a matrix: it is diagonal in the nodes, and
    // applying it is one loop over the contact nodes, which project $x$ onto
    // their normals and weight it with $m_i$.
    const auto apply_M_nu = [&](const Vector<double> &x, Vector<double> &Mx) {
      Mx = 0;
      for (const ContactNode<dim> &node : contact_nodes)
        {
          double x_nu = 0;
          for (unsigned int c = 0; c < dim; ++c)
            x_nu += x(node.dofs[c]) * node.normal[c];
          for (unsigned int c = 0; c < dim; ++c)
            Mx(node.dofs[c]) = node.mass * x_nu * node.normal[c];
        }
    };

    // One factorisation of $K$, used in every step of the iteration; the
    // start is the normal field on $\Gamma_3$, which the lowest mode
    // resembles.
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
        // The Rayleigh quotient of the current iterate, which approaches
        // $\lambda_1$ from above.
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

  // @sect4{AdaptiveContactProblem::output_results}

  // Two files per cycle: the displacement with the cell values $\eta_K$
  // and the refinement level for ParaView (solution-NN.vtu), and the
  // nodal displacement in full double precision (displacement-NN.txt: the
  // vertices with their coordinates and $u$, hanging nodes included), for
  // the comparison with the full program.
  template <int dim>
  void
  AdaptiveContactProblem<dim>::output_results(const unsigned int   cycle,
                                              const ErrorEstimate &e) const
  {
    char suffix[16];
    std::snprintf(suffix, sizeof(suffix), "%02u", cycle);

    // Two cell fields beside the displacement: $\eta_K$, to see where the
    // estimate is large, and the refinement level, to see where the marking
    // put the cells (colour the mesh by either in ParaView).
    const Vector<float> eta = e.cell_values();
    Vector<float>       level(triangulation.n_active_cells());
    for (const auto &cell : triangulation.active_cell_iterators())
      level[cell->active_cell_index()] = cell->level();
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
    data_out.add_data_vector(eta, "error_estimate");
    data_out.add_data_vector(level, "level");
    data_out.build_patches();
    std::ofstream vtu(std::string("solution-") + suffix + ".vtu");
    data_out.write_vtu(vtu);

    // Each vertex once, with printf's %.17g, which prints a double so that
    // it reads back bit for bit: the comparison at $10^{-10}$ must not be
    // limited by the output. A hanging vertex has its own degrees of
    // freedom in the DoFHandler, and its value is the constrained one.
    std::FILE *nodal =
      std::fopen((std::string("displacement-") + suffix + ".txt").c_str(), "w");
    AssertThrow(nodal != nullptr, ExcIO());
    // Each vertex once, although it belongs to up to four cells.
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

    // The picture of the body (doc/plot_meshes.py): each cell's vertices in
    // counterclockwise order (0, 1, 3, 2 in deal.II's lexicographic
    // numbering of a quadrilateral's vertices) with the displacement there
    // and, at a contact node, its two branches (-1 elsewhere), as step-1
    // writes them to body-NN.csv. A hanging vertex is drawn with its
    // constrained value, as in displacement-NN.txt.
    // The branches are looked up by the first degree of freedom of a vertex,
    // which is what a contact node and a cell's vertex share.
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
  }

  // @sect3{The refinement studies}

  // One row of a study: the mesh, the Newton iterations, the energy
  // $J_h(u_h)$ and the estimate with its four parts.
  // A row is what the tables and the CSV files need: the sizes, the Newton
  // iterations, the energy from which $E_J$ is computed later (the
  // reference is not known until the loop is done), and the estimate.
  struct CycleResult
  {
    unsigned int cells, dofs, newton;
    double       energy;
    double       eta, eta_interior, eta_jumps, eta_neumann, eta_contact;
  };

  // Solve, estimate, write: what each cycle and each uniform level does.
  // The two studies share it, so that a uniform level and an adaptive
  // cycle are measured alike.
  template <int dim>
  CycleResult
  solve_and_estimate(AdaptiveContactProblem<dim> &problem, ErrorEstimate &e)
  {
    // The order of step-6: solve, then estimate on the same mesh; the caller
    // writes the files and refines.
    problem.solve();
    e = problem.estimate_error();
    return {problem.n_cells(),
            problem.n_dofs(),
            problem.newton_iterations,
            problem.energy(),
            e.total(),
            e.part(e.interior),
            e.part(e.jumps),
            e.part(e.neumann),
            e.part(e.contact)};
  }

  // The adaptive loop of step-6: solve, estimate, mark and refine, from
  // the L refined twice (48 cells), a fixed fraction 0.2 of the cells
  // refined in each cycle, @p n_cycles cycles. Each cycle writes its
  // files; the first line printed is the smallness condition on the
  // starting mesh.
  std::vector<CycleResult>
  adaptive_study(const LShapeData &data, const unsigned int n_cycles)
  {
    // The L refined twice, 48 cells: coarse enough that the first cycles show
    // where the estimate sends the refinement, and the same starting mesh as
    // the uniform study, so that both tables begin with the same row.
    AdaptiveContactProblem<2> problem(data, 2);
    const double              lambda_1 = problem.smallness_constant();
    std::cout << "alpha_nu = " << data.law.alpha << ", lambda_1 = " << lambda_1
              << (data.law.alpha < lambda_1 ?
                    " (alpha_nu < lambda_1: one solution)" :
                    " (alpha_nu >= lambda_1: maybe several solutions)")
              << std::endl;
    // The last cycle is not refined: its estimate is reported, but no
    // further mesh would be solved on.
    std::vector<CycleResult> results;
    for (unsigned int cycle = 0; cycle < n_cycles; ++cycle)
      {
        ErrorEstimate e;
        results.push_back(solve_and_estimate(problem, e));
        // The files of every cycle, the last and finest included.
        problem.output_results(cycle, e);
        if (cycle + 1 < n_cycles)
          problem.refine_mesh(e.cell_values(), 0.2);
      }
    // The branches of the last mesh, the finest of the loop: the line that
    // tells the reader which contact conditions the adapted meshes resolve.
    const auto counts = problem.branch_counts();
    std::cout << "cycle " << n_cycles - 1
              << ": normal separating/stick/penetrating " << counts[0] << '/'
              << counts[1] << '/' << counts[2] << ", tangential stick/slip "
              << counts[3] << '/' << counts[4] << std::endl;
    return results;
  }

  // Uniform refinement from the same mesh: level $l$ refines the L $2 + l$
  // times, a new problem each (as step-1's convergence study does).
  std::vector<CycleResult>
  uniform_study(const LShapeData &data, const unsigned int n_levels)
  {
    std::vector<CycleResult> results;
    for (unsigned int level = 0; level < n_levels; ++level)
      {
        // A new problem per level, started from zero, as step-1's convergence
        // study does: the uniform levels are independent of one another, and
        // their Newton counts show what a start from zero costs.
        AdaptiveContactProblem<2> problem(data, 2 + level);
        ErrorEstimate             e;
        results.push_back(solve_and_estimate(problem, e));
      }
    return results;
  }

  // @sect4{The error and the tables}

  // The error in the energy norm, measured by the energy (the
  // introduction, "Measuring the error"): $E_J = (2(J_h(u_h) -
  // J_\text{ref}))^{1/2}$, with $J_\text{ref}$ the energy of a much finer
  // solution. If $J_h(u_h) \le J_\text{ref}$, the reference is not finer
  // than the mesh at hand and $E_J$ is undefined: we return NaN, the
  // tables show such a row without $E_J$, and main() says why and stops
  // after printing and writing every row.
  double
  energy_error(const double J, const double J_reference)
  {
    return J > J_reference ? std::sqrt(2 * (J - J_reference)) :
                             std::numeric_limits<double>::quiet_NaN();
  }

  // The rows of a study in full precision, for the figure
  // (doc/plot_convergence.py) and the comparison with the full program:
  // the mesh, the Newton iterations, $J_h(u_h)$, $E_J$, $\eta$ and its four
  // parts, and the effectivity index $\eta/E_J$. Without a reference
  // (@p J_reference not finite: the mode "adaptive"), or where $E_J$ is
  // undefined, the columns of $E_J$ and of the effectivity are empty.
  void
  write_csv(const std::vector<CycleResult> &rows,
            const double                    J_reference,
            const std::string              &filename)
  {
    // Seventeen digits, as in displacement-NN.txt: the test against the full
    // program compares the energies and estimates at $10^{-10}$.
    std::ofstream csv(filename);
    AssertThrow(csv, ExcIO());
    csv << "cycle,cells,dofs,newton,energy,error,estimate,estimate_interior,"
           "estimate_jumps,estimate_neumann,estimate_contact,effectivity\n"
        << std::setprecision(17);
    for (unsigned int k = 0; k < rows.size(); ++k)
      {
        const CycleResult &r = rows[k];
        const double       E = energy_error(r.energy, J_reference);
        csv << k << ',' << r.cells << ',' << r.dofs << ',' << r.newton << ','
            << r.energy << ',';
        if (std::isfinite(E))
          csv << E;
        csv << ',' << r.eta << ',' << r.eta_interior << ',' << r.eta_jumps
            << ',' << r.eta_neumann << ',' << r.eta_contact << ',';
        if (std::isfinite(E))
          csv << r.eta / E;
        csv << '\n';
      }
  }

  // One table on the terminal: per row the mesh, the Newton iterations,
  // $E_J$ and its rate against the number of unknowns $n_\text{dofs}$,
  // $p = \log(E_{J,j-1}/E_{J,j}) / \log(n_{\text{dofs},j}/n_{\text{dofs},j-1})$
  // between rows $j - 1$ and $j$ (so that $E_J \sim n_\text{dofs}^{-p}$;
  // $p = 1/2$ is the rate of $Q_1$ for a smooth solution in 2D),
  // the estimate $\eta$ with its rate, and the effectivity index
  // $\eta/E_J$; then the rate over the whole table. A row whose $E_J$ is
  // undefined (energy_error()) shows "undefined", and "-" for the numbers
  // made from it.
  void
  print_table(const std::string              &title,
              const std::string              &row_name,
              const std::vector<CycleResult> &rows,
              const double                    J_reference)
  {
    std::cout << '\n'
              << title << '\n'
              << row_name
              << " cells  dofs Newton    E_J     rate    eta     rate "
                 "effectivity\n";
    for (unsigned int k = 0; k < rows.size(); ++k)
      {
        // The row and its error; the error is undefined (NaN) where the energy
        // is not above the reference's, and then printed as "undefined".
        const CycleResult &r = rows[k];
        const double       E = energy_error(r.energy, J_reference);
        // The rates against the row before; the first row has none, and
        // shows "-" in their place, as deal.II's ConvergenceTable does.
        char rate_E[8] = "  - ", rate_eta[8] = "  - ";
        if (k > 0)
          {
            const CycleResult &p        = rows[k - 1];
            const double       E_before = energy_error(p.energy, J_reference);
            const double       dN       = std::log(double(r.dofs) / p.dofs);
            if (std::isfinite(E) && std::isfinite(E_before))
              std::snprintf(rate_E,
                            sizeof(rate_E),
                            "%4.2f",
                            std::log(E_before / E) / dN);
            std::snprintf(rate_eta,
                          sizeof(rate_eta),
                          "%4.2f",
                          std::log(p.eta / r.eta) / dN);
          }
        char error[16] = "undefined", effectivity[16] = "    -";
        if (std::isfinite(E))
          {
            std::snprintf(error, sizeof(error), "%9.3e", E);
            std::snprintf(effectivity, sizeof(effectivity), "%5.2f", r.eta / E);
          }
        // One line per row, in the fixed columns the results page shows.
        char line[160];
        std::snprintf(line,
                      sizeof(line),
                      "%5u %5u %5u %6u %s %s %9.3e %s    %s",
                      k,
                      r.cells,
                      r.dofs,
                      r.newton,
                      error,
                      rate_E,
                      r.eta,
                      rate_eta,
                      effectivity);
        std::cout << line << '\n';
      }
    // The rate over the whole table, from its first row to its last.
    const CycleResult &first = rows.front(), &last = rows.back();
    const double       dN         = std::log(double(last.dofs) / first.dofs);
    const double       E_first    = energy_error(first.energy, J_reference);
    const double       E_last     = energy_error(last.energy, J_reference);
    char               rate_E[16] = "-";
    if (std::isfinite(E_first) && std::isfinite(E_last))
      std::snprintf(rate_E,
                    sizeof(rate_E),
                    "%4.2f",
                    std::log(E_first / E_last) / dN);
    std::printf("rate from %s 0 to %u: E_J %s, eta %4.2f\n",
                row_name.c_str(),
                static_cast<unsigned int>(rows.size() - 1),
                rate_E,
                std::log(first.eta / last.eta) / dN);
    std::cout << std::flush;
  }
} // namespace Step4

// @sect3{The command line}

// The program runs everything without arguments, or one part by its mode,
// as the usage says. Its check is one table and one test in main(): the
// table names each mode and how many arguments it takes, itself included
// (the empty mode is the run without arguments); the test refuses an
// unknown mode, a surplus argument and a number of cycles that is not one
// to three decimal digits from 1 to max_cycles (std::stoul() alone would
// read "3x" as 3 and "-1" as four billion). A bad command line ends the
// program before anything is computed, with a message that quotes the
// arguments, the usage and the exit code 2 (1 is kept for a computation
// that fails).
namespace CommandLine
{
  const char *const usage =
    "usage: step-4                    the reference solution, then the\n"
    "                                 uniform and the adaptive tables\n"
    "       step-4 adaptive CYCLES    CYCLES (1 to 16) cycles of the\n"
    "                                 adaptive loop, without the errors\n"
    "       step-4 --help             this text\n"
    "exit codes: 0 done, 1 the computation failed, 2 a bad argument";

  const std::map<std::string, std::size_t> modes = {{"", 0},
                                                    {"adaptive", 2},
                                                    {"--help", 1}};

  // Each cycle refines a fifth of the cells, about 1.6 times the unknowns of
  // the cycle before and, with the direct solver, about twice the time: 16
  // cycles end at 121,872 unknowns after about 20 s, and the cap keeps a typo
  // from running for an hour or exhausting the memory.
  const unsigned int max_cycles = 16;
} // namespace CommandLine

// @sect3{The main function}

// Without arguments: the adaptive loop run far beyond the table, to a
// fine mesh whose energy is the reference $J_\text{ref}$; then the
// uniform levels and the first cycles of the same adaptive loop, each
// with its error against that reference. The mode "adaptive CYCLES" runs
// the loop alone and writes its files (the comparison with the full
// program uses it).
int
main(int argc, char **argv)
{
  using namespace Step4;
  const std::vector<std::string> arguments(argv + 1, argv + argc);
  const std::string              mode = arguments.empty() ? "" : arguments[0];
  // The number of cycles: the mode "adaptive" needs one (without it the
  // test refuses the empty text), the other modes take none ("1" passes).
  const std::string cycles = arguments.size() == 2 ? arguments[1] :
                             mode == "adaptive"    ? "" :
                                                     "1";
  // A bad command line ends here, before any output file is opened, and
  // so does --help.
  if ((!arguments.empty() && mode.empty()) ||
      CommandLine::modes.count(mode) == 0 ||
      arguments.size() > CommandLine::modes.at(mode) || cycles.empty() ||
      cycles.size() > 3 ||
      cycles.find_first_not_of("0123456789") != std::string::npos ||
      std::stoul(cycles) < 1 || std::stoul(cycles) > CommandLine::max_cycles)
    {
      std::cerr << "step-4: cannot run";
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
  // 0 cycles: the default run, the reference and the two tables.
  const unsigned int n_cycles = mode == "adaptive" ? std::stoul(cycles) : 0;

  try
    {
      // One problem for both modes: the L-shaped body with its load.
      const LShapeData data;
      // The mode "adaptive CYCLES": the loop alone, no reference, no errors.
      if (n_cycles > 0)
        {
          // The loop alone, its rows in adaptive.csv without errors.
          const auto rows = adaptive_study(data, n_cycles);
          write_csv(rows,
                    std::numeric_limits<double>::quiet_NaN(),
                    "adaptive.csv");
          // One line per cycle, with the energy in full and the estimate: what
          // the comparison with the full program reads.
          std::printf("cycle cells  dofs Newton    J_h        eta\n");
          for (unsigned int k = 0; k < rows.size(); ++k)
            std::printf("%5u %5u %5u %6u %.6e %9.3e\n",
                        k,
                        rows[k].cells,
                        rows[k].dofs,
                        rows[k].newton,
                        rows[k].energy,
                        rows[k].eta);
          return 0;
        }

      // The default run. The reference: 15 cycles of the adaptive loop
      // (0 to 14), the last with about fifteen times the unknowns of the
      // last cycle of the table (cycle 8), and so an error about four
      // times smaller; the introduction ("Measuring the error") says what
      // this costs the error of the table. The table's cycles are the
      // first cycles of the same loop, so the adaptive loop runs once.
      // The CPU time of the whole run goes to standard error, so that
      // standard output, which the results page shows, is the same on
      // every machine.
      Timer                          timer;
      const unsigned int             n_table_cycles = 9, n_reference = 15;
      const std::vector<CycleResult> all = adaptive_study(data, n_reference);
      // The energy of the last cycle, on the finest mesh, is the reference.
      const double J_reference = all.back().energy;
      // The reference's own estimate is printed too: against the estimate
      // of the table's last cycle it says how much smaller the reference's
      // error is.
      std::cout << "reference: cycle " << n_reference - 1 << ", "
                << all.back().dofs << " dofs, J_ref = " << std::setprecision(12)
                << J_reference << std::setprecision(4)
                << ", eta = " << all.back().eta << std::setprecision(6)
                << std::endl;
      // The adaptive table is the first nine cycles of the same run: the loop
      // runs once, and its first cycles are measured against its last.
      const std::vector<CycleResult> adaptive(all.begin(),
                                              all.begin() + n_table_cycles);
      // Four uniform levels, up to 6,402 unknowns: about as many as cycle 8 of
      // the adaptive table, so that the two tables end at a comparable size.
      const std::vector<CycleResult> uniform = uniform_study(data, 4);
      // Both tables on the terminal, with the rates against the unknowns, and
      // then in full precision in the CSV files, for the figure and for the
      // comparison with the full program.
      print_table("Uniform refinement (E_J, eta, rates against the dofs)",
                  "level",
                  uniform,
                  J_reference);
      // (the adaptive rows are measured with the same reference and the same
      // rates as the uniform ones, so that the two tables compare line by line)
      print_table("Adaptive refinement (E_J, eta, rates against the dofs)",
                  "cycle",
                  adaptive,
                  J_reference);
      write_csv(uniform, J_reference, "uniform.csv");
      write_csv(adaptive, J_reference, "adaptive.csv");
      std::cerr << "step-4: " << timer.cpu_time() << " s CPU time" << std::endl;

      // A row with an energy not above the reference's has no $E_J$: the
      // reference is not finer than that row's mesh, e.g. when a marking
      // grows the mesh too slowly for 15 cycles to outrun the uniform
      // levels. Every row is printed and written above; we name those
      // rows and stop with exit code 1.
      std::string undefined;
      for (const auto &[name, rows] :
           {std::make_pair("uniform level ", &uniform),
            std::make_pair("adaptive cycle ", &adaptive)})
        for (unsigned int k = 0; k < rows->size(); ++k)
          if (!std::isfinite(energy_error((*rows)[k].energy, J_reference)))
            undefined += (undefined.empty() ? "" : ", ") + std::string(name) +
                         std::to_string(k) + " (" +
                         std::to_string((*rows)[k].dofs) + " dofs)";
      if (!undefined.empty())
        {
          std::cerr << "step-4: E_J is undefined for " << undefined
                    << ": the energy there is not above J_ref of the "
                       "reference (cycle "
                    << n_reference - 1 << ", " << all.back().dofs
                    << " dofs), which is therefore not finer than those "
                       "meshes. The tables above and uniform.csv, "
                       "adaptive.csv hold every row; a reference from more "
                       "cycles, or a marking that refines more per cycle, "
                       "defines E_J."
                    << std::endl;
          return 1;
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
