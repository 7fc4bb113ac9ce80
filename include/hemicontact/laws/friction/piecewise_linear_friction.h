#pragma once

#include <hemicontact/laws/friction_law.h>

#include <utility>
#include <vector>

namespace hemicontact
{
  /**
   * A friction force given by breakpoints (s_k, g_k) in the slip speed,
   * s_0 = 0 < s_1 < ..., g_0 = 1, g_k >= 0: F(s) = F_b g(s) with g the
   * continuous piecewise-linear interpolant, constant beyond the last
   * breakpoint. Any shape is allowed: rising (rate strengthening), falling
   * (weakening), or first one then the other. Remainder r = F_b (g - 1);
   * alpha_tau = F_b times the steepest descent slope of g.
   */
  class PiecewiseLinearFrictionLaw : public FrictionLaw
  {
  public:
    static constexpr const char *law_name = "piecewise linear";
    static void
    declare_parameters(ParameterHandler &prm);

    explicit PiecewiseLinearFrictionLaw(ParameterHandler &prm);
    /** Breakpoints (s_k, g_k); (0, 1) is put first if not given. */
    explicit PiecewiseLinearFrictionLaw(
      const std::vector<std::pair<double, double>> &breakpoints);

    std::string
    name() const override
    {
      return law_name;
    }
    double
    remainder(const double bound, const double s) const override;
    double
    remainder_derivative(const double bound, const double s) const override;
    double
    remainder_primitive(const double bound, const double s) const override;
    double
    relaxed_monotonicity_constant(const double bound) const override;

  private:
    /** The ratio g(s) = F(s)/F_b. */
    double
    ratio(const double s) const;

    std::vector<std::pair<double, double>> points;
  };
} // namespace hemicontact
