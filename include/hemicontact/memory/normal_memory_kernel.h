#pragma once

#include <hemicontact/input/parameters.h>
#include <hemicontact/memory/memory_kernel.h>

#include <string>

namespace hemicontact
{
  /**
   * The kernel b(t) of the memory term of the normal response of 'normal
   * memory' (doc/theory.md, section 11.9): a Prony series or an expression
   * b(t).
   */
  class NormalMemoryKernel : public MemoryKernel<1>
  {
  public:
    /**
     * The kernel of @p parameters, its expression parsed with the constants
     * of 'data/constants' @p constants (InputError on a syntax error or an
     * unknown name).
     */
    NormalMemoryKernel(const NormalMemoryParameters &parameters,
                       const std::string            &constants)
      : MemoryKernel<1>(parameters.kernel,
                        parameters.relaxation_times,
                        {{{"b", parameters.amplitudes, parameters.b}}},
                        "normal memory",
                        "11.9",
                        constants)
    {}

    using MemoryKernel<1>::amplitude;

    /** b_m of term @p m of a Prony series. */
    double
    amplitude(const unsigned int m) const
    {
      return amplitude(0, m);
    }

    /** b(t), as values(). */
    double
    operator()(const double t) const
    {
      return values(t)[0];
    }
  };
} // namespace hemicontact
