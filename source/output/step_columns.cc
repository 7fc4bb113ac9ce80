#include <hemicontact/output/step_columns.h>

#include <iomanip>
#include <sstream>

namespace hemicontact
{
  namespace
  {
    using S = StepStatistics;
    using E = EnergyBalance;
  } // namespace

  const std::vector<StepColumn> &
  step_columns()
  {
    // a column per line: name, then what it writes
#define HC_COLUMN(name, expression)                       \
  StepColumn                                              \
  {                                                       \
    name, [](std::ostream &out, const S &s, const E &e) { \
      (void)s;                                            \
      (void)e;                                            \
      out << expression;                                  \
    }                                                     \
  }
    // the estimate's columns are empty where none was evaluated, the time
    // indicator's also in the static class
#define HC_ESTIMATE(name, member)                        \
  StepColumn                                             \
  {                                                      \
    name, [](std::ostream &out, const S &s, const E &) { \
      if (s.estimated)                                   \
        out << s.member;                                 \
    }                                                    \
  }
    static const std::vector<StepColumn> columns = []() {
      std::vector<StepColumn> list{
        HC_COLUMN("step", s.step),
        HC_COLUMN("time", s.time),
        HC_COLUMN("n_cells", s.n_cells),
        HC_COLUMN("n_dofs", s.n_dofs),
        HC_COLUMN("newton_iterations", s.newton_iterations),
        HC_COLUMN("linear_iterations", s.linear_iterations),
        HC_COLUMN("n_separating", s.n_separating),
        HC_COLUMN("n_normal_stick", s.n_normal_stick),
        HC_COLUMN("n_damped", s.n_damped),
        HC_COLUMN("n_stick", s.n_stick),
        HC_COLUMN("n_slip", s.n_slip),
        HC_COLUMN("residual", s.residual),
        HC_COLUMN("kinetic_energy", e.kinetic),
        HC_COLUMN("elastic_energy", e.elastic),
        HC_COLUMN("viscous_dissipation", e.viscous_dissipation),
        HC_COLUMN("friction_dissipation", e.friction_dissipation),
        HC_COLUMN("normal_damping_dissipation", e.damping_dissipation),
        HC_COLUMN("external_work", e.external_work),
        HC_COLUMN("numerical_dissipation", e.numerical_dissipation),
        HC_COLUMN("energy_defect", e.defect()),
        HC_COLUMN("relative_energy_defect", e.relative_defect()),
        HC_COLUMN("line_search_reductions", s.line_search_reductions),
        HC_COLUMN("wall_seconds", s.wall_seconds),
        HC_COLUMN("adapted", (s.adapted ? 1 : 0)),
        HC_COLUMN("kinetic_before_adaptation", s.kinetic_before_adaptation),
        HC_COLUMN("elastic_before_adaptation", s.elastic_before_adaptation),
        HC_COLUMN("kinetic_after_adaptation", s.kinetic_after_adaptation),
        HC_COLUMN("elastic_after_adaptation", s.elastic_after_adaptation),
        HC_COLUMN("energy_transfer_change", e.transfer_change),
        HC_COLUMN("time_step_halvings", s.time_step_halvings),
        HC_COLUMN("minimised_energy", e.minimised_energy),
        HC_COLUMN("bound_iterations", s.bound_iterations),
        HC_COLUMN("n_at_breakpoint", s.n_at_breakpoint),
        HC_COLUMN("n_at_wall", s.n_at_wall),
        HC_COLUMN("memory_work", e.memory_work),
        HC_ESTIMATE("error_estimate", estimate),
        HC_ESTIMATE("estimate_interior", estimate_interior),
        HC_ESTIMATE("estimate_jumps", estimate_jumps),
        HC_ESTIMATE("estimate_neumann", estimate_neumann),
        HC_ESTIMATE("estimate_contact", estimate_contact),
        StepColumn{"estimate_time",
                   [](std::ostream &out, const S &s, const E &) {
                     if (s.time_estimated)
                       out << s.estimate_time;
                   }}};
      // the coupled fields' terms that have a column (doc/outputs.md)
      const std::vector<EnergyTermSpec> &terms = coupled_energy_terms();
      for (std::size_t i = 0; i < terms.size(); ++i)
        if (!terms[i].column.empty())
          list.push_back(
            {terms[i].column, [i](std::ostream &out, const S &, const E &e) {
               out << e.coupled[i];
             }});
      list.push_back(HC_COLUMN("coupling_passes", s.coupling_passes));
      return list;
    }();
#undef HC_COLUMN
#undef HC_ESTIMATE
    return columns;
  }

  std::string
  step_columns_header()
  {
    std::string header;
    for (const StepColumn &column : step_columns())
      header += (header.empty() ? "" : ",") + column.name;
    return header + "\n";
  }

  std::string
  step_columns_row(const StepStatistics &stats, const EnergyBalance &energy)
  {
    std::ostringstream row;
    row << std::setprecision(12);
    bool first = true;
    for (const StepColumn &column : step_columns())
      {
        if (!first)
          row << ",";
        first = false;
        column.write(row, stats, energy);
      }
    row << "\n";
    return row.str();
  }
} // namespace hemicontact
