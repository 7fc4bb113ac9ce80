#include <deal.II/base/mpi.h>

#include <hemicontact/input_error.h>
#include <hemicontact/output_file.h>

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <system_error>

namespace hemicontact
{
  namespace
  {
    std::string
    reason(const std::string &path, const int error_number)
    {
      return "cannot write '" + path + "': " + write_failure(error_number) +
             ".";
    }
  } // namespace

  std::string
  write_failure(const int error_number)
  {
    return error_number != 0 ? std::strerror(error_number) :
                               "the write failed";
  }

  std::string
  append_complete(std::ofstream &file, const std::string &path,
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
      std::filesystem::resize_file(path, static_cast<std::uintmax_t>(before),
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
          std::filesystem::remove(aside, ec);
          return "cannot write '" + path + "': " + ec.message() + ".";
        }
    }
    const int       error_number = errno;
    std::error_code ec;
    std::filesystem::remove(aside, ec);
    return reason(path, error_number);
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
