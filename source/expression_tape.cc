#include <hemicontact/expression_tape.h>

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
    const std::vector<const Expression *> &expressions)
  {
    for (const Expression *e : expressions)
      outputs.push_back(compile(e->tree()));
    known.clear();
  }

  unsigned int
  ExpressionTape::append(const Instruction &instruction)
  {
    // the same operation on the same operands is the same subexpression
    const Key key{static_cast<int>(instruction.op), instruction.function_id,
                  instruction.a, instruction.b, instruction.n,
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
          instruction.op = Op::negate;
          instruction.a  = compile(*node.args[0]);
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
                instruction.op = Op::integer_power;
                instruction.a  = compile(*node.args[0]);
                instruction.n  = static_cast<unsigned int>(exponent.value);
                return append(instruction);
              }
            instruction.a = compile(*node.args[0]);
            instruction.b = compile(*node.args[1]);
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
                  instruction.op          = Op::function;
                  instruction.function_id = Expression::function_id("pow");
              }
            return append(instruction);
          }
        default:
          instruction.op          = Op::function;
          instruction.function_id = node.function_id;
          instruction.a           = compile(*node.args[0]);
          if (node.args.size() > 1)
            instruction.b = compile(*node.args[1]);
          return append(instruction);
      }
  }

  void
  ExpressionTape::evaluate(const std::vector<double> &variables,
                           std::vector<double> &      results) const
  {
    std::vector<double> r(code.size());
    for (unsigned int i = 0; i < code.size(); ++i)
      {
        const Instruction &c = code[i];
        const double       a = r[c.a], b = r[c.b];
        switch (c.op)
          {
            case Op::constant:
              r[i] = c.value;
              break;
            case Op::variable:
              r[i] = variables[c.n];
              break;
            case Op::negate:
              r[i] = -a;
              break;
            case Op::add:
              r[i] = a + b;
              break;
            case Op::subtract:
              r[i] = a - b;
              break;
            case Op::multiply:
              r[i] = a * b;
              break;
            case Op::divide:
              r[i] = a / b;
              break;
            case Op::integer_power:
              {
                double p = a;
                for (unsigned int k = 1; k < c.n; ++k)
                  p = p * a;
                r[i] = p;
                break;
              }
            default:
              r[i] = Expression::apply_function(c.function_id, a, b);
          }
      }
    results.resize(outputs.size());
    for (unsigned int k = 0; k < outputs.size(); ++k)
      results[k] = r[outputs[k]];
  }
} // namespace hemicontact
