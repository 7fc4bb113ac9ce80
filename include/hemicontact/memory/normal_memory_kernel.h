#pragma once

#include <hemicontact/expressions/expression.h>
#include <hemicontact/input/parameters.h>

#include <memory>
#include <string>
#include <vector>

namespace hemicontact
{
  /**
   * The kernel b(t) of the memory term of the normal response of 'normal
   * memory' (doc/theory.md, section 11.9): a Prony series or an expression
   * b(t).
   */
  class NormalMemoryKernel
  {
  public:
    /**
     * The kernel of @p parameters, its expression parsed with the constants
     * of 'data/constants' @p constants (InputError on a syntax error or an
     * unknown name).
     */
    NormalMemoryKernel(const NormalMemoryParameters &parameters,
                       const std::string            &constants);

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
    /** b_m and tau_m of term @p m of a Prony series. */
    double
    amplitude(const unsigned int m) const
    {
      return amplitudes[m];
    }
    double
    relaxation_time(const unsigned int m) const
    {
      return relaxation_times[m];
    }

    /**
     * b(t): the Prony sum or the expression; an expression that is not a
     * finite number at @p t throws an InputError naming it and t.
     */
    double
    operator()(const double t) const;

    /**
     * Throw an InputError if the kernel is not finite at one of the times
     * t = k, 2k, ..., n_steps k, the arguments t_n - t_j of the rule.
     */
    void
    require_finite(const double k, const unsigned int n_steps) const;

  private:
    RelaxationKernelType        kernel;
    std::vector<double>         amplitudes;
    std::vector<double>         relaxation_times;
    std::string                 text;
    std::shared_ptr<Expression> b;
  };
} // namespace hemicontact
