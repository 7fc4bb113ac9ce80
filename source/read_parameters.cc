// Reading a parameter file: declare every entry, parse the file (or a
// string) and turn deal.II's exceptions into one-paragraph InputErrors.
#include <deal.II/base/exceptions.h>

#include <hemicontact/friction_law.h>
#include <hemicontact/input_error.h>
#include <hemicontact/normal_law.h>
#include <hemicontact/parameters.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <iterator>
#include <set>
#include <fstream>
#include <sstream>

namespace hemicontact
{
  void
  declare_all_parameters(ParameterHandler &prm)
  {
    Parameters::declare(prm);
    declare_normal_law_parameters(prm);
    declare_friction_law_parameters(prm);
  }

  namespace
  {
    /**
     * The entries of @p prm that define the problem, as "path/entry =
     * value", from its short listing (subsection / set / end lines).
     */
    std::vector<std::string>
    problem_definition(const ParameterHandler &prm)
    {
      static const std::set<std::string> not_defining = {
        "output", "checkpoint", "linear solver", "nonlinear solver",
        "convergence study"};
      std::ostringstream listing;
      prm.print_parameters(listing, ParameterHandler::ShortPRM);
      std::istringstream       in(listing.str());
      std::vector<std::string> path, entries;
      std::string              line;
      while (std::getline(in, line))
        {
          const std::size_t start = line.find_first_not_of(' ');
          if (start == std::string::npos)
            continue;
          line = line.substr(start);
          if (line.rfind("subsection ", 0) == 0)
            path.push_back(line.substr(11));
          else if (line == "end")
            path.pop_back();
          else if (line.rfind("set ", 0) == 0 &&
                   (path.empty() || not_defining.count(path.front()) == 0))
            {
              std::string prefix;
              for (const std::string &p : path)
                prefix += p + "/";
              entries.push_back(prefix + line.substr(4));
            }
        }
      return entries;
    }

    /**
     * The message of a deal.II exception without its stack trace, with
     * its line breaks and indentation collapsed into one paragraph.
     */
    std::string
    message_of(const ExceptionBase &e)
    {
      std::ostringstream s;
      e.print_info(s);
      std::string message;
      for (const char c : s.str())
        if (std::isspace(static_cast<unsigned char>(c)))
          {
            if (!message.empty() && message.back() != ' ')
              message += ' ';
          }
        else
          message += c;
      while (!message.empty() && message.back() == ' ')
        message.pop_back();
      return message;
    }

    template <typename ParseFunction>
    Parameters
    read_with(ParameterHandler &prm, const std::string &source,
              const ParseFunction &parse)
    {
      declare_all_parameters(prm);
      try
        {
          parse();
        }
      catch (const ExceptionBase &e)
        {
          throw InputError("cannot read the parameter file " + source + ": " +
                           message_of(e));
        }
      Parameters parameters;
      try
        {
          parameters.parse(prm);
          parameters.problem_definition = problem_definition(prm);
        }
      catch (const ExceptionBase &e)
        {
          throw InputError("invalid value in the parameter file " + source +
                           ": " + message_of(e));
        }
      return parameters;
    }
  } // namespace

  Parameters
  read_parameters(ParameterHandler &prm, const std::string &filename)
  {
    return read_parameters(prm, filename, "");
  }

  Parameters
  read_parameters(ParameterHandler &prm, const std::string &filename,
                  const std::string &overrides)
  {
    std::string text;
    {
      std::error_code ec;
      require(!std::filesystem::is_directory(filename, ec),
              "the parameter file '" + filename +
                "' is a directory; give the .prm file in it.");
      std::ifstream probe(filename, std::ios::binary);
      require(static_cast<bool>(probe),
              "cannot open the parameter file '" + filename +
                "': no such file or not readable.");
      text.assign(std::istreambuf_iterator<char>(probe),
                  std::istreambuf_iterator<char>());
      require(text.find_first_not_of(" \t\r\n") != std::string::npos,
              "the parameter file '" + filename +
                "' is empty; it must at least set what differs from the "
                "defaults (hemicontact --print-parameters lists them).");
    }
    {
      const std::string head = text.substr(0, 4096);
      require(std::none_of(head.begin(), head.end(),
                           [](const char c) {
                             const auto u = static_cast<unsigned char>(c);
                             return u < 32 && c != '\t' && c != '\n' &&
                                    c != '\r' && c != '\f';
                           }),
              "the parameter file '" + filename +
                "' is not a text file (it holds control characters); give "
                "a .prm file (hemicontact --print-parameters writes one).");
    }
    // a UTF-8 byte order mark (written by some editors) is not part of the
    // first line
    const bool bom = text.rfind("\xEF\xBB\xBF", 0) == 0;
    return read_with(prm, "'" + filename + "'", [&]() {
      if (bom)
        prm.parse_input_from_string(text.substr(3), "", false);
      else
        prm.parse_input(filename);
      if (!overrides.empty())
        prm.parse_input_from_string(overrides);
    });
  }

  Parameters
  read_parameters_from_string(ParameterHandler &prm, const std::string &text)
  {
    return read_with(prm, "(string)",
                     [&]() { prm.parse_input_from_string(text); });
  }
} // namespace hemicontact
