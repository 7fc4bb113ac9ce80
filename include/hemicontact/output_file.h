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

  /** Throw an OutputError on every rank if any rank has an @p error. */
  void
  throw_if_any(const std::string &error, MPI_Comm comm);
  /** @} */
} // namespace hemicontact
