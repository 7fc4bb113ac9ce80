#pragma once

namespace hemicontact
{
  /**
   * The hemicontact program: parse the command line (a parameter file,
   * --resume FILE, --print-parameters [prm|json], --help), initialise MPI,
   * run, and map every failure to a one-paragraph message on standard
   * error and the documented exit code (0 success, 1 usage, 2 input error,
   * 3 solver failure, 4 internal error, 5 interrupted, 6 I/O error).
   *
   * A program that links the library and registers laws of its own
   * (register_normal_law(), register_friction_law()) calls it from its
   * main() after the registrations and behaves as hemicontact with those
   * laws added.
   */
  int
  run_command_line(int argc, char **argv);
} // namespace hemicontact
