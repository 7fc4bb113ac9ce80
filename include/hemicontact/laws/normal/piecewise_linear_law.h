#pragma once

#include <hemicontact/laws/normal_law.h>

#include <vector>

namespace hemicontact
{
  /**
   * A nonmonotone law given by breakpoints (r_k, p_k), r_0 = 0 <= r_1 <= ...:
   * dj(r) = 0 (r<0), [0, p_0] (r=0), and for r > 0 the piecewise-linear
   * interpolant of the breakpoints, constant beyond the last one. Two
   * breakpoints at the same r > 0 give the response's one-sided values
   * there: an upward jump is a convex kink (kinks()), a downward jump a
   * concave one (alpha = +inf). The jump at zero is a = p_0; otherwise
   * alpha is the steepest descent slope. This covers the laws of
   * Jureczka-Ochal et al. (p = 20 r up to r = 0.1, then 0).
   */
  class PiecewiseLinearLaw : public NormalLaw
  {
  public:
    static constexpr const char *law_name = "piecewise linear";
    static void
    declare_parameters(ParameterHandler &prm);

    explicit PiecewiseLinearLaw(ParameterHandler &prm);
    /** Breakpoints as (r_k, p_k) pairs. */
    explicit PiecewiseLinearLaw(
      const std::vector<std::pair<double, double>> &breakpoints);

    std::string
    name() const override
    {
      return law_name;
    }
    double
    jump() const override
    {
      return points.front().second;
    }
    double
    remainder(const double r) const override;
    double
    remainder_derivative(const double r) const override;
    double
    remainder_primitive(const double r) const override;
    double
    relaxed_monotonicity_constant() const override;
    const std::vector<Kink> &
    kinks() const override
    {
      return upward_jumps;
    }

  private:
    /** The response p(r) for r > 0 (the interpolant). */
    double
    response(const double r) const;

    std::vector<std::pair<double, double>> points;
    std::vector<Kink>                      upward_jumps;
  };
} // namespace hemicontact
