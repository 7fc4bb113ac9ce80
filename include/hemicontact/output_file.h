#pragma once

#include <mpi.h>

#include <fstream>
#include <string>

namespace hemicontact
{
  /**
   * @name Output that fails cleanly
   * Writing a table row or a file either completes or leaves what was
   * there before; the reason of a failure (e.g. "No space left on device")
   * is returned, and throw_if_any() turns it into an OutputError on every
   * rank.
   */
  /** @{ */
  /**
   * Append @p text to the open @p file (at @p path) and flush. If that
   * fails, cut the file back to its size before and return the reason
   * naming @p path; else an empty string.
   */
  std::string
  append_complete(std::ofstream &file, const std::string &path,
                  const std::string &text);

  /**
   * Write @p text to @p path aside and rename it into place: @p path holds
   * either its old or its new content. Returns the reason of a failure.
   */
  std::string
  write_atomically(const std::string &path, const std::string &text);

  /** The reason of a failed write from its errno (0: "the write failed"). */
  std::string
  write_failure(int error_number);

  /** Throw an OutputError on every rank if any rank has an @p error. */
  void
  throw_if_any(const std::string &error, MPI_Comm comm);
  /** @} */

  /**
   * An exclusive lock on an output directory for the lifetime of the
   * object (an flock on DIRECTORY/.hemicontact.lock, released by the
   * system also when the process is killed): a second run writing into
   * the same directory at the same time is refused.
   */
  class OutputLock
  {
  public:
    /** Lock @p directory (which must exist); throws an InputError naming
     *  it if another process holds the lock. */
    explicit OutputLock(const std::string &directory);
    ~OutputLock();
    OutputLock(const OutputLock &) = delete;
    OutputLock &
    operator=(const OutputLock &) = delete;

  private:
    int descriptor = -1;
  };
} // namespace hemicontact
