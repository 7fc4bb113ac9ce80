/**
 * The command line of hemicontact
 * (include/hemicontact/simulation/command_line.h).
 */
#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include <hemicontact/base/exceptions.h>
#include <hemicontact/input/parameters.h>
#include <hemicontact/laws/contact_laws.h>
#include <hemicontact/model/step_scheme.h>
#include <hemicontact/problem/contact_problem.h>
#include <hemicontact/problem/equilibrated_estimate.h>
#include <hemicontact/simulation/command_line.h>
#include <hemicontact/simulation/simulation.h>
#include <hemicontact/verification/convergence_study.h>

#include <cstdlib>
#include <iostream>
#include <sstream>
#include <string>

namespace hemicontact
{

  namespace
  {
    void
    print_help()
    {
      std::cout
        << "hemicontact - dynamic viscoelastic contact with a nonmonotone normal\n"
           "damped response and friction (Han & Han 2019, Problem 4.4).\n\n"
           "Usage:\n"
           "  hemicontact FILE.prm            run the problem described in FILE\n"
           "  mpirun -np N hemicontact FILE   the same on N MPI ranks\n"
           "  hemicontact --resume FILE.prm   continue the run of FILE from its\n"
           "                                  newest checkpoint\n"
           "  hemicontact --print-parameters [prm|json]\n"
           "                                  print every parameter with its\n"
           "                                  default value and documentation\n"
           "                                  (.prm form, or JSON; a FILE.json\n"
           "                                  is read as JSON, FILE.xml as XML)\n"
           "  hemicontact --help              this text\n\n"
           "Exit codes: 0 success, 1 usage, 2 input error, 3 solver failure,\n"
           "4 internal error, 5 interrupted (SIGTERM, SIGINT or 'checkpoint/stop\n"
           "after'; a checkpoint was written: continue with --resume), 6 I/O error\n"
           "(output could not be written, e.g. no space left on device; what\n"
           "was written before stays valid), 7 target error not reached\n"
           "('adaptivity/target error': the mesh limit came first).\n";
    }

    int
    run_program(int argc, char **argv)
    {
      const std::string argument = argc > 1 ? argv[1] : "";
      if (argument == "--help" || argument == "-h")
        {
          print_help();
          return 0;
        }
      if (argument == "--print-parameters")
        {
          const std::string format = argc > 2 ? argv[2] : "prm";
          if (argc > 3 || (format != "prm" && format != "json"))
            {
              std::cerr << "hemicontact: --print-parameters takes 'prm' "
                           "(the default) or 'json'.\n";
              return 1;
            }
          ParameterHandler prm;
          declare_all_parameters(prm);
          prm.print_parameters(std::cout,
                               (format == "json" ? ParameterHandler::JSON :
                                                   ParameterHandler::PRM) |
                                 ParameterHandler::KeepDeclarationOrder);
          return 0;
        }
      const bool        resume = argument == "--resume" && argc == 3;
      const std::string file   = resume ? argv[2] : argument;
      if ((argc != 2 && !resume) || file.empty() || file[0] == '-')
        {
          std::cerr << "hemicontact: expected exactly one parameter file "
                       "(or --resume FILE, --help, --print-parameters).\n";
          return 1;
        }

      ParameterHandler prm;
      const Parameters parameters =
        resume ?
          read_parameters(prm,
                          file,
                          "subsection checkpoint\n  set resume = true\nend\n") :
          read_parameters(prm, file);
      require_equilibrated_usable(parameters);
      if (const std::string note =
            StepScheme(parameters.problem).ignored_parameters(parameters);
          !note.empty() &&
          Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
        std::cerr << "hemicontact: note: " << note << std::endl;
      if (parameters.manufactured.enabled)
        {
          if (parameters.dimension == 2)
            run_convergence_study<2>(parameters, prm, MPI_COMM_WORLD);
          else
            run_convergence_study<3>(parameters, prm, MPI_COMM_WORLD);
          return 0;
        }
      ContactLaws laws = create_contact_laws(prm);
      if (parameters.dimension == 2)
        {
          ContactProblem<2> problem(parameters,
                                    std::move(laws),
                                    MPI_COMM_WORLD);
          Simulation<2>(problem).run();
        }
      else
        {
          ContactProblem<3> problem(parameters,
                                    std::move(laws),
                                    MPI_COMM_WORLD);
          Simulation<3>(problem).run();
        }
      return 0;
    }
  } // namespace

  int
  run_command_line(int argc, char **argv)
  {
    // OpenMPI's MPI-IO guards every file open (the checkpoints' field data)
    // with a named POSIX semaphore of its 'sm' shared-file-pointer component,
    // keyed by the file's name. A run killed inside that open leaves the
    // semaphore taken, and every later run that opens a file of the same
    // name (the resume) waits for it forever. The other components lock with
    // fcntl, which the system releases when a process dies; a user's own
    // setting of the variable is kept.
    setenv("OMPI_MCA_sharedfp", "^sm", /*overwrite=*/0);
    // deal.II initialises PETSc with the command line when it has PETSc
    // (Debian 13's deal.II 9.6), and PETSc then prints on standard output, at
    // the end, that it did not use '--print-parameters' or '--help' (which
    // are this program's, not PETSc's); PETSc's own '-options_left no'
    // turns that report off, a user's own PETSC_OPTIONS is kept.
    setenv("PETSC_OPTIONS", "-options_left no", /*overwrite=*/0);
    Utilities::MPI::MPI_InitFinalize mpi(argc,
                                         argv,
                                         numbers::invalid_unsigned_int);
    const bool root = Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;
    try
      {
        return run_program(argc, argv);
      }
    catch (const InputError &e)
      {
        if (root)
          std::cerr << "hemicontact: input error: " << e.what() << std::endl;
        return 2;
      }
    catch (const SolverFailure &e)
      {
        if (root)
          std::cerr << "hemicontact: solver failure: " << e.what() << std::endl;
        return 3;
      }
    catch (const OutputError &e)
      {
        if (root)
          std::cerr << "hemicontact: I/O error: " << e.what() << std::endl;
        return 6;
      }
    catch (const RunInterrupted &e)
      {
        if (root)
          std::cerr << "hemicontact: interrupted: " << e.what() << std::endl;
        return 5;
      }
    catch (const TargetErrorNotReached &e)
      {
        if (root)
          std::cerr << "hemicontact: target error not reached: " << e.what()
                    << std::endl;
        return 7;
      }
    catch (const dealii::ExceptionBase &e)
      {
        if (root)
          {
            std::cerr << "hemicontact: internal error: ";
            e.print_info(std::cerr);
            std::cerr << std::endl;
          }
        return 4;
      }
    catch (const std::exception &e)
      {
        if (root)
          std::cerr << "hemicontact: error: " << e.what() << std::endl;
        return 4;
      }
  }
} // namespace hemicontact
