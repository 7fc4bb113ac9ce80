// A third coupled field costs one entry (doc/extending.md, "A coupled
// field"): a skeleton field phi written in this file alone, with no branch
// for it in problem/, output/, simulation/ or the energy balance, added by
// add_field(). Its step, ordered before the mechanical step, is phi_n =
// phi_{n-1} + k (so phi = t_n at every node, which every transfer keeps
// exactly); its load on the mechanical step is zero, so the mechanical
// answer is bitwise that of the run without it. It gives a contact CSV
// column and a number of the progress lines. The test checks that it is
// stepped, moved by the adaptations, written, saved and resumed bitwise,
// and that steps.csv and the checkpoint's energy terms are those of the run
// without it (no format change).
#include <deal.II/fe/fe_q.h>

#include <hemicontact/base/exceptions.h>
#include <hemicontact/coupling/coupled_field.h>
#include <hemicontact/input/parameters.h>
#include <hemicontact/problem/contact_problem.h>
#include <hemicontact/simulation/simulation.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "tests.h"

using namespace hemicontact;

namespace
{
  /** The skeleton: phi_n = phi_{n-1} + k, no load, no energy terms. */
  class Skeleton : public CoupledField<2>
  {
  public:
    FieldDefinition<2>
    definition(const bool) const override
    {
      return {"phi", std::make_shared<FE_Q<2>>(1), nullptr};
    }
    std::string
    subsection() const override
    {
      return "skeleton";
    }
    std::string
    symbol() const override
    {
      return "phi_n";
    }
    Order
    order() const override
    {
      return Order::before_mechanical_step;
    }
    std::string
    step_name() const override
    {
      return "skeleton step";
    }
    void
    reinit(const FieldSpace<2> &, const MechanicalView<2> &) override
    {
      ++meshes;
    }
    void
    add_mechanical_load(const double,
                        const MechanicalView<2> &,
                        TrilinosWrappers::MPI::Vector &,
                        TrilinosWrappers::MPI::Vector &) override
    {
      ++loads;
    }
    FieldStepEnergy
    step(const double,
         const double k,
         const MechanicalView<2> &,
         LinearSolver &,
         TrilinosWrappers::MPI::Vector &value) override
    {
      value.add(k);
      ++steps;
      return {};
    }
    const std::vector<EnergyTermSpec> &
    energy_terms() const override
    {
      static const std::vector<EnergyTermSpec> none;
      return none;
    }
    std::vector<std::string>
    contact_columns() const override
    {
      return {"phi"};
    }
    std::vector<std::vector<double>>
    contact_values(const MechanicalView<2> &view,
                   const TrilinosWrappers::MPI::Vector &) const override
    {
      return std::vector<std::vector<double>>(view.contact_nodes.size(),
                                              {view.time});
    }
    std::vector<SummaryValue>
    summary() const override
    {
      return {{"skeleton steps", "skeleton", double(steps)}};
    }

    unsigned int meshes = 0, loads = 0, steps = 0;
  };

  const std::string text = R"(
set dimension = 2
subsection geometry
  set upper right corner = 4, 1
  set subdivisions       = 4, 1
  set global refinements = 2
end
subsection boundary
  set clamped boundary ids  = 0
  set traction boundary ids = 3
  set contact boundary ids  = 2
end
subsection time
  set end time  = 0.4
  set time step = 0.1
end
subsection data
  set surface traction = 0; -1
end
subsection adaptivity
  set strategy         = fixed number
  set refine fraction  = 0.3
  set coarsen fraction = 0.1
end
subsection output
  set terminal        = quiet
  set output interval = 1
end
)";

  /** The problem writing to @p directory, with the skeleton if @p with. */
  std::unique_ptr<ContactProblem<2>>
  problem(const std::string &directory,
          const bool         with,
          const bool         adapt,
          const bool         resume,
          const unsigned int stop_after,
          Skeleton         **skeleton = nullptr)
  {
    ParameterHandler prm;
    Parameters       parameters      = read_parameters_from_string(prm, text);
    parameters.adaptivity.interval   = adapt ? 1 : 0;
    parameters.output.directory      = directory;
    parameters.checkpoint.interval   = 1;
    parameters.checkpoint.resume     = resume;
    parameters.checkpoint.stop_after = stop_after;
    auto p = std::make_unique<ContactProblem<2>>(parameters,
                                                 create_contact_laws(prm),
                                                 MPI_COMM_WORLD);
    if (with)
      {
        auto field = std::make_unique<Skeleton>();
        if (skeleton != nullptr)
          *skeleton = field.get();
        // the one entry
        p->add_field(std::move(field));
      }
    return p;
  }

  /** max |v - w| (0 exactly: bitwise equal). */
  double
  difference(const TrilinosWrappers::MPI::Vector &v,
             const TrilinosWrappers::MPI::Vector &w)
  {
    TrilinosWrappers::MPI::Vector d(v);
    d -= w;
    return d.linfty_norm();
  }

  /** The first line of @p file. */
  std::string
  first_line(const std::filesystem::path &file)
  {
    std::ifstream in(file);
    std::string   line;
    std::getline(in, line);
    return line;
  }

  /** Whether a VTU file of step 2 in @p directory names @p field. */
  bool
  written(const std::string &directory, const std::string &field)
  {
    bool found = false;
    for (const auto &entry : std::filesystem::directory_iterator(directory))
      if (entry.path().filename().string().rfind("solution_00002", 0) == 0 &&
          entry.path().extension() == ".vtu")
        {
          std::ifstream      in(entry.path());
          std::ostringstream content;
          content << in.rdbuf();
          found = found || content.str().find("Name=\"" + field + "\"") !=
                             std::string::npos;
        }
    return found;
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const bool root = Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;

  // stepped before each mechanical step, loaded into each, with no effect
  // on the mechanical answer
  Skeleton *skeleton = nullptr;
  auto      with     = problem("with", true, false, false, 0, &skeleton);
  Simulation<2>(*with).run();
  auto without = problem("without", false, false, false, 0);
  Simulation<2>(*without).run();
  const TrilinosWrappers::MPI::Vector &phi =
    with->get_added_fields().vector("phi");
  out() << "steps " << skeleton->steps << ", loads " << skeleton->loads
        << ", meshes " << skeleton->meshes << "; phi = t_end at every node: "
        << (std::abs(phi.linfty_norm() - 0.4) < 1e-14 &&
                std::abs(phi.mean_value() - 0.4) < 1e-14 ?
              "yes" :
              "no")
        << "; u as without it: "
        << (difference(with->state().displacement,
                       without->state().displacement) == 0 ?
              "bitwise" :
              "differs")
        << "\n";
  MPI_Barrier(MPI_COMM_WORLD);
  if (root)
    out() << "steps.csv header as without it: "
          << (first_line("with/steps.csv") == first_line("without/steps.csv") ?
                "yes" :
                "no")
          << "; contact CSV's last column: "
          << first_line("with/contact_00004.csv")
               .substr(first_line("with/contact_00004.csv").rfind(',') + 1)
          << "; phi written: " << (written("with", "phi") ? "yes" : "no")
          << "\n";

  // moved by the adaptations exactly
  auto adapted = problem("adapted", true, true, false, 0);
  Simulation<2>(*adapted).run();
  const TrilinosWrappers::MPI::Vector &moved =
    adapted->get_added_fields().vector("phi");
  out() << "mesh adapted: "
        << (adapted->state()
                  .dof_handler.get_triangulation()
                  .n_global_active_cells() != 4 * 16 ?
              "yes" :
              "no")
        << "; phi = t_end after the adaptations: "
        << (std::abs(moved.linfty_norm() - 0.4) < 1e-14 &&
                std::abs(moved.mean_value() - 0.4) < 1e-14 ?
              "yes" :
              "no")
        << "\n";

  // interrupted after step 2 and resumed: bitwise the uninterrupted run
  try
    {
      Simulation<2>(*problem("parts", true, false, false, 2)).run();
    }
  catch (const RunInterrupted &)
    {
      out() << "interrupted after step 2\n";
    }
  auto second = problem("parts", true, false, true, 0);
  Simulation<2>(*second).run();
  out() << "resumed run ends as the uninterrupted one: phi "
        << (difference(second->get_added_fields().vector("phi"), phi) == 0 ?
              "bitwise" :
              "differs")
        << ", u "
        << (difference(second->state().displacement,
                       with->state().displacement) == 0 ?
              "bitwise" :
              "differs")
        << "\n";
}
