/**
 * hemicontact: dynamic frictional contact with hemivariational laws.
 *
 *   hemicontact file.prm           run
 *   hemicontact --print-parameters print the documented default file
 *   hemicontact --help
 *
 * The program is run_command_line() of the library, so that a program of
 * one's own that registers further laws behaves the same way.
 */
#include <hemicontact/simulation/command_line.h>

int
main(int argc, char **argv)
{
  return hemicontact::run_command_line(argc, argv);
}
