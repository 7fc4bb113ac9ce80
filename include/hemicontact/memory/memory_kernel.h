#pragma once

#include <hemicontact/expressions/expression.h>
#include <hemicontact/input/parameters.h>

#include <array>
#include <memory>
#include <string>
#include <vector>

namespace hemicontact
{
  /**
   * A memory kernel of @p n components K_c(t) (doc/theory.md, section 11):
   * a Prony series K_c(t) = sum_m a_{c,m} exp(-t/tau_m) or expressions in
   * t. The stress's R(t) has two (mu_R, lambda_R), the normal memory's b(t)
   * one.
   */
  template <unsigned int n>
  class MemoryKernel
  {
  public:
    /** The number of components. */
    static constexpr unsigned int n_components = n;

    /** What a component is called and what it is. */
    struct Component
    {
      /** Its entry: 'mu', 'lambda', 'b'. */
      std::string name;
      /** a_{c,m}: one per term of a Prony series. */
      std::vector<double> amplitudes;
      /** The expression K_c(t). */
      std::string expression;
    };

    /**
     * The kernel @p type with the relaxation times @p relaxation_times and
     * the components @p components of the subsection @p subsection
     * (doc/theory.md, section @p section), its expressions parsed with the
     * constants of 'data/constants' @p constants (InputError on a syntax
     * error or an unknown name).
     */
    MemoryKernel(const MemoryKernelType          type,
                 const std::vector<double>      &relaxation_times,
                 const std::array<Component, n> &components,
                 const std::string              &subsection,
                 const std::string              &section,
                 const std::string              &constants);

    MemoryKernelType
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
    /** a_{c,m} of component @p c and term @p m of a Prony series. */
    double
    amplitude(const unsigned int c, const unsigned int m) const
    {
      return components[c].amplitudes[m];
    }
    /** tau_m of term @p m of a Prony series. */
    double
    relaxation_time(const unsigned int m) const
    {
      return relaxation_times[m];
    }

    /**
     * K_c(t) of every component: the Prony sum or the expressions. An
     * expression that is not a finite number at @p t throws an InputError
     * naming it and t.
     */
    std::array<double, n>
    values(const double t) const;

    /**
     * Throw an InputError if the kernel is not finite at one of the times
     * t = k, 2k, ..., n_steps k, the arguments t_n - t_j of the rule.
     */
    void
    require_finite(const double k, const unsigned int n_steps) const;

  private:
    MemoryKernelType                           kernel;
    std::vector<double>                        relaxation_times;
    std::array<Component, n>                   components;
    std::string                                subsection;
    std::string                                section;
    std::array<std::shared_ptr<Expression>, n> expressions;
  };
} // namespace hemicontact
