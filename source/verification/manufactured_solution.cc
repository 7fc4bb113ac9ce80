#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/utilities.h>
#include <deal.II/lac/vector.h>

#include <hemicontact/base/exceptions.h>
#include <hemicontact/verification/manufactured_solution.h>
#include <hemicontact/verification/tape_at_points.h>

#include <cmath>

namespace hemicontact
{
  namespace
  {
    std::vector<Expression>
    parse_vector(const std::string                   &text,
                 const int                            dim,
                 const std::map<std::string, double> &constants,
                 const std::string                   &name)
    {
      std::vector<std::string> parts = Utilities::split_string_list(text, ';');
      if (parts.size() == 1 && dim > 1)
        parts.assign(dim, parts[0]);
      require(static_cast<int>(parts.size()) == dim,
              "manufactured solution: '" + name + "' needs " +
                std::to_string(dim) + " expressions separated by ';'.");
      std::vector<Expression> result;
      for (const std::string &part : parts)
        result.emplace_back(part,
                            space_time_variables(dim),
                            constants,
                            "manufactured solution/" + name);
      return result;
    }
  } // namespace

  template <int dim>
  ManufacturedSolution<dim>::ManufacturedSolution(const Parameters  &parameters,
                                                  const NormalLaw   &law,
                                                  const FrictionLaw &friction)
    : law(law)
    , friction(friction)
    , material(
        StepScheme(parameters.problem).class_material(parameters.material))
    , inertia_density(
        StepScheme(parameters.problem).inertia_density(material.density()))
  {
    const auto constants = parse_constants(parameters.data.constants);
    const ManufacturedParameters &m = parameters.manufactured;
    displacement =
      parse_vector(m.exact_displacement, dim, constants, "exact displacement");
    normal_multiplier =
      std::make_unique<Expression>(m.normal_multiplier,
                                   space_time_variables(dim),
                                   constants,
                                   "manufactured solution/normal multiplier");
    tangential_multiplier = parse_vector(m.tangential_multiplier,
                                         dim,
                                         constants,
                                         "tangential multiplier");
    friction_bound =
      std::make_shared<FrictionBound<dim>>(parameters.data.friction_bound,
                                           parameters.data.constants);
    if (parameters.relaxation.active())
      relaxation =
        std::make_unique<RelaxationKernel>(parameters.relaxation,
                                           parameters.data.constants);
    if (parameters.normal_memory.active())
      normal_memory =
        std::make_unique<NormalMemoryKernel>(parameters.normal_memory,
                                             parameters.data.constants);
    for (int c = 0; c < dim; ++c)
      displacement_rate.push_back(displacement[c].derivative(dim));
    if (parameters.temperature.enabled)
      temperature = std::make_unique<ManufacturedTemperature<dim>>(parameters);

    // the derivatives, once: t is variable number dim; in the static class
    // the laws see u itself, which takes the place of w (doc/theory.md 9.7)
    const bool laws_on_displacement =
      StepScheme(parameters.problem).is_static();
    // in the velocity classes the wall bounds w_nu by (g - u_nu)/k with the
    // discrete u: no exact field sits at it (doc/theory.md section 10)
    require(laws_on_displacement || !std::isfinite(law.penetration_limit()),
            "manufactured solution: the normal law '" + law.name() +
              "' has a wall ('penetration limit'), which manufactured "
              "solutions support in the static class only ('problem/class "
              "= static'): in the velocity classes the wall bounds the "
              "step's velocity by (g - u_nu)/k with the discrete "
              "displacement, which no exact field can follow. Choose the "
              "static class or a law without a wall.");
    std::vector<Expression> displacement_again =
      laws_on_displacement ? parse_vector(m.exact_displacement,
                                          dim,
                                          constants,
                                          "exact displacement") :
                             std::vector<Expression>();
    for (int c = 0; c < dim; ++c)
      {
        velocity.push_back(laws_on_displacement ?
                             std::move(displacement_again[c]) :
                             displacement[c].derivative(dim));
        acceleration.push_back(velocity[c].derivative(dim));
        for (int i = 0; i < dim; ++i)
          {
            displacement_gradient.push_back(displacement[c].derivative(i));
            velocity_gradient.push_back(velocity[c].derivative(i));
          }
      }
    for (int c = 0; c < dim; ++c) // in the order (c dim + i) dim + j
      for (int i = 0; i < dim; ++i)
        for (int j = 0; j < dim; ++j)
          {
            displacement_hessian.push_back(
              displacement_gradient[c * dim + i].derivative(j));
            velocity_hessian.push_back(
              velocity_gradient[c * dim + i].derivative(j));
          }

    // the tapes, in the order unpack_fields() and evaluate() read them
    std::vector<const Expression *> fields;
    for (const auto *list :
         {&displacement, &velocity, &displacement_gradient, &velocity_gradient})
      for (const Expression &e : *list)
        fields.push_back(&e);
    // the time (variable dim) is the same at all points of a batch
    const std::vector<unsigned int> time = {dim};
    fields_tape = std::make_unique<ExpressionTape>(fields, time);
    std::vector<const Expression *> second_derivatives;
    for (const Expression &e : acceleration)
      second_derivatives.push_back(&e);
    for (int c = 0; c < dim; ++c)
      for (int i = 0; i < dim; ++i)
        for (int j = i; j < dim; ++j)
          {
            second_derivatives.push_back(
              &displacement_hessian[(c * dim + i) * dim + j]);
            second_derivatives.push_back(
              &velocity_hessian[(c * dim + i) * dim + j]);
          }
    force_tape = std::make_unique<ExpressionTape>(second_derivatives, time);
    std::vector<const Expression *> all = fields;
    all.insert(all.end(), second_derivatives.begin(), second_derivatives.end());
    all_tape = std::make_unique<ExpressionTape>(all, time);
  }

  namespace
  {
    /** u, w, grad u, grad w from the outputs of the fields tape. */
    template <int dim>
    void
    unpack_fields(const double                               *r,
                  typename ManufacturedSolution<dim>::Values &v)
    {
      for (int c = 0; c < dim; ++c)
        {
          v.u[c] = r[c];
          v.w[c] = r[dim + c];
          for (int i = 0; i < dim; ++i)
            {
              v.grad_u[c][i] = r[2 * dim + c * dim + i];
              v.grad_w[c][i] = r[2 * dim + dim * dim + c * dim + i];
            }
        }
    }
  } // namespace

  namespace
  {
    /** Div(2 mu eps(v) + lambda div v I)_i = mu lap v_i + (mu + lambda)
     *  d_i div v from the Hessian @p h of v ([component][i][j]). */
    template <int dim>
    Tensor<1, dim>
    isotropic_stress_divergence(const Tensor<3, dim> &h,
                                const double          mu,
                                const double          lambda)
    {
      Tensor<1, dim> result;
      for (int i = 0; i < dim; ++i)
        for (int j = 0; j < dim; ++j)
          result[i] += mu * h[i][j][j] + (mu + lambda) * h[j][i][j];
      return result;
    }
  } // namespace

  template <int dim>
  std::vector<std::pair<double, double>>
  ManufacturedSolution<dim>::memory_quadrature(const double t) const
  {
    // 8-point Gauss-Legendre on pieces of length at most 1/8: for smooth u
    // and kernels with relaxation times down to about 0.01 the quadrature
    // error stays far below the discretisation errors measured
    const QGauss<1>    gauss(8);
    const unsigned int n_pieces =
      std::max(1u, static_cast<unsigned int>(std::ceil(8 * t - 1e-12)));
    const double                           piece = t / n_pieces;
    std::vector<std::pair<double, double>> nodes;
    for (unsigned int i = 0; i < n_pieces; ++i)
      for (unsigned int q = 0; q < gauss.size(); ++q)
        nodes.emplace_back((i + gauss.point(q)[0]) * piece,
                           gauss.weight(q) * piece);
    return nodes;
  }

  template <int dim>
  SymmetricTensor<2, dim>
  ManufacturedSolution<dim>::memory_stress(const Point<dim> &p,
                                           const double      t) const
  {
    SymmetricTensor<2, dim> m;
    if (!relaxation || t <= 0)
      return m;
    for (const auto &[s, weight] : memory_quadrature(t))
      {
        const auto [mu, lambda] = (*relaxation)(t - s);
        const SymmetricTensor<2, dim> eps_u =
          symmetrize(evaluate_fields(std::vector<Point<dim>>{p}, s)[0].grad_u);
        m += weight * (2 * mu * eps_u +
                       lambda * trace(eps_u) * unit_symmetric_tensor<dim>());
      }
    return m;
  }

  template <int dim>
  double
  ManufacturedSolution<dim>::normal_memory_pressure(
    const Point<dim>     &p,
    const Tensor<1, dim> &normal,
    const double          t) const
  {
    double n = 0;
    if (!normal_memory || t <= 0)
      return n;
    for (const auto &[s, weight] : memory_quadrature(t))
      {
        const double u_nu =
          evaluate_fields(std::vector<Point<dim>>{p}, s)[0].u * normal;
        n += weight * (*normal_memory)(t - s) * std::max(u_nu, 0.);
      }
    return n;
  }

  template <int dim>
  double
  ManufacturedSolution<dim>::accumulated_slip(const Point<dim>     &p,
                                              const Tensor<1, dim> &normal,
                                              const double          t) const
  {
    double slip = 0;
    if (t <= 0)
      return slip;
    std::vector<double> at(dim + 1);
    for (int i = 0; i < dim; ++i)
      at[i] = p[i];
    for (const auto &[s, weight] : memory_quadrature(t))
      {
        at[dim] = s;
        Tensor<1, dim> rate;
        for (int c = 0; c < dim; ++c)
          rate[c] = displacement_rate[c].evaluate(at);
        slip += weight * (rate - (rate * normal) * normal).norm();
      }
    return slip;
  }

  template <int dim>
  std::vector<Tensor<1, dim>>
  ManufacturedSolution<dim>::memory_stress_divergence(
    const std::vector<Point<dim>> &points,
    const double                   t) const
  {
    std::vector<Tensor<1, dim>> divergence(points.size());
    if (!relaxation || t <= 0)
      return divergence;
    for (const auto &[s, weight] : memory_quadrature(t))
      {
        const auto [mu, lambda]     = (*relaxation)(t - s);
        const std::vector<double> r = evaluate_tape(*force_tape, points, s);
        for (unsigned int p = 0; p < points.size(); ++p)
          {
            // the force tape's outputs: dw/dt, then per (c, i <= j) the
            // entries of the Hessians of u and of w, interleaved
            const double  *at = r.data() + p * force_tape->n_outputs() + dim;
            Tensor<3, dim> hessian_u;
            for (int c = 0; c < dim; ++c)
              for (int i = 0; i < dim; ++i)
                for (int j = i; j < dim; ++j, at += 2)
                  hessian_u[c][i][j] = hessian_u[c][j][i] = at[0];
            divergence[p] +=
              weight * isotropic_stress_divergence(hessian_u, mu, lambda);
          }
      }
    return divergence;
  }

  template <int dim>
  void
  ManufacturedSolution<dim>::unpack_second_derivatives(const double *r,
                                                       Values       &v) const
  {
    unsigned int k = 0;
    for (int c = 0; c < dim; ++c)
      v.w_dot[c] = r[k++];
    Tensor<3, dim> hessian_u, hessian_w; // [component][i][j]
    for (int c = 0; c < dim; ++c)
      for (int i = 0; i < dim; ++i)
        for (int j = i; j < dim; ++j)
          {
            hessian_u[c][i][j] = hessian_u[c][j][i] = r[k++];
            hessian_w[c][i][j] = hessian_w[c][j][i] = r[k++];
          }
    v.div_sigma = material.stress_divergence(hessian_w, hessian_u);
  }

  template <int dim>
  std::vector<typename ManufacturedSolution<dim>::Values>
  ManufacturedSolution<dim>::evaluate(const std::vector<Point<dim>> &points,
                                      const double                   t) const
  {
    const std::vector<double> r        = evaluate_tape(*all_tape, points, t);
    const unsigned int        n_fields = fields_tape->n_outputs();
    std::vector<Values>       values(points.size());
    for (unsigned int p = 0; p < points.size(); ++p)
      {
        const double *at = r.data() + p * all_tape->n_outputs();
        unpack_fields<dim>(at, values[p]);
        unpack_second_derivatives(at + n_fields, values[p]);
      }
    return values;
  }

  template <int dim>
  std::vector<typename ManufacturedSolution<dim>::Values>
  ManufacturedSolution<dim>::evaluate_fields(
    const std::vector<Point<dim>> &points,
    const double                   t,
    SpatialCache                  *cache) const
  {
    const std::vector<double> r = evaluate_tape(*fields_tape, points, t, cache);
    std::vector<Values>       values(points.size());
    for (unsigned int p = 0; p < points.size(); ++p)
      unpack_fields<dim>(r.data() + p * fields_tape->n_outputs(), values[p]);
    return values;
  }

  template <int dim>
  typename ManufacturedSolution<dim>::Values
  ManufacturedSolution<dim>::evaluate(const Point<dim> &p, const double t) const
  {
    return evaluate(std::vector<Point<dim>>{p}, t)[0];
  }

  template <int dim>
  typename ManufacturedSolution<dim>::Values
  ManufacturedSolution<dim>::evaluate_fields(const Point<dim> &p,
                                             const double      t) const
  {
    return evaluate_fields(std::vector<Point<dim>>{p}, t)[0];
  }

  template <int dim>
  std::vector<Tensor<1, dim>>
  ManufacturedSolution<dim>::body_force(const std::vector<Point<dim>> &points,
                                        const double                   t,
                                        SpatialCache *cache) const
  {
    const std::vector<double> r = evaluate_tape(*force_tape, points, t, cache);
    const std::vector<Tensor<1, dim>> memory =
      memory_stress_divergence(points, t);
    std::vector<Tensor<1, dim>> forces(points.size());
    for (unsigned int p = 0; p < points.size(); ++p)
      {
        Values v;
        unpack_second_derivatives(r.data() + p * force_tape->n_outputs(), v);
        forces[p] = inertia_density * v.w_dot - v.div_sigma - memory[p];
      }
    // sigma's -c_e theta I: -Div sigma gains grad(c_e theta)
    if (temperature)
      {
        const auto theta = temperature->evaluate(points, t);
        for (unsigned int p = 0; p < points.size(); ++p)
          forces[p] += theta[p].grad_thermal_stress;
      }
    return forces;
  }

  template <int dim>
  std::unique_ptr<SpatialCache>
  ManufacturedSolution<dim>::make_fields_cache() const
  {
    return std::make_unique<SpatialCache>(*fields_tape);
  }

  template <int dim>
  std::unique_ptr<SpatialCache>
  ManufacturedSolution<dim>::make_force_cache() const
  {
    return std::make_unique<SpatialCache>(*force_tape);
  }

  template <int dim>
  SymmetricTensor<2, dim>
  ManufacturedSolution<dim>::stress(const Values &v) const
  {
    return material.stress(symmetrize(v.grad_w), symmetrize(v.grad_u));
  }

  template <int dim>
  Tensor<1, dim>
  ManufacturedSolution<dim>::body_force(const Point<dim> &p,
                                        const double      t) const
  {
    return body_force(std::vector<Point<dim>>{p}, t)[0];
  }

  template <int dim>
  Tensor<1, dim>
  ManufacturedSolution<dim>::surface_traction(const Point<dim>     &p,
                                              const Tensor<1, dim> &normal,
                                              const double          t) const
  {
    return (stress(evaluate_fields(p, t)) + memory_stress(p, t)) * normal -
           thermal_stress(p, t) * normal;
  }

  template <int dim>
  double
  ManufacturedSolution<dim>::thermal_stress(const Point<dim> &p,
                                            const double      t) const
  {
    if (!temperature)
      return 0;
    const auto theta = temperature->evaluate(std::vector<Point<dim>>{p}, t);
    return theta[0].c_e * theta[0].theta;
  }

  template <int dim>
  std::vector<typename ManufacturedTemperature<dim>::Values>
  ManufacturedSolution<dim>::temperature_values(
    const std::vector<Point<dim>> &points,
    const double                   t) const
  {
    Assert(temperature, ExcInternalError());
    return temperature->evaluate(points, t);
  }

  template <int dim>
  typename ManufacturedSolution<dim>::ContactResponse
  ManufacturedSolution<dim>::contact_response(const Point<dim>     &p,
                                              const Tensor<1, dim> &normal,
                                              const double          t) const
  {
    const Values         v     = evaluate_fields(p, t);
    const double         w_n   = v.w * normal;
    const Tensor<1, dim> w_t   = v.w - w_n * normal;
    const double         scale = 1e-13 * (1 + v.w.norm());

    std::vector<double> at(dim + 1);
    for (int i = 0; i < dim; ++i)
      at[i] = p[i];
    at[dim] = t;

    // xi_nu in dj(w_nu) + N(w_nu): the given multiplier where w_nu is at a
    // hold point (0, a kink, the wall: doc/theory.md section 10)
    bool held = std::abs(w_n) <= scale ||
                std::abs(w_n - law.penetration_limit()) <= scale;
    for (const NormalLaw::Kink &kink : law.kinks())
      held = held || std::abs(w_n - kink.position) <= scale;
    const double xi_n =
      held ? normal_multiplier->evaluate(at) : law.subgradient(w_n);
    // the memory of the normal response, -sigma_nu = xi_nu + N (section
    // 11.9): the exact contact pressure p_nu of the bound is xi_nu + N, and
    // its s_tau the exact slip up to t (doc/theory.md 11.11)
    const double n_memory = normal_memory_pressure(p, normal, t);
    const double bound =
      friction_bound->value(p,
                            t,
                            v.u * normal,
                            v.w * normal,
                            xi_n + n_memory,
                            friction_bound->uses_slip() ?
                              accumulated_slip(p, normal, t) :
                              0.);
    // xi_tau in dphi(w_tau): the given multiplier where w_tau = 0
    Tensor<1, dim> xi_t;
    if (w_t.norm() <= scale)
      {
        for (int c = 0; c < dim; ++c)
          xi_t[c] = tangential_multiplier[c].evaluate(at);
        xi_t -= (xi_t * normal) * normal;
      }
    else
      xi_t = friction.response(bound, w_t.norm()) * w_t / w_t.norm();

    return {v, xi_n + n_memory, xi_t};
  }

  template <int dim>
  Tensor<1, dim>
  ManufacturedSolution<dim>::contact_traction(const Point<dim>     &p,
                                              const Tensor<1, dim> &normal,
                                              const double          t) const
  {
    const ContactResponse r = contact_response(p, normal, t);
    return (stress(r.v) + memory_stress(p, t)) * normal -
           thermal_stress(p, t) * normal + r.pressure * normal + r.xi_tau;
  }

  template <int dim>
  ProblemData<dim>
  ManufacturedSolution<dim>::make_problem_data() const
  {
    ProblemData<dim> data;
    /** The fields of the manufactured solution given to the problem. */
    enum class Kind
    {
      body_force,           ///< f0(x, t)
      initial_displacement, ///< u(x, t)
      initial_velocity      ///< w(x, t) = du/dt
    };
    // f0 and the initial fields as deal.II Functions (time from get_time())
    class Field : public Function<dim>
    {
    public:
      Field(const ManufacturedSolution<dim> &m, const Kind kind)
        : Function<dim>(dim)
        , m(m)
        , kind(kind)
        , cache(kind == Kind::body_force ? m.make_force_cache() : nullptr)
      {}
      void
      vector_value(const Point<dim> &p, Vector<double> &values) const override
      {
        std::vector<Vector<double>> list(1, Vector<double>(dim));
        vector_value_list({p}, list);
        values = list[0];
      }
      void
      vector_value_list(const std::vector<Point<dim>> &points,
                        std::vector<Vector<double>>   &values) const override
      {
        // one batch: what depends only on t is computed once; f0 is
        // assembled at every step on the same cells: what depends only on
        // x is remembered
        const double t = this->get_time();
        if (kind == Kind::body_force)
          {
            const std::vector<Tensor<1, dim>> f =
              m.body_force(points, t, cache.get());
            for (unsigned int p = 0; p < points.size(); ++p)
              for (int c = 0; c < dim; ++c)
                values[p](c) = f[p][c];
            return;
          }
        const std::vector<Values> v = m.evaluate_fields(points, t);
        for (unsigned int p = 0; p < points.size(); ++p)
          for (int c = 0; c < dim; ++c)
            values[p](c) =
              kind == Kind::initial_displacement ? v[p].u[c] : v[p].w[c];
      }
      double
      value(const Point<dim> &p, const unsigned int c) const override
      {
        Vector<double> v(dim);
        vector_value(p, v);
        return v(c);
      }

    private:
      const ManufacturedSolution<dim>    &m;
      const Kind                          kind;
      const std::unique_ptr<SpatialCache> cache;
    };

    data.body_force = std::make_unique<Field>(*this, Kind::body_force);
    data.initial_displacement =
      std::make_unique<Field>(*this, Kind::initial_displacement);
    data.initial_velocity =
      std::make_unique<Field>(*this, Kind::initial_velocity);
    data.surface_traction = std::make_unique<Functions::ZeroFunction<dim>>(dim);
    data.contact_traction = std::make_unique<Functions::ZeroFunction<dim>>(dim);
    data.friction_bound   = friction_bound;
    data.surface_traction_with_normal =
      [this](const Point<dim> &p, const Tensor<1, dim> &n, double t) {
        return surface_traction(p, n, t);
      };
    data.contact_traction_with_normal =
      [this](const Point<dim> &p, const Tensor<1, dim> &n, double t) {
        return contact_traction(p, n, t);
      };
    if (temperature)
      data.heat = make_heat_data();
    return data;
  }

  template <int dim>
  HeatData<dim>
  ManufacturedSolution<dim>::make_heat_data() const
  {
    /** The scalar fields of the heat data. */
    enum class Kind
    {
      initial_temperature, ///< theta(x, 0)
      temperature,         ///< theta(x, t)
      heat_source          ///< q(x, t)
    };
    class Field : public Function<dim>
    {
    public:
      Field(const ManufacturedSolution<dim> &m, const Kind kind)
        : Function<dim>(1)
        , m(m)
        , kind(kind)
      {}
      void
      value_list(const std::vector<Point<dim>> &points,
                 std::vector<double>           &values,
                 const unsigned int) const override
      {
        const double t =
          kind == Kind::initial_temperature ? 0. : this->get_time();
        if (kind == Kind::heat_source)
          {
            // c_e div w with the exact w
            const std::vector<Values> v = m.evaluate_fields(points, t);
            std::vector<double>       div_w(points.size());
            for (unsigned int p = 0; p < points.size(); ++p)
              div_w[p] = trace(v[p].grad_w);
            values = m.temperature->heat_source(points, div_w, t);
            return;
          }
        const auto theta = m.temperature->evaluate(points, t);
        for (unsigned int p = 0; p < points.size(); ++p)
          values[p] = theta[p].theta;
      }
      double
      value(const Point<dim> &p, const unsigned int) const override
      {
        std::vector<double> v(1);
        value_list({p}, v, 0);
        return v[0];
      }

    private:
      const ManufacturedSolution<dim> &m;
      const Kind                       kind;
    };

    HeatData<dim> heat;
    heat.initial_temperature =
      std::make_shared<Field>(*this, Kind::initial_temperature);
    heat.prescribed_temperature =
      std::make_shared<Field>(*this, Kind::temperature);
    heat.heat_source = std::make_shared<Field>(*this, Kind::heat_source);
    heat.heat_flux =
      [this](const Point<dim> &p, const Tensor<1, dim> &n, double t) {
        return temperature->normal_flux(p, n, t);
      };
    // g_3 with the exact u_nu and |xi_tau . w_tau| of the friction law
    heat.contact_heat_source =
      [this](const Point<dim> &p, const Tensor<1, dim> &n, double t) {
        const ContactResponse r     = contact_response(p, n, t);
        const Tensor<1, dim>  w_tau = r.v.w - (r.v.w * n) * n;
        return temperature->contact_heat_source(
          p, n, t, r.v.u * n, std::abs(r.xi_tau * w_tau));
      };
    return heat;
  }

  template class ManufacturedSolution<2>;
  template class ManufacturedSolution<3>;
} // namespace hemicontact
