#include <hemicontact/expressions/expression_tape.h>

#include <algorithm>
#include <cmath>
#include <cstring>

namespace hemicontact
{
  namespace
  {
    std::uint64_t
    bits(const double x)
    {
      std::uint64_t b;
      std::memcpy(&b, &x, sizeof b);
      return b;
    }
  } // namespace

  ExpressionTape::ExpressionTape(
    const std::vector<const Expression *> &expressions,
    const std::vector<unsigned int>       &uniform_variables)
    : uniform_variables(uniform_variables)
  {
    for (const Expression *e : expressions)
      outputs.push_back(compile(e->tree()));
    known.clear();

    // evaluate_cached() needs the spatial values that an instruction
    // depending on the uniform variables reads, and the spatial results
    const auto keep = [this](const unsigned int i) {
      if (code[i].spatial && code[i].cached < 0)
        code[i].cached = n_cached_values++;
    };
    for (const Instruction &c : code)
      if (!c.spatial && !c.uniform)
        {
          keep(c.a);
          if (c.n_operands > 1)
            keep(c.b);
          if (c.n_operands > 2)
            keep(c.c);
        }
    for (const unsigned int o : outputs)
      keep(o);
    for (unsigned int i = 0; i < code.size(); ++i)
      {
        all_instructions.push_back(i);
        if (!code[i].timed)
          time_free_instructions.push_back(i);
        if (!code[i].spatial || code[i].cached >= 0)
          given_spatial_instructions.push_back(i);
      }
  }

  bool
  ExpressionTape::is_uniform_variable(const unsigned int v) const
  {
    return std::find(uniform_variables.begin(), uniform_variables.end(), v) !=
           uniform_variables.end();
  }

  unsigned int
  ExpressionTape::append(Instruction instruction)
  {
    switch (instruction.op)
      {
        case Op::constant:
          instruction.uniform = true;
          break;
        case Op::variable:
          instruction.uniform = is_uniform_variable(instruction.n);
          instruction.timed   = instruction.uniform;
          break;
        default:
          {
            const bool         binary = instruction.n_operands > 1;
            const Instruction &a      = code[instruction.a];
            const Instruction &b = code[binary ? instruction.b : instruction.a];
            const Instruction &c =
              code[instruction.n_operands > 2 ? instruction.c : instruction.a];
            instruction.uniform = a.uniform && b.uniform && c.uniform;
            instruction.timed   = a.timed || b.timed || c.timed;
          }
      }
    instruction.spatial = !instruction.uniform && !instruction.timed;
    // the same operation on the same operands is the same subexpression
    const Key  key{static_cast<int>(instruction.op),
                  static_cast<int>(instruction.function),
                  instruction.a,
                  instruction.b,
                  instruction.c,
                  instruction.n,
                  bits(instruction.value)};
    const auto found = known.find(key);
    if (found != known.end())
      return found->second;
    code.push_back(instruction);
    known.emplace(key, code.size() - 1);
    return code.size() - 1;
  }

  unsigned int
  ExpressionTape::compile(const Expression::Node &node)
  {
    Instruction instruction;
    switch (node.kind)
      {
        case Expression::Node::constant:
          instruction.op    = Op::constant;
          instruction.value = node.value;
          return append(instruction);
        case Expression::Node::variable:
          instruction.op = Op::variable;
          instruction.n  = node.index;
          return append(instruction);
        case Expression::Node::unary:
          instruction.op         = Op::negate;
          instruction.a          = compile(*node.args[0]);
          instruction.n_operands = 1;
          return append(instruction);
        case Expression::Node::binary:
          {
            const Expression::Node &exponent = *node.args[1];
            if (node.op[0] == '^' &&
                exponent.kind == Expression::Node::constant &&
                exponent.value == static_cast<int>(exponent.value) &&
                exponent.value >= 1 && exponent.value <= 8)
              {
                if (exponent.value == 1)
                  return compile(*node.args[0]);
                instruction.op         = Op::integer_power;
                instruction.a          = compile(*node.args[0]);
                instruction.n_operands = 1;
                instruction.n = static_cast<unsigned int>(exponent.value);
                return append(instruction);
              }
            instruction.a          = compile(*node.args[0]);
            instruction.b          = compile(*node.args[1]);
            instruction.n_operands = 2;
            switch (node.op[0])
              {
                case '+':
                  instruction.op = Op::add;
                  break;
                case '-':
                  instruction.op = Op::subtract;
                  break;
                case '*':
                  instruction.op = Op::multiply;
                  break;
                case '/':
                  instruction.op = Op::divide;
                  break;
                default: // '^' with a general exponent
                  instruction.op       = Op::function;
                  instruction.function = Expression::Function::pow;
              }
            return append(instruction);
          }
        default:
          instruction.op         = Op::function;
          instruction.function   = node.fn;
          instruction.a          = compile(*node.args[0]);
          instruction.n_operands = node.args.size();
          if (node.args.size() > 1)
            instruction.b = compile(*node.args[1]);
          if (node.args.size() > 2)
            instruction.c = compile(*node.args[2]);
          return append(instruction);
      }
  }

  void
  ExpressionTape::evaluate(const std::vector<double> &variables,
                           std::vector<double>       &results) const
  {
    results.resize(outputs.size());
    evaluate(variables.data(), variables.size(), 1, results.data());
  }

  void
  ExpressionTape::evaluate(const double      *variables,
                           const unsigned int n_variables,
                           const unsigned int n_points,
                           double            *results) const
  {
    gather(execute(variables, n_variables, n_points, Pass::all, nullptr),
           n_points,
           results);
  }

  void
  ExpressionTape::evaluate_spatial(const double      *variables,
                                   const unsigned int n_variables,
                                   const unsigned int n_points,
                                   double            *spatial) const
  {
    const double *const r =
      execute(variables, n_variables, n_points, Pass::time_free, nullptr);
    for (unsigned int i = 0; i < code.size(); ++i)
      if (code[i].cached >= 0)
        std::copy_n(r + std::size_t(i) * n_points,
                    n_points,
                    spatial + std::size_t(code[i].cached) * n_points);
  }

  void
  ExpressionTape::evaluate_cached(const double      *variables,
                                  const unsigned int n_variables,
                                  const unsigned int n_points,
                                  const double      *spatial,
                                  double            *results) const
  {
    gather(
      execute(variables, n_variables, n_points, Pass::given_spatial, spatial),
      n_points,
      results);
  }

  void
  ExpressionTape::gather(const double      *r,
                         const unsigned int n_points,
                         double            *results) const
  {
    const unsigned int n_results = outputs.size();
    for (unsigned int p = 0; p < n_points; ++p)
      for (unsigned int k = 0; k < n_results; ++k)
        results[std::size_t(p) * n_results + k] =
          r[std::size_t(outputs[k]) * n_points + p];
  }

  double *
  ExpressionTape::execute(const double      *variables,
                          const unsigned int n_variables,
                          const unsigned int n_points,
                          const Pass         pass,
                          const double      *spatial) const
  {
    // one register per instruction and point; per thread, as deal.II may
    // evaluate functions from several threads
    thread_local std::vector<double> registers;
    registers.resize(code.size() * std::size_t(n_points));
    double *const                    r = registers.data();
    const std::vector<unsigned int> &instructions =
      pass == Pass::all       ? all_instructions :
      pass == Pass::time_free ? time_free_instructions :
                                given_spatial_instructions;
    for (const unsigned int i : instructions)
      {
        const Instruction &c   = code[i];
        double *const      out = r + std::size_t(i) * n_points;
        if (pass == Pass::given_spatial && c.spatial)
          {
            std::copy_n(spatial + std::size_t(c.cached) * n_points,
                        n_points,
                        out);
            continue;
          }
        const double *const a = r + std::size_t(c.a) * n_points;
        const double *const b = r + std::size_t(c.b) * n_points;
        const double *const d = r + std::size_t(c.c) * n_points;
        const unsigned int  n = c.uniform ? 1 : n_points;
        switch (c.op)
          {
            case Op::constant:
              out[0] = c.value;
              break;
            case Op::variable:
              for (unsigned int p = 0; p < n; ++p)
                out[p] = variables[std::size_t(p) * n_variables + c.n];
              break;
            case Op::negate:
              for (unsigned int p = 0; p < n; ++p)
                out[p] = -a[p];
              break;
            case Op::add:
              for (unsigned int p = 0; p < n; ++p)
                out[p] = a[p] + b[p];
              break;
            case Op::subtract:
              for (unsigned int p = 0; p < n; ++p)
                out[p] = a[p] - b[p];
              break;
            case Op::multiply:
              for (unsigned int p = 0; p < n; ++p)
                out[p] = a[p] * b[p];
              break;
            case Op::divide:
              for (unsigned int p = 0; p < n; ++p)
                out[p] = a[p] / b[p];
              break;
            case Op::integer_power:
              for (unsigned int p = 0; p < n; ++p)
                {
                  double power = a[p];
                  for (unsigned int k = 1; k < c.n; ++k)
                    power = power * a[p];
                  out[p] = power;
                }
              break;
            default:
              if (c.function == Expression::Function::conditional)
                for (unsigned int p = 0; p < n; ++p)
                  out[p] = a[p] != 0 ? b[p] : d[p];
              else
                for (unsigned int p = 0; p < n; ++p)
                  out[p] = Expression::apply_function(c.function, a[p], b[p]);
          }
        if (c.uniform)
          std::fill(out + 1, out + n_points, out[0]);
      }
    return r;
  }
} // namespace hemicontact
