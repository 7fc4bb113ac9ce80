#pragma once

#include <hemicontact/laws/normal_law.h>

namespace hemicontact
{
  /**
   * The penalised normal compliance of Example B (doc/examples.md,
   * section 9): the potential penalty * j(r) with, for r >= 0,
   *   j(r) = (a + e^{-b}) r^2 / (2b)                     (r < b),
   *   j(r) = a r - e^{-r} + ((b + 2) e^{-b} - a b) / 2   (r >= b),
   * and j = 0 for r <= 0. Its derivative rises linearly to a + e^{-b} at
   * r = b and then softens as a + e^{-r} towards a. No jump at 0; the
   * remainder is p = penalty * j'; alpha = penalty * e^{-b}, the steepest
   * descent of j'; the largest remainder slope penalty (a + e^{-b})/b, its
   * rise. At r = 0 remainder_derivative() is the right derivative
   * penalty (a + e^{-b})/b (an element of the generalized derivative
   * [0, penalty (a + e^{-b})/b]): Newton started from u = 0 then sees the
   * compliance, instead of jumping to the free body's penetration.
   */
  class PenalisedSofteningCompliance : public NormalLaw
  {
  public:
    static constexpr const char *law_name = "penalised softening compliance";
    static void
    declare_parameters(ParameterHandler &prm);

    explicit PenalisedSofteningCompliance(ParameterHandler &prm);
    PenalisedSofteningCompliance(const double a,
                                 const double b,
                                 const double penalty);

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
    remainder(const double r) const override;
    double
    remainder_derivative(const double r) const override;
    double
    remainder_primitive(const double r) const override;
    double
    relaxed_monotonicity_constant() const override;
    /** penalty (a + e^{-b})/b: the slope of the rise on (0, b). */
    double
    largest_remainder_slope() const override;

  private:
    double a, b, penalty;
  };
} // namespace hemicontact
