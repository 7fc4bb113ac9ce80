#pragma once

#include <hemicontact/laws/normal_law.h>

namespace hemicontact
{
  /**
   * The reference nonmonotone law of doc/theory.md section 1:
   * dj(r) = 0 (r<0), [0,a] (r=0), (a-b) exp(-beta r) + b (r>0),
   * with a >= b >= 0, beta >= 0; alpha = beta (a - b).
   */
  class ExponentialLaw : public NormalLaw
  {
  public:
    static constexpr const char *law_name = "exponential";
    static void
    declare_parameters(ParameterHandler &prm);

    explicit ExponentialLaw(ParameterHandler &prm);
    ExponentialLaw(const double a, const double b, const double beta);

    std::string
    name() const override
    {
      return law_name;
    }
    double
    jump() const override
    {
      return a;
    }
    double
    remainder(const double r) const override;
    double
    remainder_derivative(const double r) const override;
    double
    remainder_primitive(const double r) const override;
    double
    relaxed_monotonicity_constant() const override
    {
      return beta * (a - b);
    }

  private:
    double a, b, beta;
  };
} // namespace hemicontact
