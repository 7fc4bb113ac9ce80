#pragma once

#include <deal.II/base/symmetric_tensor.h>

#include <hemicontact/input/parameters.h>

namespace hemicontact
{
  using namespace dealii;

  /**
   * The Kelvin-Voigt law sigma = A eps(w) + B eps(u) with isotropic
   * viscosity A (mu_v, lambda_v) and elasticity B (mu, lambda).
   */
  template <int dim>
  class KelvinVoigtMaterial
  {
  public:
    explicit KelvinVoigtMaterial(const MaterialParameters &parameters)
      : rho(parameters.density)
      , mu_v(parameters.viscosity.mu)
      , lambda_v(parameters.viscosity.lambda)
      , mu_e(parameters.elasticity.mu)
      , lambda_e(parameters.elasticity.lambda)
    {}

    double
    density() const
    {
      return rho;
    }

    /** A eps = 2 mu_v eps + lambda_v tr(eps) I. */
    SymmetricTensor<2, dim>
    viscous_stress(const SymmetricTensor<2, dim> &eps) const
    {
      return 2 * mu_v * eps +
             lambda_v * trace(eps) * unit_symmetric_tensor<dim>();
    }

    /** B eps = 2 mu eps + lambda tr(eps) I. */
    SymmetricTensor<2, dim>
    elastic_stress(const SymmetricTensor<2, dim> &eps) const
    {
      return 2 * mu_e * eps +
             lambda_e * trace(eps) * unit_symmetric_tensor<dim>();
    }

    /** sigma = A eps(w) + B eps(u). */
    SymmetricTensor<2, dim>
    stress(const SymmetricTensor<2, dim> &eps_w,
           const SymmetricTensor<2, dim> &eps_u) const
    {
      return viscous_stress(eps_w) + elastic_stress(eps_u);
    }

    /**
     * Div sigma = Div(A eps(w) + B eps(u)) from the Hessians of w and u
     * ([component][i][j]): for each isotropic part, Div(2 mu eps(v) +
     * lambda div v I)_i = mu lap v_i + (mu + lambda) d_i div v.
     */
    Tensor<1, dim>
    stress_divergence(const Tensor<3, dim> &hessian_w,
                      const Tensor<3, dim> &hessian_u) const
    {
      const auto part =
        [](const Tensor<3, dim> &h, const double mu, const double lambda) {
          Tensor<1, dim> result;
          for (int i = 0; i < dim; ++i)
            for (int j = 0; j < dim; ++j)
              result[i] += mu * h[i][j][j] + (mu + lambda) * h[j][i][j];
          return result;
        };
      return part(hessian_w, mu_v, lambda_v) + part(hessian_u, mu_e, lambda_e);
    }

    /** von Mises equivalent stress sqrt(3/2 dev(s):dev(s)) (of the 3D
     *  embedding in plane strain). */
    static double
    von_mises(const SymmetricTensor<2, dim> &s)
    {
      const SymmetricTensor<2, dim> d = deviator(s);
      return std::sqrt(1.5 * (d * d));
    }

    double
    mu_viscous() const
    {
      return mu_v;
    }
    double
    lambda_viscous() const
    {
      return lambda_v;
    }
    double
    mu_elastic() const
    {
      return mu_e;
    }
    double
    lambda_elastic() const
    {
      return lambda_e;
    }

  private:
    double rho, mu_v, lambda_v, mu_e, lambda_e;
  };
} // namespace hemicontact
