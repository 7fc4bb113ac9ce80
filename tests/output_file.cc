// Output that fails cleanly: write_atomically() onto a directory names the
// file and the system's reason ("Is a directory") and leaves no file aside;
// truncate_table() keeps the rows up to a step, drops a last row cut short
// with a warning naming the line, refuses a damaged row in the middle
// (naming the file and the line, the file unchanged, nothing aside), and
// leaves a table without rows to cut unchanged.
#include <hemicontact/base/exceptions.h>
#include <hemicontact/output/output_file.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "tests.h"

using namespace hemicontact;
namespace fs = std::filesystem;

namespace
{
  std::string
  read(const fs::path &file)
  {
    std::ifstream      in(file);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
  }

  void
  write(const fs::path &file, const std::string &text)
  {
    std::ofstream(file) << text;
  }

  /** truncate_table() on @p text, reported with the table it leaves. */
  void
  truncate(const std::string &what,
           const std::string &text,
           const unsigned int step)
  {
    write("table.csv", text);
    out() << what << ":\n";
    try
      {
        const std::string warning = truncate_table("table.csv", step);
        out() << "  warning: '" << warning << "'\n";
      }
    catch (const InputError &e)
      {
        out() << "  refused: " << e.what() << "\n";
      }
    out() << "  table: '" << read("table.csv") << "'\n"
          << "  aside left: " << fs::exists("table.csv.tmp") << "\n";
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  fs::remove_all("work");
  fs::create_directory("work");
  fs::current_path("work");

  out() << "write: '" << write_atomically("series.pvd", "new") << "', "
        << read("series.pvd") << "\n";
  fs::create_directory("directory.pvd");
  out() << "onto a directory: '" << write_atomically("directory.pvd", "new")
        << "', aside left: " << fs::exists("directory.pvd.tmp") << "\n";

  const std::string header = "step,time,value\n";
  truncate("rows after step 2 go", header + "1,0.1,5\n2,0.2,6\n3,0.3,7\n", 2);
  truncate("nothing to cut", header + "1,0.1,5\n2,0.2,6\n", 2);
  truncate("a last row cut short after the step",
           header + "1,0.1,5\n2,0.2,6\n3,0.3",
           2);
  truncate("a last row cut short at the step",
           header + "1,0.1,5\n2,0.2,6\n3,0.3,",
           3);
  truncate("a last row without its line end", header + "1,0.1,5\n2,0.2,6", 2);
  truncate("a line that is not numbers in the middle",
           header + "1,0.1,5\nnot a row\n2,0.2,6\n",
           2);
  truncate("a row with a field too many in the middle",
           header + "1,0.1,5,9\n2,0.2,6\n",
           2);
  truncate("non-finite values are numbers",
           header + "1,nan,inf\n2,-nan,-inf\n",
           2);
  truncate("no header", "", 2);
}
