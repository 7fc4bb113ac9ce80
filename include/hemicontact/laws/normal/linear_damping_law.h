#pragma once

#include <hemicontact/laws/normal_law.h>

namespace hemicontact
{
  /**
   * Monotone linear damping xi = c r_+ (convex j = c r_+^2 / 2, alpha = 0,
   * no jump).
   */
  class LinearDampingLaw : public NormalLaw
  {
  public:
    static constexpr const char *law_name = "linear damping";
    static void
    declare_parameters(ParameterHandler &prm);

    explicit LinearDampingLaw(ParameterHandler &prm);
    explicit LinearDampingLaw(const double coefficient);

    std::string
    name() const override
    {
      return law_name;
    }
    double
    jump() const override
    {
      return 0.;
    }
    double
    remainder(const double r) const override
    {
      return r > 0 ? coefficient * r : 0.;
    }
    double
    remainder_derivative(const double r) const override
    {
      return r > 0 ? coefficient : 0.;
    }
    double
    remainder_primitive(const double r) const override
    {
      return r > 0 ? 0.5 * coefficient * r * r : 0.;
    }
    double
    relaxed_monotonicity_constant() const override
    {
      return 0.;
    }
    double
    largest_remainder_slope() const override
    {
      return coefficient;
    }

  private:
    double coefficient;
  };
} // namespace hemicontact
