/**
 * The reader of a memory kernel's subsection, 'relaxation' and 'normal
 * memory' (KernelSubsection, include/hemicontact/input/kernel_subsection.h).
 */
#include <hemicontact/base/exceptions.h>
#include <hemicontact/input/kernel_subsection.h>
#include <hemicontact/input/number_list.h>
#include <hemicontact/input/selection.h>

#include <sstream>

namespace hemicontact
{
  namespace
  {
    const SelectionNames<MemoryKernelType> kernel_types = {
      {"none", MemoryKernelType::none},
      {"prony", MemoryKernelType::prony},
      {"expression", MemoryKernelType::expression}};
  } // namespace

  void
  KernelSubsection::declare(ParameterHandler &prm) const
  {
    prm.enter_subsection(name);
    prm.declare_entry("kernel",
                      "none",
                      selection_pattern(kernel_types),
                      kernel_help);
    for (const auto &[entry, help] : amplitudes)
      prm.declare_entry(entry, "", Patterns::Anything(), help);
    prm.declare_entry("relaxation times",
                      "",
                      Patterns::Anything(),
                      "'kernel = prony': the relaxation times tau_m > 0 of "
                      "the terms, comma-separated finite numbers.");
    for (const Entry &entry : more)
      prm.declare_entry(entry.name,
                        entry.default_value,
                        *entry.pattern,
                        entry.help);
    for (const auto &[entry, help] : expressions)
      prm.declare_entry(entry, "0", Patterns::Anything(), help);
    prm.leave_subsection();
  }

  KernelSubsection::Values
  KernelSubsection::parse(
    ParameterHandler                                    &prm,
    const std::function<void(const ParameterHandler &)> &read_more) const
  {
    prm.enter_subsection(name);
    Values values;
    values.kernel = get_selection(prm, "kernel", kernel_types);
    for (const auto &entry : amplitudes)
      values.amplitudes.push_back(get_number_list(prm, name, entry.first));
    values.relaxation_times = get_number_list(prm, name, "relaxation times");
    for (const auto &entry : expressions)
      values.expressions.push_back(prm.get(entry.first));
    if (read_more)
      read_more(prm);
    prm.leave_subsection();
    return values;
  }

  void
  KernelSubsection::require_terms(
    const Values                   &values,
    const std::vector<std::string> &amplitude_names) const
  {
    const std::vector<double> &times = values.relaxation_times;
    require(!times.empty(),
            name + ": 'kernel = prony' needs at least one term: set " +
              set_terms + ".");
    for (const double tau : times)
      {
        std::ostringstream message;
        message << name << ": 'relaxation times' holds " << tau
                << "; every relaxation time tau_m must be positive (the "
                   "terms are exp(-t/tau_m)).";
        require(tau > 0, message.str());
      }
    for (unsigned int i = 0; i < amplitudes.size(); ++i)
      require(values.amplitudes[i].size() == times.size(),
              name + ": '" +
                (amplitude_names.empty() ? amplitudes[i].first :
                                           amplitude_names[i]) +
                "' has " + std::to_string(values.amplitudes[i].size()) +
                " values and 'relaxation times' " +
                std::to_string(times.size()) + "; give one amplitude per term" +
                per_term + ".");
  }
} // namespace hemicontact
