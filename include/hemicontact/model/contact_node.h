#pragma once

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/base/types.h>

#include <hemicontact/laws/friction_law.h>
#include <hemicontact/laws/normal_law.h>

#include <array>
#include <limits>
#include <utility>
#include <vector>

namespace hemicontact
{
  using namespace dealii;

  /** Normal branch of a contact node (doc/theory.md section 3). */
  enum class NormalBranch : unsigned char
  {
    separating = 0, ///< s + c w_nu < 0: s = 0, w_nu free
    stick      = 1, ///< 0 <= s + c w_nu <= a: w_nu = 0
    damped     = 2, ///< s + c w_nu > a: s = a plus the remainder p(w_nu)
    breakpoint = 3, ///< held at a convex kink r_j of the law: w_nu = r_j
    wall       = 4  ///< held at the wall: w_nu = the node's upper limit
  };

  /** Tangential branch of a contact node. */
  enum class TangentialBranch : unsigned char
  {
    stick = 0, ///< |lambda + c w_tau| <= F_b: w_tau = 0
    slip  = 1  ///< lambda = F_b (lambda + c w_tau)/|lambda + c w_tau|
  };

  /**
   * One node x_i of Gamma_3 with everything the node-wise contact
   * conditions need: its dofs (one per component), the nodal normal and
   * lumped boundary mass m_i = int phi_i computed from the mesh, the
   * friction bound, the projection constant c_i, and its current branches.
   */
  template <int dim>
  struct ContactNode
  {
    std::array<types::global_dof_index, dim> dofs;
    Point<dim>                               position;
    Tensor<1, dim>                           normal;
    double                                   mass           = 0;
    double                                   friction_bound = 0;
    double                                   c              = 1;
    bool                                     locally_owned  = false;
    /**
     * The wall in the step's unknown, w_nu <= upper_limit (g in the static
     * class, (g - u_nu)/k in the velocity classes; +inf without a wall).
     */
    double upper_limit = std::numeric_limits<double>::infinity();
    /**
     * The shift of the normal law's argument: the law acts on
     * w_nu - law_offset (the wear depth in the static class, doc/theory.md
     * section 11.12; zero otherwise). upper_limit and held_value are in
     * w_nu itself.
     */
    double law_offset = 0;
    /** w_nu on the branches that hold it (stick, breakpoint, wall). */
    double           held_value        = 0;
    NormalBranch     normal_branch     = NormalBranch::separating;
    TangentialBranch tangential_branch = TangentialBranch::stick;
  };

  /**
   * The state of a contact node at an iterate: the velocity in normal and
   * tangential components (the normal one as the law's argument,
   * w_nu - law_offset), and the multipliers of the laws' convex parts
   * (normal s, tangential lambda) from the nodal contact force
   * G = m_i (s nu + p(w_nu) nu + lambda + r(|w_tau|) w_tau/|w_tau|)
   * = -(K w - b)_i.
   */
  template <int dim>
  struct NodeState
  {
    double         s;
    Tensor<1, dim> lambda;
    double         w_normal;
    Tensor<1, dim> w_tangential;
  };

  /** The linearised nodal contact force: force + matrix (w - w_k). */
  template <int dim>
  struct NodeLinearization
  {
    Tensor<2, dim> matrix;
    Tensor<1, dim> force;
  };

  /** The nodal unknown of @p node in the global vector @p v (owned or
   *  ghosted entries). */
  template <int dim, class VectorType>
  Tensor<1, dim>
  nodal_vector(const ContactNode<dim> &node, const VectorType &v)
  {
    Tensor<1, dim> x;
    for (unsigned int c = 0; c < dim; ++c)
      x[c] = v[node.dofs[c]];
    return x;
  }

  /** The pure, node-wise pieces of the active-set method (nodal::). */
  namespace nodal
  {
    /**
     * Split velocity and contact force G into normal/tangential parts and
     * take off the laws' remainders, leaving the convex parts' multipliers.
     */
    template <int dim>
    NodeState<dim>
    state(const ContactNode<dim> &node,
          const Tensor<1, dim>   &velocity,
          const Tensor<1, dim>   &force,
          const NormalLaw        &law,
          const FrictionLaw      &friction);

    /**
     * A point where w_nu can be held: position, the interval [lower, upper]
     * of the convex part's multiplier s there, and the branch.
     */
    struct HoldPoint
    {
      double       position;
      double       lower;
      double       upper;
      NormalBranch branch;
    };

    /**
     * The node's hold points in increasing position: r = 0 (the jump
     * [0, a]), the law's kinks below the wall, and the wall at
     * node.upper_limit (doc/theory.md section 10), as values of the law's
     * argument w_nu - node.law_offset. Between them w_nu is free.
     */
    template <int dim>
    std::vector<HoldPoint>
    hold_points(const ContactNode<dim> &node, const NormalLaw &law);

    /** The normal branch and the w_nu it holds (0 where it holds none). */
    struct NormalHold
    {
      NormalBranch branch;
      double       value;
    };

    /**
     * Branch from q = s + c w_nu against the path of the convex part's
     * graph: held at a hold point x where lower + c x <= q <= upper + c x,
     * free between them (doc/theory.md section 10; with the one hold point r =
     * 0 this is q against [0, a]).
     */
    template <int dim>
    NormalHold
    normal_hold(const ContactNode<dim> &node,
                const NodeState<dim>   &m,
                const NormalLaw        &law);

    /** The branch of normal_hold(). */
    template <int dim>
    NormalBranch
    normal_branch(const ContactNode<dim> &node,
                  const NodeState<dim>   &m,
                  const NormalLaw        &law);

    /**
     * The reaction of the wall at a node held there, -sigma_nu minus the
     * law's response left of the wall (>= 0 at a solution); zero on the
     * other branches. @p normal_traction is -sigma_nu.
     */
    template <int dim>
    double
    wall_reaction(const ContactNode<dim> &node,
                  const double            normal_traction,
                  const NormalLaw        &law);

    /**
     * The normal branch a Newton iteration (after the first of a step)
     * uses when the complementarity function moves a node from @p current
     * to @p predicted: the prediction, except that a jump between
     * separating and damped passes through normal stick, the branch between
     * them. Without this, groups of nodes at the edge of a lifting contact
     * zone can alternate between free and damped for several iterations.
     * Near a solution the two branches are never adjacent (the gap a > 0
     * lies between them), so the converged branches are the
     * complementarity function's own. A law without a jump (a = 0) has no
     * branch between them: the prediction is returned.
     */
    NormalBranch
    gradual_normal_branch(const NormalBranch current,
                          const NormalBranch predicted,
                          const NormalLaw   &law);

    /** Branch from |lambda + c w_tau| against F_b. */
    template <int dim>
    TangentialBranch
    tangential_branch(const ContactNode<dim> &node, const NodeState<dim> &m);

    /**
     * Complementarity function s - P(s + c w_nu) (a traction), P the
     * projection onto the convex part's graph (P_[0,a] without kinks and
     * wall).
     */
    template <int dim>
    double
    normal_complementarity(const ContactNode<dim> &node,
                           const NodeState<dim>   &m,
                           const NormalLaw        &law);

    /** lambda - P_{|.|<=F_b}(lambda + c w_tau) (a traction). */
    template <int dim>
    Tensor<1, dim>
    tangential_complementarity(const ContactNode<dim> &node,
                               const NodeState<dim>   &m);

    /**
     * Linearised nodal force m_i (traction) of the free branches (damped,
     * slip) about the current iterate; zero for constrained branches. The
     * slip tangent is the condensed semismooth-Newton tangent of the
     * friction disk, which at a solution is the Hessian of F_b |w_tau|,
     * plus the Hessian of the friction law's remainder R(|w_tau|).
     */
    template <int dim>
    NodeLinearization<dim>
    linearize(const ContactNode<dim> &node,
              const NodeState<dim>   &m,
              const NormalLaw        &law,
              const FrictionLaw      &friction);

    /**
     * The nodal part of J_n: m_i [ j(w_nu) + F_b |w_tau| + R(|w_tau|) ].
     */
    template <int dim>
    double
    energy(const ContactNode<dim> &node,
           const Tensor<1, dim>   &velocity,
           const NormalLaw        &law,
           const FrictionLaw      &friction);

    /**
     * The work rates m_i xi_nu w_nu (normal) and m_i xi_tau . w_tau
     * (friction) of the laws' contact forces xi at @p velocity: what the
     * energy balance books as dissipated. Where w_nu = 0 or w_tau = 0 the
     * work is zero whatever the multiplier; at a breakpoint or the wall
     * xi_nu is the solution's @p normal_traction (-sigma_nu).
     */
    template <int dim>
    std::pair<double, double>
    contact_work(const ContactNode<dim> &node,
                 const Tensor<1, dim>   &velocity,
                 const double            normal_traction,
                 const NormalLaw        &law,
                 const FrictionLaw      &friction);

    /**
     * Unit vectors of the directions on which the node's constrained
     * branches impose w . e = const (normal stick, breakpoint, wall: nu,
     * w . nu = held_value; tangential stick: the tangent plane, w . e = 0).
     */
    template <int dim>
    std::vector<Tensor<1, dim>>
    constrained_directions(const ContactNode<dim> &node);

    /**
     * The orthogonal projector Pi_i onto the directions that the node's
     * constrained branches leave free: I minus the sum of e e over
     * constrained_directions().
     */
    template <int dim>
    Tensor<2, dim>
    free_projector(const ContactNode<dim> &node);

    /** An orthonormal basis of the plane orthogonal to @p normal. */
    template <int dim>
    std::array<Tensor<1, dim>, dim - 1>
    tangent_basis(const Tensor<1, dim> &normal);

  } // namespace nodal
} // namespace hemicontact
