// Reading a parameter file: declare every entry, parse the file (or a
// string) and turn deal.II's exceptions into one-paragraph InputErrors.
#include <deal.II/base/exceptions.h>

#include <boost/property_tree/json_parser.hpp>
#include <boost/property_tree/ptree.hpp>

#include <hemicontact/base/exceptions.h>
#include <hemicontact/input/parameters.h>
#include <hemicontact/laws/friction_law.h>
#include <hemicontact/laws/normal_law.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <set>
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
     * The entries of @p prm that define the problem and the output entries
     * that name the series files, as "path/entry = value", from its short
     * listing (subsection / set / end lines).
     */
    std::vector<std::string>
    problem_definition(const ParameterHandler &prm)
    {
      static const std::set<std::string> not_defining   = {"output",
                                                           "checkpoint",
                                                           "linear solver",
                                                           "nonlinear solver",
                                                           "convergence study"};
      static const std::set<std::string> series_entries = {"output/format",
                                                           "output/precision"};
      std::ostringstream                 listing;
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
          else if (line.rfind("set ", 0) == 0)
            {
              std::string prefix;
              for (const std::string &p : path)
                prefix += p + "/";
              // "set NAME = VALUE", NAME padded to its subsection's longest
              const std::size_t eq   = line.find(" = ");
              const std::string name = line.substr(4, eq - 4);
              const std::string path_name =
                prefix + name.substr(0, name.find_last_not_of(' ') + 1);
              if (path.empty() || not_defining.count(path.front()) == 0 ||
                  series_entries.count(path_name) > 0)
                entries.push_back(path_name + " = " +
                                  (eq == std::string::npos ?
                                     std::string() :
                                     line.substr(eq + 3)));
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
      return single_spaced(s.str());
    }

    /**
     * Throw an InputError if the .prm @p text sets an entry twice within
     * one subsection block (between a 'subsection' and its 'end', or at the
     * top level), naming the entry and both lines of @p filename: deal.II
     * would take the last value silently. A later block of the same
     * subsection may set an entry again (scripts append such blocks to
     * override a file's values).
     */
    void
    require_each_entry_once_in_prm(const std::string &text,
                                   const std::string &filename)
    {
      std::istringstream       in(text);
      std::vector<std::string> path;
      // per open block: the line of each entry set in it
      std::vector<std::map<std::string, unsigned int>> blocks(1);
      std::string                                      line, statement;
      unsigned int line_number = 0, start = 0;
      while (std::getline(in, line))
        {
          ++line_number;
          if (statement.empty())
            start = line_number;
          // a line ending in a backslash continues on the next one
          const std::size_t end = line.find_last_not_of(" \t\r");
          if (end != std::string::npos && line[end] == '\\')
            {
              statement += line.substr(0, end) + " ";
              continue;
            }
          statement += line;
          const std::size_t comment = statement.find('#');
          const std::string s = single_spaced(statement.substr(0, comment));
          statement.clear();
          if (s.rfind("subsection ", 0) == 0)
            {
              path.push_back(single_spaced(s.substr(11)));
              blocks.emplace_back();
            }
          else if (s == "end" && !path.empty())
            {
              path.pop_back();
              blocks.pop_back();
            }
          else if (s.rfind("set ", 0) == 0 && s.find('=') != std::string::npos)
            {
              const std::string name =
                single_spaced(s.substr(4, s.find('=') - 4));
              const auto known = blocks.back().emplace(name, start);
              if (known.second)
                continue;
              std::string entry;
              for (const std::string &p : path)
                entry += p + "/";
              throw InputError("the parameter file '" + filename + "' sets '" +
                               entry + name +
                               "' twice in one subsection, on line " +
                               std::to_string(known.first->second) +
                               " and on line " + std::to_string(start) +
                               "; keep one (neither is chosen silently).");
            }
        }
    }

    /** Throw an InputError naming the key path (e.g. "time/end time") of
     *  a key that occurs twice in one object of the JSON @p tree. */
    void
    require_each_key_once(const boost::property_tree::ptree &tree,
                          const std::string                 &prefix,
                          const std::string                 &filename)
    {
      std::set<std::string> seen;
      for (const auto &child : tree)
        {
          if (child.first.empty()) // an element of an array
            continue;
          require(seen.insert(child.first).second,
                  "the parameter file '" + filename + "' has the key '" +
                    prefix + child.first +
                    "' twice; keep one (neither is chosen silently).");
          require_each_key_once(child.second,
                                prefix + child.first + "/",
                                filename);
        }
    }

    /** The same for the JSON @p text; a file that is not valid JSON is
     *  left to deal.II's reader, which reports where. */
    void
    require_each_entry_once_in_json(const std::string &text,
                                    const std::string &filename)
    {
      boost::property_tree::ptree tree;
      std::istringstream          in(text);
      try
        {
          boost::property_tree::read_json(in, tree);
        }
      catch (const boost::property_tree::json_parser_error &)
        {
          return;
        }
      require_each_key_once(tree, "", filename);
    }

    /**
     * Throw an InputError naming the key path of the first subsection or
     * entry of the JSON @p tree that @p declared (the JSON listing of the
     * declared parameters, where an entry has a "value" or an "alias"
     * child) lacks, as the .prm reader names an unknown subsection or
     * entry; deal.II's JSON reader names only the first entry below it.
     * In @p tree an entry is a string or an object with a "value" key.
     */
    void
    require_declared(const boost::property_tree::ptree &tree,
                     const boost::property_tree::ptree &declared,
                     const std::string                 &prefix,
                     const std::string                 &filename)
    {
      const auto is_entry = [](const boost::property_tree::ptree &node) {
        return node.empty() || node.count("value") > 0;
      };
      for (const auto &[key, node] : tree)
        {
          if (key.empty()) // an element of an array: deal.II reports it
            continue;
          const auto known          = declared.find(key);
          const bool entry          = is_entry(node);
          const bool declared_entry = known != declared.not_found() &&
                                      (known->second.count("value") > 0 ||
                                       known->second.count("alias") > 0);
          const std::string where =
            prefix.empty() ?
              "at the top level" :
              "in subsection '" + prefix.substr(0, prefix.size() - 1) + "'";
          require(known != declared.not_found(),
                  "the parameter file '" + filename + "' has the " +
                    (entry ? "entry '" : "subsection '") + prefix + key +
                    "', but there is no such " +
                    (entry ? "entry" : "subsection") + " " + where +
                    " (hemicontact --print-parameters json lists every "
                    "subsection and entry).");
          require(entry == declared_entry,
                  "the parameter file '" + filename + "' gives '" + prefix +
                    key + "' as " +
                    (entry ? "an entry (a value)" :
                             "a subsection (an object)") +
                    ", but it is " +
                    (declared_entry ? "an entry" : "a subsection") + " " +
                    where + ".");
          if (!entry)
            require_declared(node, known->second, prefix + key + "/", filename);
        }
    }

    /** The same for the JSON @p text against the entries declared in
     *  @p prm; a file that is not valid JSON is left to deal.II's reader,
     *  which reports where. */
    void
    require_declared_in_json(const std::string      &text,
                             const std::string      &filename,
                             const ParameterHandler &prm)
    {
      boost::property_tree::ptree tree, declared;
      std::istringstream          in(text);
      try
        {
          boost::property_tree::read_json(in, tree);
        }
      catch (const boost::property_tree::json_parser_error &)
        {
          return;
        }
      std::stringstream listing;
      prm.print_parameters(listing, ParameterHandler::JSON);
      boost::property_tree::read_json(listing, declared);
      require_declared(tree, declared, "", filename);
    }

    /** "json", "xml" or "prm": how deal.II reads @p filename (by its
     *  extension, in any case; anything else is .prm). */
    std::string
    format_of(const std::string &filename)
    {
      std::string extension = std::filesystem::path(filename).extension();
      std::transform(extension.begin(),
                     extension.end(),
                     extension.begin(),
                     [](const unsigned char c) { return std::tolower(c); });
      if (extension == ".json")
        return "json";
      if (extension == ".xml")
        return "xml";
      return "prm";
    }

    template <typename ParseFunction>
    Parameters
    read_with(ParameterHandler    &prm,
              const std::string   &source,
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
  read_parameters(ParameterHandler  &prm,
                  const std::string &filename,
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
      require(std::none_of(head.begin(),
                           head.end(),
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
    const bool        bom    = text.rfind("\xEF\xBB\xBF", 0) == 0;
    const std::string body   = bom ? text.substr(3) : text;
    const std::string format = format_of(filename);
    if (format == "prm")
      require_each_entry_once_in_prm(body, filename);
    else if (format == "json")
      require_each_entry_once_in_json(body, filename);
    return read_with(prm, "'" + filename + "'", [&]() {
      std::istringstream in(body);
      if (format == "json")
        {
          require_declared_in_json(body, filename, prm);
          prm.parse_input_from_json(in);
        }
      else if (format == "xml")
        prm.parse_input_from_xml(in);
      else if (bom)
        prm.parse_input_from_string(body, "", false);
      else
        prm.parse_input(filename);
      if (!overrides.empty())
        prm.parse_input_from_string(overrides);
    });
  }

  Parameters
  read_parameters_from_string(ParameterHandler &prm, const std::string &text)
  {
    return read_with(prm, "(string)", [&]() {
      prm.parse_input_from_string(text);
    });
  }
} // namespace hemicontact
