#pragma once

#include <hemicontact/input/parameters.h>
#include <hemicontact/memory/memory_kernel.h>

#include <string>
#include <utility>

namespace hemicontact
{
  /**
   * The isotropic relaxation tensor R(t) eps = 2 mu_R(t) eps + lambda_R(t)
   * tr(eps) I of 'relaxation' (doc/theory.md, section 11): a Prony series
   * or the expressions mu_R(t), lambda_R(t).
   */
  class RelaxationKernel : public MemoryKernel<2>
  {
  public:
    /**
     * The kernel of @p parameters, its expressions parsed with the
     * constants of 'data/constants' @p constants (InputError on a syntax
     * error or an unknown name).
     */
    RelaxationKernel(const RelaxationParameters &parameters,
                     const std::string          &constants)
      : MemoryKernel<2>(
          parameters.kernel,
          parameters.relaxation_times,
          {{{"mu", parameters.mu_amplitudes, parameters.mu},
            {"lambda", parameters.lambda_amplitudes, parameters.lambda}}},
          "relaxation",
          "11",
          constants)
    {}

    /** mu_m of term @p m of a Prony series. */
    double
    mu_amplitude(const unsigned int m) const
    {
      return amplitude(0, m);
    }
    /** lambda_m of term @p m of a Prony series. */
    double
    lambda_amplitude(const unsigned int m) const
    {
      return amplitude(1, m);
    }

    /** (mu_R(t), lambda_R(t)), as values(). */
    std::pair<double, double>
    operator()(const double t) const
    {
      const auto [mu, lambda] = values(t);
      return {mu, lambda};
    }
  };
} // namespace hemicontact
