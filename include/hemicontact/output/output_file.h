#pragma once

#include <mpi.h>

#include <cstdint>
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
  append_complete(std::ofstream     &file,
                  const std::string &path,
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

  /**
   * Keep the header and the rows of @p step or earlier of the CSV table
   * @p path, whose first column is the step, and return a warning (empty:
   * none). A last row cut short (fewer fields than the header, a field
   * that is not a number, no line end: a run killed while writing it) is
   * dropped with a warning naming the file and the line. Any other row
   * that is not a complete row of numbers is refused (InputError naming
   * the file, the line and its text; the file is left unchanged). The
   * result is written aside and renamed; a failure throws an OutputError
   * and leaves neither the file changed nor the file aside behind.
   */
  std::string
  truncate_table(const std::string &path, unsigned int step);

  /**
   * Refuse (InputError on every rank, checked on the root) an output
   * @p directory in which a name the program writes is taken by something
   * else: the directory itself not a directory, a file where the run puts
   * a directory (checkpoint/, earlier_run/), a directory or another
   * non-regular file where it puts a file (steps.csv, probes.csv,
   * performance.csv, solution.pvd, solution.xdmf, convergence.csv, the
   * lock file). Touches nothing.
   */
  void
  require_usable_output_directory(const std::string &directory, MPI_Comm comm);

  /**
   * The reason a write of @p bytes into the directory @p directory cannot
   * succeed (fewer bytes free on its file system, statvfs), or an empty
   * string.
   */
  std::string
  free_space_shortfall(const std::string &directory, std::uintmax_t bytes);
  /** @} */

  /**
   * The files an earlier run left in an output directory (steps.csv,
   * probes.csv, performance.csv, the solution series and its files,
   * contact_NNNNN.csv) while a new run starts there: they are moved into
   * DIRECTORY/earlier_run before the new run writes anything, deleted
   * once it has completed its first step (keep_new_output()), and moved
   * back if it stops before (restore()). A run killed before its first
   * step leaves them in earlier_run; the next run in the directory keeps
   * them there (and deletes the killed run's files), a resume moves them
   * back. Every move is a rename within the directory; the state between
   * two moves is one the next run completes. Call on the root only.
   */
  class EarlierOutput
  {
  public:
    /**
     * Set aside the earlier run's files of @p directory (for a new run), or
     * with @p resume move back a backup a run that stopped before its
     * first step left. Throws an OutputError naming the file that could
     * not be moved.
     */
    void
    set_aside(const std::string &directory, bool resume);

    /** Whether files are set aside and the new run has not kept its own. */
    bool
    pending() const
    {
      return !directory.empty();
    }

    /** The new run has produced its own output: delete the backup.
     *  Returns the reason of a failure. */
    std::string
    keep_new_output();

    /** The new run stopped before its first step: delete its files and
     *  move the earlier run's back. Returns the reason of a failure. */
    std::string
    restore();

  private:
    /** The output directory while files are set aside, else empty. */
    std::string directory;
  };

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
