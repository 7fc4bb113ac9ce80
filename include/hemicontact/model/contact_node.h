#pragma once

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/base/types.h>

#include <hemicontact/laws/friction_law.h>
#include <hemicontact/laws/normal_law.h>

#include <array>
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
    damped     = 2  ///< s + c w_nu > a: s = a plus the remainder p(w_nu)
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
    NormalBranch     normal_branch     = NormalBranch::separating;
    TangentialBranch tangential_branch = TangentialBranch::stick;
  };

  /**
   * The state of a contact node at an iterate: the velocity in normal and
   * tangential components, and the multipliers of the laws' convex parts
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

    /** Branch from s + c w_nu against [0, a]. */
    template <int dim>
    NormalBranch
    normal_branch(const ContactNode<dim> &node,
                  const NodeState<dim>   &m,
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

    /** Complementarity function s - P_[0,a](s + c w_nu) (a traction). */
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
     * work is zero whatever the multiplier.
     */
    template <int dim>
    std::pair<double, double>
    contact_work(const ContactNode<dim> &node,
                 const Tensor<1, dim>   &velocity,
                 const NormalLaw        &law,
                 const FrictionLaw      &friction);

    /**
     * Unit vectors of the directions on which the node's constrained
     * branches impose w . e = 0 (normal stick: nu; tangential stick: the
     * tangent plane).
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
