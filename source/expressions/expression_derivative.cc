// Symbolic differentiation of Expression trees: each rule builds the
// derivative from copies of the operands, simplifying as it goes (constant
// folding, no zero terms, no factors one), so that the derivatives of a
// manufactured solution stay small trees evaluated in doubles.
#include <hemicontact/expressions/expression.h>

#include <algorithm>
#include <cmath>

namespace hemicontact
{
  namespace
  {
    using Node    = Expression::Node;
    using NodePtr = std::unique_ptr<Node>;

    NodePtr
    constant(const double value)
    {
      auto node   = std::make_unique<Node>();
      node->kind  = Node::constant;
      node->value = value;
      return node;
    }

    bool
    is_constant(const NodePtr &node, const double value)
    {
      return node->kind == Node::constant && node->value == value;
    }

    NodePtr
    clone(const Node &node)
    {
      auto copy   = std::make_unique<Node>();
      copy->kind  = node.kind;
      copy->value = node.value;
      copy->index = node.index;
      copy->op    = node.op;
      copy->fn    = node.fn;
      for (const auto &arg : node.args)
        copy->args.push_back(clone(*arg));
      return copy;
    }

    NodePtr
    binary(const char op, NodePtr a, NodePtr b)
    {
      auto node  = std::make_unique<Node>();
      node->kind = Node::binary;
      node->op   = std::string(1, op);
      node->args.push_back(std::move(a));
      node->args.push_back(std::move(b));
      return node;
    }

    NodePtr
    function(const std::string &name, NodePtr a, NodePtr b = nullptr)
    {
      auto node  = std::make_unique<Node>();
      node->kind = Node::function;
      node->op   = name;
      node->fn   = Expression::function_of(name);
      node->args.push_back(std::move(a));
      if (b)
        node->args.push_back(std::move(b));
      return node;
    }

    NodePtr
    negate(NodePtr a)
    {
      if (a->kind == Node::constant)
        return constant(-a->value);
      if (a->kind == Node::unary)
        return std::move(a->args[0]);
      auto node  = std::make_unique<Node>();
      node->kind = Node::unary;
      node->op   = "-";
      node->args.push_back(std::move(a));
      return node;
    }

    NodePtr
    add(NodePtr a, NodePtr b)
    {
      if (is_constant(a, 0))
        return b;
      if (is_constant(b, 0))
        return a;
      if (a->kind == Node::constant && b->kind == Node::constant)
        return constant(a->value + b->value);
      return binary('+', std::move(a), std::move(b));
    }

    NodePtr
    subtract(NodePtr a, NodePtr b)
    {
      if (is_constant(b, 0))
        return a;
      if (is_constant(a, 0))
        return negate(std::move(b));
      if (a->kind == Node::constant && b->kind == Node::constant)
        return constant(a->value - b->value);
      return binary('-', std::move(a), std::move(b));
    }

    NodePtr
    multiply(NodePtr a, NodePtr b)
    {
      if (is_constant(a, 0) || is_constant(b, 0))
        return constant(0);
      if (is_constant(a, 1))
        return b;
      if (is_constant(b, 1))
        return a;
      if (a->kind == Node::constant && b->kind == Node::constant)
        return constant(a->value * b->value);
      return binary('*', std::move(a), std::move(b));
    }

    NodePtr
    divide(NodePtr a, NodePtr b)
    {
      if (is_constant(a, 0))
        return constant(0);
      if (is_constant(b, 1))
        return a;
      return binary('/', std::move(a), std::move(b));
    }

    /** a^n for a constant n: by multiplication if n is 1..8 (as evaluate()). */
    NodePtr
    power(NodePtr a, const double n)
    {
      if (n == 0)
        return constant(1);
      if (n == 1)
        return a;
      return binary('^', std::move(a), constant(n));
    }

    bool
    is_small_integer(const Node &node)
    {
      return node.kind == Node::constant &&
             node.value == static_cast<int>(node.value) && node.value >= 1 &&
             node.value <= 8;
    }

    NodePtr
    derivative(const Node &node, const unsigned int index);

    /** (a^b)' for the operands of a '^' node or of pow(a, b). */
    NodePtr
    power_derivative(const Node &a, const Node &b, const unsigned int index)
    {
      NodePtr da = derivative(a, index);
      NodePtr db = derivative(b, index);
      if (is_constant(db, 0))
        {
          // b a^(b-1) a'
          if (b.kind != Node::constant)
            return multiply(multiply(clone(b),
                                     function("pow",
                                              clone(a),
                                              subtract(clone(b), constant(1)))),
                            std::move(da));
          const double n     = b.value;
          NodePtr      lower = is_small_integer(b) ?
                                 power(clone(a), n - 1) :
                                 function("pow", clone(a), constant(n - 1));
          return multiply(multiply(constant(n), std::move(lower)),
                          std::move(da));
        }
      // a^b (b' log a + b a'/a)
      return multiply(function("pow", clone(a), clone(b)),
                      add(multiply(std::move(db), function("log", clone(a))),
                          divide(multiply(clone(b), std::move(da)), clone(a))));
    }

    /** d/dx max(a, b) (@p greater) or min(a, b): the branch evaluate() takes.
     */
    NodePtr
    selection_derivative(const Node        &a,
                         const Node        &b,
                         const bool         greater,
                         const unsigned int index)
    {
      NodePtr da = derivative(a, index);
      NodePtr db = derivative(b, index);
      if (is_constant(da, 0) && is_constant(db, 0))
        return constant(0);
      NodePtr a_taken = function("step",
                                 greater ? subtract(clone(a), clone(b)) :
                                           subtract(clone(b), clone(a)));
      NodePtr b_taken = subtract(constant(1), clone(*a_taken));
      return add(multiply(std::move(a_taken), std::move(da)),
                 multiply(std::move(b_taken), std::move(db)));
    }

    NodePtr
    derivative(const Node &node, const unsigned int index)
    {
      switch (node.kind)
        {
          case Node::constant:
            return constant(0);
          case Node::variable:
            return constant(node.index == index ? 1 : 0);
          case Node::unary:
            return negate(derivative(*node.args[0], index));
          case Node::binary:
            {
              const Node &a = *node.args[0];
              const Node &b = *node.args[1];
              switch (node.op[0])
                {
                  case '+':
                    return add(derivative(a, index), derivative(b, index));
                  case '-':
                    return subtract(derivative(a, index), derivative(b, index));
                  case '*':
                    return add(multiply(derivative(a, index), clone(b)),
                               multiply(clone(a), derivative(b, index)));
                  case '/':
                    // a'/b - a b'/b^2
                    return subtract(divide(derivative(a, index), clone(b)),
                                    divide(multiply(clone(a),
                                                    derivative(b, index)),
                                           power(clone(b), 2)));
                  default: // '^'
                    return power_derivative(a, b, index);
                }
            }
          default:
            break;
        }

      using Function   = Expression::Function;
      const Node    &a = *node.args[0];
      const Function f = node.fn;
      if (f == Function::pow)
        return power_derivative(a, *node.args[1], index);
      if (f == Function::max || f == Function::min)
        return selection_derivative(a,
                                    *node.args[1],
                                    f == Function::max,
                                    index);
      if (f == Function::conditional)
        {
          // c ? a' : b' (c is constant between its switches)
          NodePtr da = derivative(*node.args[1], index);
          NodePtr db = derivative(*node.args[2], index);
          if (is_constant(da, 0) && is_constant(db, 0))
            return constant(0);
          NodePtr result  = clone(node);
          result->args[1] = std::move(da);
          result->args[2] = std::move(db);
          return result;
        }
      if (Expression::is_condition(f))
        return constant(0); // piecewise constant: 0 off the switching set
      NodePtr da = derivative(a, index);
      if (is_constant(da, 0) || f == Function::step || f == Function::sign)
        return constant(0);
      NodePtr outer; // f'(a)
      switch (f)
        {
          case Function::sin:
            outer = function("cos", clone(a));
            break;
          case Function::cos:
            outer = negate(function("sin", clone(a)));
            break;
          case Function::tan:
            outer = add(constant(1), power(function("tan", clone(a)), 2));
            break;
          case Function::exp:
            outer = function("exp", clone(a));
            break;
          case Function::log:
            return divide(std::move(da), clone(a));
          case Function::sqrt:
            return divide(std::move(da),
                          multiply(constant(2), function("sqrt", clone(a))));
          case Function::abs:
            outer = function("sign", clone(a));
            break;
          case Function::tanh:
            outer = subtract(constant(1), power(function("tanh", clone(a)), 2));
            break;
          case Function::sinh:
            outer = function("cosh", clone(a));
            break;
          case Function::cosh:
            outer = function("sinh", clone(a));
            break;
          case Function::atan:
            return divide(std::move(da), add(constant(1), power(clone(a), 2)));
          default: // pos
            outer = function("step", clone(a));
        }
      return multiply(std::move(outer), std::move(da));
    }
  } // namespace

  Expression::Function
  Expression::function_of(const std::string &name)
  {
    const auto &names = function_names();
    return static_cast<Function>(std::find(names.begin(), names.end(), name) -
                                 names.begin());
  }

  Expression::Expression(std::unique_ptr<Node> root)
    : root(std::move(root))
  {}

  Expression
  Expression::derivative(const unsigned int index) const
  {
    return Expression(hemicontact::derivative(*root, index));
  }
} // namespace hemicontact
