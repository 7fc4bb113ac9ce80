#include <deal.II/base/symmetric_tensor.h>

#include <hemicontact/laws/friction_disk.h>
#include <hemicontact/model/contact_node.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace hemicontact
{
  namespace nodal
  {
    template <int dim>
    NodeState<dim>
    state(const ContactNode<dim> &node,
          const Tensor<1, dim>   &velocity,
          const Tensor<1, dim>   &force,
          const NormalLaw        &law,
          const FrictionLaw      &friction)
    {
      NodeState<dim>        m;
      const Tensor<1, dim> &nu      = node.normal;
      const double          w_nu    = velocity * nu;
      m.w_normal                    = w_nu - node.law_offset;
      m.w_tangential                = velocity - w_nu * nu;
      const Tensor<1, dim> traction = force / node.mass;
      m.s                           = traction * nu - law.remainder(m.w_normal);
      m.lambda                      = traction - (traction * nu) * nu;
      const double slip             = m.w_tangential.norm();
      if (slip > 0)
        m.lambda -=
          friction.remainder(node.friction_bound, slip) / slip * m.w_tangential;
      return m;
    }

    template <int dim>
    std::vector<HoldPoint>
    hold_points(const ContactNode<dim> &node, const NormalLaw &law)
    {
      std::vector<HoldPoint> points;
      // in the law's argument, w_nu - law_offset
      const double limit = node.upper_limit - node.law_offset;
      double       s     = 0;
      if (0 < limit)
        {
          points.push_back({0., 0., law.jump(), NormalBranch::stick});
          s = law.jump();
        }
      for (const NormalLaw::Kink &kink : law.kinks())
        if (kink.position < limit)
          {
            points.push_back(
              {kink.position, s, s + kink.jump, NormalBranch::breakpoint});
            s += kink.jump;
          }
      if (std::isfinite(limit))
        points.push_back({limit,
                          s,
                          std::numeric_limits<double>::infinity(),
                          NormalBranch::wall});
      return points;
    }

    namespace
    {
      /** normal_hold() together with P(q), the multiplier it projects to. */
      template <int dim>
      std::pair<NormalHold, double>
      project_on_path(const ContactNode<dim> &node,
                      const NodeState<dim>   &m,
                      const NormalLaw        &law)
      {
        const double                 q      = m.s + node.c * m.w_normal;
        const std::vector<HoldPoint> points = hold_points(node, law);
        for (const HoldPoint &point : points)
          {
            const double x = point.position;
            if (q < point.lower + node.c * x)
              return {{x <= 0 ? NormalBranch::separating : NormalBranch::damped,
                       0.},
                      point.lower};
            if (q <= point.upper + node.c * x)
              return {{point.branch, x}, q - node.c * x};
          }
        return {{NormalBranch::damped, 0.}, points.back().upper};
      }
    } // namespace

    template <int dim>
    NormalHold
    normal_hold(const ContactNode<dim> &node,
                const NodeState<dim>   &m,
                const NormalLaw        &law)
    {
      return project_on_path(node, m, law).first;
    }

    template <int dim>
    NormalBranch
    normal_branch(const ContactNode<dim> &node,
                  const NodeState<dim>   &m,
                  const NormalLaw        &law)
    {
      return normal_hold(node, m, law).branch;
    }

    template <int dim>
    double
    wall_reaction(const ContactNode<dim> &node,
                  const double            normal_traction,
                  const NormalLaw        &law)
    {
      if (node.normal_branch != NormalBranch::wall ||
          !std::isfinite(node.upper_limit))
        return 0.;
      const double limit = node.upper_limit - node.law_offset;
      return normal_traction - law.remainder(limit) -
             hold_points(node, law).back().lower;
    }

    NormalBranch
    gradual_normal_branch(const NormalBranch current,
                          const NormalBranch predicted,
                          const NormalLaw   &law)
    {
      const bool jumps =
        law.jump() > 0 && ((current == NormalBranch::separating &&
                            predicted == NormalBranch::damped) ||
                           (current == NormalBranch::damped &&
                            predicted == NormalBranch::separating));
      return jumps ? NormalBranch::stick : predicted;
    }

    template <int dim>
    TangentialBranch
    tangential_branch(const ContactNode<dim> &node, const NodeState<dim> &m)
    {
      return FrictionDisk::sticks(m.lambda + node.c * m.w_tangential,
                                  node.friction_bound) ?
               TangentialBranch::stick :
               TangentialBranch::slip;
    }

    template <int dim>
    double
    normal_complementarity(const ContactNode<dim> &node,
                           const NodeState<dim>   &m,
                           const NormalLaw        &law)
    {
      return m.s - project_on_path(node, m, law).second;
    }

    template <int dim>
    Tensor<1, dim>
    tangential_complementarity(const ContactNode<dim> &node,
                               const NodeState<dim>   &m)
    {
      return m.lambda -
             FrictionDisk::project(m.lambda + node.c * m.w_tangential,
                                   node.friction_bound);
    }

    template <int dim>
    NodeLinearization<dim>
    linearize(const ContactNode<dim> &node,
              const NodeState<dim>   &m,
              const NormalLaw        &law,
              const FrictionLaw      &friction)
    {
      NodeLinearization<dim> lin;
      const Tensor<1, dim>  &nu = node.normal;
      if (node.normal_branch == NormalBranch::damped)
        {
          // the multiplier of the free segment the node is on, plus p
          const double s = project_on_path(node, m, law).second;
          lin.force += node.mass * (s + law.remainder(m.w_normal)) * nu;
          lin.matrix += node.mass * law.remainder_derivative(m.w_normal) *
                        outer_product(nu, nu);
        }
      if (node.tangential_branch == TangentialBranch::slip)
        {
          const Tensor<1, dim> q  = m.lambda + node.c * m.w_tangential;
          const double         qn = q.norm();
          const Tensor<1, dim> d  = q / qn;
          // Newton for lambda = F_b q/|q| (q = lambda + c w_tau), with lambda
          // condensed out: lambda_new = F_b d + T/m_i w_tau, where
          // T = m_i F_b c/(|q| - F_b) (I - nu nu - d d). At a solution
          // |q| - F_b = c|w_tau| and w_tau || d, so T is the Hessian
          // F_b/|w_tau| (I - t t) of F_b |w_tau| and the force is F_b t.
          // T is symmetric positive semidefinite; the floor on |q| - F_b
          // bounds it by 100 m_i c for nodes that barely slip.
          const double   excess = std::max(qn - node.friction_bound, 1e-2 * qn);
          Tensor<2, dim> tangent_projector = unit_symmetric_tensor<dim>();
          tangent_projector -= outer_product(nu, nu) + outer_product(d, d);
          const Tensor<2, dim> tangent = node.mass * node.friction_bound *
                                         node.c / excess * tangent_projector;
          lin.matrix += tangent;
          lin.force +=
            node.mass * node.friction_bound * d + tangent * m.w_tangential;

          // the law's remainder r(s) e, s = |w_tau|, e = w_tau/s (d while
          // w_tau = 0): force m_i r(s) e, Hessian
          // m_i [r'(s) e e + r(s)/s (I - nu nu - e e)]
          const double         slip   = m.w_tangential.norm();
          const Tensor<1, dim> e      = slip > 0 ? m.w_tangential / slip : d;
          const double         bound  = node.friction_bound;
          Tensor<2, dim>       across = unit_symmetric_tensor<dim>();
          across -= outer_product(nu, nu) + outer_product(e, e);
          lin.matrix +=
            node.mass *
            (friction.remainder_derivative(bound, slip) * outer_product(e, e) +
             friction.remainder_over_slip(bound, slip) * across);
          lin.force += node.mass * friction.remainder(bound, slip) * e;
        }
      return lin;
    }

    template <int dim>
    double
    energy(const ContactNode<dim> &node,
           const Tensor<1, dim>   &velocity,
           const NormalLaw        &law,
           const FrictionLaw      &friction)
    {
      const double         wn = velocity * node.normal;
      const Tensor<1, dim> wt = velocity - wn * node.normal;
      return node.mass * (law.potential(wn - node.law_offset) +
                          friction.potential(node.friction_bound, wt.norm()));
    }

    template <int dim>
    std::pair<double, double>
    contact_work(const ContactNode<dim> &node,
                 const Tensor<1, dim>   &velocity,
                 const double            normal_traction,
                 const NormalLaw        &law,
                 const FrictionLaw      &friction)
    {
      const double wn   = velocity * node.normal;
      const double slip = (velocity - wn * node.normal).norm();
      const bool   held_away_from_zero =
        node.normal_branch == NormalBranch::breakpoint ||
        node.normal_branch == NormalBranch::wall;
      const double xi_nu = held_away_from_zero ?
                             normal_traction :
                             law.subgradient(wn - node.law_offset);
      return {node.mass * xi_nu * wn,
              slip > 0 ? node.mass *
                           friction.response(node.friction_bound, slip) * slip :
                         0.};
    }

    template <int dim>
    std::array<Tensor<1, dim>, dim - 1>
    tangent_basis(const Tensor<1, dim> &normal)
    {
      std::array<Tensor<1, dim>, dim - 1> t;
      if constexpr (dim == 2)
        {
          t[0][0] = -normal[1];
          t[0][1] = normal[0];
        }
      else
        {
          // the coordinate axis least aligned with the normal
          unsigned int axis = 0;
          for (unsigned int d = 1; d < dim; ++d)
            if (std::abs(normal[d]) < std::abs(normal[axis]))
              axis = d;
          Tensor<1, dim> e;
          e[axis] = 1;
          t[0]    = e - (e * normal) * normal;
          t[0] /= t[0].norm();
          t[1] = cross_product_3d(normal, t[0]);
        }
      return t;
    }

    template <int dim>
    std::vector<Tensor<1, dim>>
    constrained_directions(const ContactNode<dim> &node)
    {
      std::vector<Tensor<1, dim>> directions;
      if (node.normal_branch == NormalBranch::stick ||
          node.normal_branch == NormalBranch::breakpoint ||
          node.normal_branch == NormalBranch::wall)
        directions.push_back(node.normal);
      if (node.tangential_branch == TangentialBranch::stick)
        for (const Tensor<1, dim> &t : tangent_basis(node.normal))
          directions.push_back(t);
      return directions;
    }

    template <int dim>
    Tensor<2, dim>
    free_projector(const ContactNode<dim> &node)
    {
      Tensor<2, dim> projector = unit_symmetric_tensor<dim>();
      for (const Tensor<1, dim> &e : constrained_directions(node))
        projector -= outer_product(e, e);
      return projector;
    }

#define HEMICONTACT_INSTANTIATE(dim)                                           \
  template NodeState<dim>         state(const ContactNode<dim> &,              \
                                        const Tensor<1, dim> &,                \
                                        const Tensor<1, dim> &,                \
                                        const NormalLaw &,                     \
                                        const FrictionLaw &);                  \
  template std::vector<HoldPoint> hold_points(const ContactNode<dim> &,        \
                                              const NormalLaw &);              \
  template NormalHold             normal_hold(const ContactNode<dim> &,        \
                                              const NodeState<dim> &,          \
                                              const NormalLaw &);              \
  template double                 wall_reaction(const ContactNode<dim> &,      \
                                                const double,                  \
                                                const NormalLaw &);            \
  template NormalBranch           normal_branch(const ContactNode<dim> &,      \
                                                const NodeState<dim> &,        \
                                                const NormalLaw &);            \
  template TangentialBranch       tangential_branch(const ContactNode<dim> &,  \
                                                    const NodeState<dim> &);   \
  template double         normal_complementarity(const ContactNode<dim> &,     \
                                                 const NodeState<dim> &,       \
                                                 const NormalLaw &);           \
  template Tensor<1, dim> tangential_complementarity(const ContactNode<dim> &, \
                                                     const NodeState<dim> &);  \
  template NodeLinearization<dim>    linearize(const ContactNode<dim> &,       \
                                               const NodeState<dim> &,         \
                                               const NormalLaw &,              \
                                               const FrictionLaw &);           \
  template double                    energy(const ContactNode<dim> &,          \
                                            const Tensor<1, dim> &,            \
                                            const NormalLaw &,                 \
                                            const FrictionLaw &);              \
  template std::pair<double, double> contact_work(const ContactNode<dim> &,    \
                                                  const Tensor<1, dim> &,      \
                                                  const double,                \
                                                  const NormalLaw &,           \
                                                  const FrictionLaw &);        \
  template std::array<Tensor<1, dim>, dim - 1> tangent_basis(                  \
    const Tensor<1, dim> &);                                                   \
  template std::vector<Tensor<1, dim>> constrained_directions(                 \
    const ContactNode<dim> &);                                                 \
  template Tensor<2, dim> free_projector(const ContactNode<dim> &);

    HEMICONTACT_INSTANTIATE(2)
    HEMICONTACT_INSTANTIATE(3)
#undef HEMICONTACT_INSTANTIATE
  } // namespace nodal
} // namespace hemicontact
