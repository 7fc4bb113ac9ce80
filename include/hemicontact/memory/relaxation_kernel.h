#pragma once

#include <hemicontact/expressions/expression.h>
#include <hemicontact/input/parameters.h>

#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace hemicontact
{
  /**
   * The isotropic relaxation tensor R(t) eps = 2 mu_R(t) eps + lambda_R(t)
   * tr(eps) I of 'relaxation' (doc/theory.md, section 11): a Prony series
   * or the expressions mu_R(t), lambda_R(t).
   */
  class RelaxationKernel
  {
  public:
    /**
     * The kernel of @p parameters, its expressions parsed with the
     * constants of 'data/constants' @p constants (InputError on a syntax
     * error or an unknown name).
     */
    RelaxationKernel(const RelaxationParameters &parameters,
                     const std::string          &constants);

    RelaxationKernelType
    type() const
    {
      return kernel;
    }

    /** The number of terms of a Prony series (0 for an expression). */
    unsigned int
    n_terms() const
    {
      return relaxation_times.size();
    }
    /** mu_m, lambda_m and tau_m of term @p m of a Prony series. */
    double
    mu_amplitude(const unsigned int m) const
    {
      return mu_amplitudes[m];
    }
    double
    lambda_amplitude(const unsigned int m) const
    {
      return lambda_amplitudes[m];
    }
    double
    relaxation_time(const unsigned int m) const
    {
      return relaxation_times[m];
    }

    /**
     * (mu_R(t), lambda_R(t)): the Prony sum or the expressions. An
     * expression that is not a finite number at @p t throws an InputError
     * naming it and t.
     */
    std::pair<double, double>
    operator()(const double t) const;

    /**
     * Throw an InputError if the kernel is not finite at one of the times
     * t = k, 2k, ..., n_steps k, the arguments t_n - t_j of the rule.
     */
    void
    require_finite(const double k, const unsigned int n_steps) const;

  private:
    RelaxationKernelType        kernel;
    std::vector<double>         mu_amplitudes;
    std::vector<double>         lambda_amplitudes;
    std::vector<double>         relaxation_times;
    std::string                 mu_text;
    std::string                 lambda_text;
    std::shared_ptr<Expression> mu;
    std::shared_ptr<Expression> lambda;
  };
} // namespace hemicontact
