#include <deal.II/base/mpi.h>

#include <hemicontact/base/exceptions.h>
#include <hemicontact/output/output_file.h>

#include <fcntl.h>
#include <sys/file.h>
#include <sys/statvfs.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <regex>
#include <sstream>
#include <system_error>
#include <vector>

namespace hemicontact
{
  namespace
  {
    namespace fs = std::filesystem;

    std::string
    reason(const std::string &path, const int error_number)
    {
      return "cannot write '" + path + "': " + write_failure(error_number) +
             ".";
    }

    /** The fields of a CSV line. */
    std::vector<std::string>
    split_fields(const std::string &line)
    {
      std::vector<std::string> fields;
      std::istringstream       in(line);
      std::string              field;
      while (std::getline(in, field, ','))
        fields.push_back(field);
      if (!line.empty() && line.back() == ',')
        fields.emplace_back();
      return fields;
    }

    /** Whether @p field is a number as the tables write them. */
    bool
    is_number(const std::string &field)
    {
      if (field.empty())
        return false;
      char *end = nullptr;
      std::strtod(field.c_str(), &end);
      return end == field.c_str() + field.size();
    }

    /** Whether @p line is a row of @p n_fields numbers or empty fields, the
     *  first a step. */
    bool
    is_complete_row(const std::string &line, const std::size_t n_fields)
    {
      const std::vector<std::string> fields = split_fields(line);
      if (fields.size() != n_fields ||
          fields[0].find_first_not_of("0123456789") != std::string::npos)
        return false;
      // an empty field is a value not evaluated at that step (the error
      // estimate's columns with 'output/error estimate = false')
      for (const std::string &field : fields)
        if (!field.empty() && !is_number(field))
          return false;
      return true;
    }

    /** @p text shortened for a message. */
    std::string
    excerpt(const std::string &text)
    {
      return text.size() <= 60 ? text : text.substr(0, 60) + "...";
    }

    /** Whether @p name is a file a run writes into its output directory
     *  (or such a file being written aside). */
    bool
    is_run_file(const std::string &name)
    {
      static const std::regex pattern(
        "((steps|probes|performance)\\.csv|(solution|nodal)\\.(pvd|xdmf)|"
        "nodal_[0-9]+\\.h5|"
        "solution_[0-9]+(\\.[0-9]+)?\\.(vtu|pvtu|h5)|contact_[0-9]+\\.csv)"
        "(\\.tmp)?");
      return std::regex_match(name, pattern);
    }

    /** The run files directly in @p directory. */
    std::vector<fs::path>
    run_files(const fs::path &directory)
    {
      std::vector<fs::path> files;
      std::error_code       ec;
      for (const auto &entry : fs::directory_iterator(directory, ec))
        if (is_run_file(entry.path().filename().string()) &&
            !entry.is_directory(ec))
          files.push_back(entry.path());
      return files;
    }

    /** Move @p files into the directory @p to; the reason of a failure. */
    std::string
    move_files(const std::vector<fs::path> &files, const fs::path &to)
    {
      for (const fs::path &file : files)
        {
          std::error_code ec;
          fs::rename(file, to / file.filename(), ec);
          if (ec)
            return "cannot move '" + file.string() + "' to '" + to.string() +
                   "': " + ec.message() + ".";
        }
      return "";
    }

    /** Delete @p files; the reason of a failure. */
    std::string
    remove_files(const std::vector<fs::path> &files)
    {
      for (const fs::path &file : files)
        {
          std::error_code ec;
          fs::remove(file, ec);
          if (ec)
            return "cannot delete '" + file.string() + "': " + ec.message() +
                   ".";
        }
      return "";
    }

    /** The files of the directory @p directory (none if it does not exist). */
    std::vector<fs::path>
    files_in(const fs::path &directory)
    {
      std::vector<fs::path> files;
      std::error_code       ec;
      for (const auto &entry : fs::directory_iterator(directory, ec))
        files.push_back(entry.path());
      return files;
    }

    /** Why the fixed names of a run in @p directory cannot be used, or "". */
    std::string
    unusable_output_name(const fs::path &directory)
    {
      std::error_code       ec;
      const fs::file_status status = fs::status(directory, ec);
      if (!fs::exists(status))
        return "";
      if (!fs::is_directory(status))
        return "cannot create the output directory '" + directory.string() +
               "': Not a directory.";
      const std::string advice =
        "; rename or remove it, or set another 'output/directory'.";
      for (const char *name : {"steps.csv",
                               "probes.csv",
                               "performance.csv",
                               "solution.pvd",
                               "solution.xdmf",
                               "nodal.xdmf",
                               "convergence.csv",
                               ".hemicontact.lock"})
        {
          const fs::file_status s = fs::status(directory / name, ec);
          if (fs::exists(s) && !fs::is_regular_file(s))
            return "'" + (directory / name).string() + "' " +
                   (fs::is_directory(s) ? "is a directory" :
                                          "is not a regular file") +
                   ", and the run writes a file of that name" + advice;
        }
      for (const char *name : {"checkpoint", "earlier_run"})
        {
          const fs::file_status s = fs::status(directory / name, ec);
          if (fs::exists(s) && !fs::is_directory(s))
            return "'" + (directory / name).string() +
                   "' is not a directory, and the run writes a directory of "
                   "that name" +
                   advice;
        }
      return "";
    }
  } // namespace

  std::string
  write_failure(const int error_number)
  {
    return error_number != 0 ? std::strerror(error_number) : "the write failed";
  }

  std::string
  append_complete(std::ofstream     &file,
                  const std::string &path,
                  const std::string &text)
  {
    const std::streampos before = file.tellp();
    errno                       = 0;
    file << text;
    file.flush();
    if (file)
      return "";
    const int error_number = errno;
    file.close();
    std::error_code ec;
    if (before >= 0)
      std::filesystem::resize_file(path,
                                   static_cast<std::uintmax_t>(before),
                                   ec);
    return reason(path, error_number);
  }

  std::string
  write_atomically(const std::string &path, const std::string &text)
  {
    const std::string aside = path + ".tmp";
    errno                   = 0;
    {
      std::ofstream out(aside);
      out << text;
      out.flush();
      if (out)
        {
          out.close();
          std::error_code ec;
          std::filesystem::rename(aside, path, ec);
          if (!ec)
            return "";
          std::error_code removal;
          std::filesystem::remove(aside, removal);
          return "cannot write '" + path + "': " + ec.message() + ".";
        }
    }
    const int       error_number = errno;
    std::error_code ec;
    std::filesystem::remove(aside, ec);
    return reason(path, error_number);
  }

  std::string
  truncate_table(const std::string &path, const unsigned int step)
  {
    std::ifstream in(path, std::ios::binary);
    if (!in)
      return "";
    const std::string content((std::istreambuf_iterator<char>(in)),
                              std::istreambuf_iterator<char>());
    in.close();
    // the lines, and whether the last one has its line end
    std::vector<std::string> lines;
    for (std::size_t begin = 0; begin < content.size();)
      {
        const std::size_t end = content.find('\n', begin);
        lines.push_back(content.substr(begin, end - begin));
        begin = end == std::string::npos ? content.size() : end + 1;
      }
    const bool last_ended = !content.empty() && content.back() == '\n';
    require(!lines.empty() && (lines.size() > 1 || last_ended),
            "checkpoint: '" + path +
              "' has no complete header line: the table cannot be "
              "continued. Delete it, or start a new run without --resume.");

    const std::size_t  n_fields = split_fields(lines[0]).size();
    std::string        kept     = lines[0] + "\n";
    std::string        warning;
    unsigned long long last_kept = 0;
    for (std::size_t i = 1; i < lines.size(); ++i)
      {
        const std::string &line = lines[i];
        const bool         last = i + 1 == lines.size();
        if (line.empty())
          continue;
        if (!is_complete_row(line, n_fields) || (last && !last_ended))
          {
            require(last,
                    "checkpoint: line " + std::to_string(i + 1) + " of '" +
                      path + "' is not a complete row of numbers ('" +
                      excerpt(line) +
                      "'): the table cannot be continued. Repair or delete "
                      "that line, or start a new run without --resume.");
            warning = "line " + std::to_string(i + 1) + " of '" + path +
                      "' is cut short ('" + excerpt(line) +
                      "'; a run stopped while writing it): dropped.";
            continue;
          }
        const unsigned long long row_step =
          std::strtoull(line.c_str(), nullptr, 10);
        if (row_step <= step)
          {
            kept += line + "\n";
            last_kept = row_step;
          }
      }
    if (!warning.empty() && last_kept < step)
      warning += " The table has no row of step " + std::to_string(step) +
                 " (the checkpoint's), its last row is of step " +
                 std::to_string(last_kept) + ".";
    if (kept == content)
      return warning;

    // aside, then renamed: the table is either as it was or cut
    const std::string aside = path + ".tmp";
    errno                   = 0;
    std::ofstream out(aside, std::ios::binary);
    out << kept;
    out.close();
    std::error_code ec;
    if (!out)
      {
        const int error_number = errno;
        fs::remove(aside, ec);
        throw OutputError(reason(path, error_number));
      }
    fs::rename(aside, path, ec);
    if (ec)
      {
        std::error_code removal;
        fs::remove(aside, removal);
        throw OutputError("cannot write '" + path + "': " + ec.message() + ".");
      }
    return warning;
  }

  void
  require_usable_output_directory(const std::string &directory,
                                  const MPI_Comm     comm)
  {
    std::string error;
    if (dealii::Utilities::MPI::this_mpi_process(comm) == 0)
      error = unusable_output_name(directory);
    error = dealii::Utilities::MPI::broadcast(comm, error, 0);
    require(error.empty(), "output: " + error);
  }

  std::string
  free_space_shortfall(const std::string &directory, const std::uintmax_t bytes)
  {
    struct statvfs file_system;
    if (::statvfs(directory.c_str(), &file_system) != 0)
      return ""; // unknown: the write itself reports
    const std::uintmax_t available =
      static_cast<std::uintmax_t>(file_system.f_bavail) * file_system.f_frsize;
    if (available >= bytes)
      return "";
    return "No space left on device (about " + std::to_string(bytes / 1024) +
           " KiB needed, " + std::to_string(available / 1024) + " KiB free)";
  }

  void
  EarlierOutput::set_aside(const std::string &output_directory,
                           const bool         resume)
  {
    const fs::path  dir    = output_directory;
    const fs::path  backup = dir / "earlier_run";
    const fs::path  moving = dir / "earlier_run.tmp"; // a move in progress
    std::error_code ec;
    fs::remove_all(dir / "earlier_run.old", ec); // a deletion cut short
    const bool has_backup = fs::exists(backup) || fs::exists(moving);
    if (resume)
      {
        // the checkpoints are those of the run in the backup
        if (has_backup)
          {
            directory               = output_directory;
            const std::string error = restore();
            if (!error.empty())
              throw OutputError(error);
          }
        return;
      }
    std::string error;
    if (fs::exists(backup))
      // the files at the top are those of a run that stopped before its
      // first step
      error = remove_files(run_files(dir));
    else
      {
        const std::vector<fs::path> files = run_files(dir);
        if (files.empty() && !fs::exists(moving))
          return;
        fs::create_directory(moving, ec);
        if (ec)
          throw OutputError("cannot create '" + moving.string() +
                            "': " + ec.message() + ".");
        error = move_files(files, moving);
        if (error.empty())
          {
            fs::rename(moving, backup, ec);
            if (ec)
              error = "cannot rename '" + moving.string() + "' to '" +
                      backup.string() + "': " + ec.message() + ".";
          }
      }
    if (!error.empty())
      throw OutputError(error);
    directory = output_directory;
  }

  std::string
  EarlierOutput::keep_new_output()
  {
    if (!pending())
      return "";
    const fs::path dir = directory;
    directory.clear();
    // renamed first: a deletion cut short is never taken for a backup
    std::error_code ec;
    fs::rename(dir / "earlier_run", dir / "earlier_run.old", ec);
    if (!ec)
      fs::remove_all(dir / "earlier_run.old", ec);
    return ec ? "cannot delete the earlier run's files in '" +
                  (dir / "earlier_run").string() + "': " + ec.message() + "." :
                "";
  }

  std::string
  EarlierOutput::restore()
  {
    if (!pending())
      return "";
    const fs::path dir    = directory;
    const fs::path moving = dir / "earlier_run.tmp";
    directory.clear();
    std::string     error = remove_files(run_files(dir));
    std::error_code ec;
    if (error.empty() && fs::exists(dir / "earlier_run"))
      {
        fs::rename(dir / "earlier_run", moving, ec);
        if (ec)
          error = "cannot rename '" + (dir / "earlier_run").string() +
                  "': " + ec.message() + ".";
      }
    if (error.empty())
      error = move_files(files_in(moving), dir);
    if (error.empty())
      fs::remove(moving, ec);
    return error.empty() ? "" :
                           error + " The earlier run's files are in '" +
                             (dir / "earlier_run").string() + "' or '" +
                             moving.string() + "'.";
  }

  OutputLock::OutputLock(const std::string &directory)
  {
    const std::string path = directory + "/.hemicontact.lock";
    descriptor             = ::open(path.c_str(), O_RDWR | O_CREAT, 0644);
    if (descriptor < 0)
      throw OutputError("cannot create the lock file '" + path +
                        "': " + std::strerror(errno) + ".");
    if (::flock(descriptor, LOCK_EX | LOCK_NB) != 0)
      {
        ::close(descriptor);
        descriptor = -1;
        throw InputError(
          "another hemicontact run is writing into '" + directory +
          "' (it holds '" + path +
          "'); two runs in one output directory would mix their files. Set "
          "another 'output/directory', or wait for the other run to end.");
      }
  }

  OutputLock::~OutputLock()
  {
    if (descriptor >= 0)
      ::close(descriptor);
  }

  void
  throw_if_any(const std::string &error, MPI_Comm comm)
  {
    for (const std::string &message :
         dealii::Utilities::MPI::all_gather(comm, error))
      if (!message.empty())
        throw OutputError(message);
  }
} // namespace hemicontact
