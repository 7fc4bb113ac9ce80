#pragma once

#include <cctype>
#include <stdexcept>
#include <string>

namespace hemicontact
{
  /**
   * A mistake in the user's input (parameter file, mesh, expression): the
   * message names the parameter and the cause in one paragraph. main()
   * prints it without a stack trace and exits with code 2.
   */
  class InputError : public std::runtime_error
  {
  public:
    explicit InputError(const std::string &message)
      : std::runtime_error(message)
    {}
  };

  /**
   * A failure of the numerical method (Newton not converged, NaN, linear
   * solver breakdown). main() exits with code 3 after the last converged
   * state was written.
   */
  class SolverFailure : public std::runtime_error
  {
  public:
    explicit SolverFailure(const std::string &message)
      : std::runtime_error(message)
    {}
  };

  /**
   * Output could not be written (no space left on device, no permission):
   * the message names the file and the system's reason. main() exits with
   * code 6; what was written before stays valid (tables end on a complete
   * row, the .pvd series lists only complete files).
   */
  class OutputError : public std::runtime_error
  {
  public:
    explicit OutputError(const std::string &message)
      : std::runtime_error(message)
    {}
  };

  /**
   * The run stopped before its end time on request (SIGTERM or SIGINT, or
   * 'checkpoint/stop after'), after writing a checkpoint to resume from.
   * main() exits with code 5.
   */
  class RunInterrupted : public std::runtime_error
  {
  public:
    explicit RunInterrupted(const std::string &message)
      : std::runtime_error(message)
    {}
  };

  /**
   * 'adaptivity/target error' was not reached at a load value before
   * 'adaptivity/max cells' or 'max level' stopped the refinement: the
   * message names the estimate reached, the target and the limit. The
   * load value's last solution is written first. main() exits with code 7.
   */
  class TargetErrorNotReached : public std::runtime_error
  {
  public:
    explicit TargetErrorNotReached(const std::string &message)
      : std::runtime_error(message)
    {}
  };

  /** Throw an InputError with @p message unless @p condition holds. */
  inline void
  require(const bool condition, const std::string &message)
  {
    if (!condition)
      throw InputError(message);
  }

  /** @p text without leading and trailing white space, each run of white
   *  space inside it one space (a message, or a line of an input file). */
  inline std::string
  single_spaced(const std::string &text)
  {
    std::string result;
    for (const char c : text)
      if (std::isspace(static_cast<unsigned char>(c)))
        {
          if (!result.empty() && result.back() != ' ')
            result += ' ';
        }
      else
        result += c;
    if (!result.empty() && result.back() == ' ')
      result.pop_back();
    return result;
  }
} // namespace hemicontact
