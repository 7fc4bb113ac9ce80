/**
 * @file
 * The executable the parameter-file tests run: hemicontact with its
 * standard error joined to its standard output, in this process.
 *
 * A test's expected output is what the program prints on both streams, in
 * order. Under mpirun each rank's two streams reach the terminal through
 * separate channels, so a warning on standard error could land before or
 * after the standard-output lines printed around it. Joining the streams
 * in the rank itself (as the shell's `2>&1` does for one process) gives
 * one channel and the program's own order.
 */

#include <unistd.h>

#include <cstdio>

int
main(int /*argc*/, char *argv[])
{
  if (dup2(STDOUT_FILENO, STDERR_FILENO) < 0)
    {
      std::perror("hemicontact_merged_streams: dup2");
      return 127;
    }
  argv[0] = const_cast<char *>(HEMICONTACT_EXECUTABLE);
  execv(HEMICONTACT_EXECUTABLE, argv);
  std::perror("hemicontact_merged_streams: execv " HEMICONTACT_EXECUTABLE);
  return 127;
}
