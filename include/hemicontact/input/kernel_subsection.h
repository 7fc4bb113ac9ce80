#pragma once

#include <deal.II/base/parameter_handler.h>

#include <hemicontact/input/parameters.h>

#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace hemicontact
{
  /**
   * A subsection of a memory kernel ('relaxation', 'normal memory'): its
   * 'kernel', the amplitude lists and 'relaxation times' of a Prony series,
   * entries of its own, and the expressions in t.
   */
  struct KernelSubsection
  {
    /** An entry: its name, default value, pattern and help. */
    struct Entry
    {
      std::string                                          name;
      std::string                                          default_value;
      std::shared_ptr<const dealii::Patterns::PatternBase> pattern;
      std::string                                          help;
    };

    /** 'relaxation', 'normal memory'. */
    std::string name;
    /** The help of 'kernel'. */
    std::string kernel_help;
    /** The amplitude lists (name, help), one value per term. */
    std::vector<std::pair<std::string, std::string>> amplitudes;
    /** Entries declared after 'relaxation times'; their reader reads them. */
    std::vector<Entry> more;
    /** The expressions (name, help), each 0 by default. */
    std::vector<std::pair<std::string, std::string>> expressions;
    /** What a Prony series without terms is asked to set. */
    std::string set_terms;
    /** The end of the advice on a list of the wrong length. */
    std::string per_term;

    /** What the entries hold. */
    struct Values
    {
      MemoryKernelType                 kernel;
      std::vector<std::vector<double>> amplitudes;
      std::vector<double>              relaxation_times;
      std::vector<std::string>         expressions;
    };

    /** Declare the subsection and its entries. */
    void
    declare(dealii::ParameterHandler &prm) const;

    /**
     * Read the subsection: all but the entries 'more', which
     * @p read_more reads, in the subsection, after the others.
     */
    Values
    parse(dealii::ParameterHandler &prm,
          const std::function<void(const dealii::ParameterHandler &)>
            &read_more = {}) const;

    /**
     * An InputError unless the Prony series of @p values has terms, each
     * with tau_m > 0 and one value in each amplitude list, which the
     * message calls @p amplitude_names (by default their entries' names).
     */
    void
    require_terms(const Values                   &values,
                  const std::vector<std::string> &amplitude_names = {}) const;
  };
} // namespace hemicontact
