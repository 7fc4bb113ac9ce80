#pragma once

#include <deal.II/base/exceptions.h>
#include <deal.II/base/parameter_handler.h>

#include <hemicontact/base/exceptions.h>
#include <hemicontact/laws/law_parameters.h>

#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace hemicontact
{
  using namespace dealii;

  /**
   * One entry of a registry of laws derived from @p Base: the law's name,
   * how to declare its parameters (inside the registry's subsection) and
   * how to create it.
   */
  template <class Base>
  struct LawEntry
  {
    std::string                                              name;
    std::function<void(ParameterHandler &)>                  declare;
    std::function<std::unique_ptr<Base>(ParameterHandler &)> create;
  };

  /**
   * The entry of a law class with a static `law_name`, a static
   * `declare_parameters(ParameterHandler &)` and a constructor from the
   * ParameterHandler (positioned in the registry's subsection).
   */
  template <class Base, class Law>
  LawEntry<Base>
  make_law_entry()
  {
    return {Law::law_name,
            &Law::declare_parameters,
            [](ParameterHandler &prm) -> std::unique_ptr<Base> {
              return std::make_unique<Law>(prm);
            }};
  }

  /**
   * The laws of one kind (normal laws, friction laws): the subsection with
   * its selection entry "law" and one subsection per law, the creation of
   * the selected law, and the registration of further laws by a program
   * that links the library.
   */
  template <class Base>
  class LawRegistry
  {
  public:
    LawRegistry(std::string                 subsection,
                std::string                 default_law,
                std::string                 documentation,
                std::vector<LawEntry<Base>> laws)
      : subsection(std::move(subsection))
      , default_law(std::move(default_law))
      , documentation(std::move(documentation))
      , laws(std::move(laws))
    {}

    /** The name of the law selected when the parameter file names none. */
    const std::string &
    default_name() const
    {
      return default_law;
    }

    /** All laws, the shipped ones first. */
    const std::vector<LawEntry<Base>> &
    entries() const
    {
      return laws;
    }

    /** Add a law; a name that is already registered throws. */
    void
    add(const LawEntry<Base> &entry)
    {
      for (const LawEntry<Base> &e : laws)
        AssertThrow(e.name != entry.name,
                    ExcMessage(subsection + " '" + entry.name +
                               "' is registered twice."));
      laws.push_back(entry);
    }

    /** Declare the subsection with "law" and one subsection per law. */
    void
    declare(ParameterHandler &prm) const
    {
      std::string names;
      for (const LawEntry<Base> &e : laws)
        names += (names.empty() ? "" : "|") + e.name;
      prm.enter_subsection(subsection);
      prm.declare_entry("law",
                        default_law,
                        Patterns::Selection(names),
                        documentation);
      for (const LawEntry<Base> &e : laws)
        e.declare(prm);
      prm.leave_subsection();
    }

    /** Create the law selected in the subsection of @p prm. */
    std::unique_ptr<Base>
    create(ParameterHandler &prm) const
    {
      prm.enter_subsection(subsection);
      const std::string     name = prm.get("law");
      std::unique_ptr<Base> law;
      try
        {
          for (const LawEntry<Base> &e : laws)
            if (e.name == name)
              law = e.create(prm);
        }
      catch (...)
        {
          prm.leave_subsection();
          throw;
        }
      prm.leave_subsection();
      require(law != nullptr, subsection + ": unknown law '" + name + "'.");
      return law;
    }

  private:
    const std::string           subsection;
    const std::string           default_law;
    const std::string           documentation;
    std::vector<LawEntry<Base>> laws;
  };
} // namespace hemicontact
