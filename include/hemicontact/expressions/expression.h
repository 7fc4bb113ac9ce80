#pragma once

#include <cmath>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace hemicontact
{
  /**
   * A scalar expression in named variables, parsed once and evaluated with
   * any number type -- double, or forward-AD numbers (Sacado) for exact
   * derivatives. The grammar of every expression entry (doc/parameters.md,
   * Expressions): numbers, variables, constants, + - * / ^ (right-assoc.),
   * unary minus (-x^2 is -(x^2)), parentheses, the functions sin cos tan exp
   * log sqrt abs tanh sinh cosh atan, pos(a) = max(a, 0), step(a) (1 if
   * a > 0, else 0), sign(a) (-1 if a < 0, else 1), pow max min (a, b), and,
   * as in muparser, the comparisons < > <= >= == != and the logical && ||
   * (1 if true, else 0; looser than + and -, then ||), and c ? a : b or
   * if(c, a, b) (a if c is not 0, else b; loosest of all).
   *
   * derivative() differentiates symbolically: the derivatives of a
   * manufactured solution are plain expressions evaluated in doubles.
   */
  class Expression
  {
  public:
    /**
     * Parse @p text; @p variables are the names bound at evaluation (in
     * this order), @p constants are fixed values. Throws InputError with
     * @p parameter_name on a syntax error or an unknown name.
     */
    Expression(const std::string                   &text,
               const std::vector<std::string>      &variables,
               const std::map<std::string, double> &constants,
               const std::string                   &parameter_name);

    /**
     * The partial derivative by the variable number @p index, as an
     * expression of its own (simplified: no zero terms, no factors one).
     * At the kinks of abs, pos, max and min it takes the one-sided
     * derivative that evaluate() with forward AD gives.
     */
    Expression
    derivative(const unsigned int index) const;

    /** Evaluate with @p values of the variables. */
    template <typename Number>
    Number
    evaluate(const std::vector<Number> &values) const;

    /**
     * The functions and the comparison, logical and conditional operators
     * of the grammar, in the order of function_names(). From pow on they
     * take two arguments; from less on they are written between their
     * operands; conditional (c ? a : b) takes three.
     */
    enum class Function
    {
      sin,
      cos,
      tan,
      exp,
      log,
      sqrt,
      abs,
      tanh,
      sinh,
      cosh,
      atan,
      pos,  ///< max(a, 0)
      step, ///< 1 if a > 0, else 0
      sign, ///< -1 if a < 0, else 1
      pow,  ///< the first function of two arguments
      max,
      min,
      less, ///< the first comparison or logical operator
      greater,
      less_equal,
      greater_equal,
      equal,
      not_equal,
      logical_and,
      logical_or,
      conditional ///< c ? a : b
    };

    struct Node
    {
      enum Kind
      {
        constant,
        variable,
        unary,
        binary,
        function
      } kind;
      double       value = 0;
      unsigned int index = 0;          ///< variable index
      std::string  op;                 ///< operator/function
      Function     fn = Function::sin; ///< of a function node
      std::vector<std::unique_ptr<Node>> args;
    };

    /** The expression tree (e.g. for ExpressionTape). */
    const Node &
    tree() const
    {
      return *root;
    }

    /** Whether the expression refers to the variable number @p index. */
    bool
    uses_variable(const unsigned int index) const;

    /** The spellings of the functions and operators, in the order of
     *  Function. */
    static const std::vector<std::string> &
    function_names();

    /** Whether @p f takes two arguments (pow, max, min and the comparison
     *  and logical operators). */
    static bool
    is_binary(const Function f);

    /** Whether @p f is a comparison or a logical operator (a value 1 or 0,
     *  piecewise constant). */
    static bool
    is_condition(const Function f);

    /** f(a) (or f(a, b)) for the function or operator @p f (not the
     *  conditional). */
    template <typename Number>
    static Number
    apply_function(const Function f, const Number &a, const Number &b);

    /** The function or operator spelt @p name (one of function_names()). */
    static Function
    function_of(const std::string &name);

  private:
    explicit Expression(std::unique_ptr<Node> root);

    template <typename Number>
    static Number
    eval(const Node &node, const std::vector<Number> &values);

    std::unique_ptr<Node> root;
  };

  /**
   * @p text in quotes for a message: at most its first 200 characters,
   * followed by "..." and its length if it is longer.
   */
  std::string
  quoted_expression(const std::string &text);

  // ---------------------------------------------------------------------
  template <typename Number>
  Number
  Expression::evaluate(const std::vector<Number> &values) const
  {
    return eval(*root, values);
  }

  template <typename Number>
  Number
  Expression::eval(const Node &node, const std::vector<Number> &values)
  {
    using std::pow;
    switch (node.kind)
      {
        case Node::constant:
          return Number(node.value);
        case Node::variable:
          return values[node.index];
        case Node::unary:
          return -eval(*node.args[0], values);
        case Node::binary:
          {
            const Number a = eval(*node.args[0], values);
            const Number b = eval(*node.args[1], values);
            switch (node.op[0])
              {
                case '+':
                  return a + b;
                case '-':
                  return a - b;
                case '*':
                  return a * b;
                case '/':
                  return a / b;
                default: // '^'
                  if (node.args[1]->kind == Node::constant &&
                      node.args[1]->value ==
                        static_cast<int>(node.args[1]->value) &&
                      node.args[1]->value >= 1 && node.args[1]->value <= 8)
                    {
                      // integer powers by multiplication: exact derivatives
                      // also at a = 0 (pos(x)^3)
                      Number r = a;
                      for (int i = 1; i < static_cast<int>(node.args[1]->value);
                           ++i)
                        r = r * a;
                      return r;
                    }
                  return pow(a, b);
              }
          }
        default:
          {
            if (node.fn == Function::conditional)
              return eval(*node.args[0], values) != Number(0.) ?
                       eval(*node.args[1], values) :
                       eval(*node.args[2], values);
            const Number a = eval(*node.args[0], values);
            const Number b =
              node.args.size() > 1 ? eval(*node.args[1], values) : Number(0.);
            return apply_function(node.fn, a, b);
          }
      }
  }

  template <typename Number>
  Number
  Expression::apply_function(const Function f, const Number &a, const Number &b)
  {
    using std::atan;
    using std::cos;
    using std::cosh;
    using std::exp;
    using std::log;
    using std::pow;
    using std::sin;
    using std::sinh;
    using std::sqrt;
    using std::tan;
    using std::tanh;
    switch (f)
      {
        case Function::sin:
          return sin(a);
        case Function::cos:
          return cos(a);
        case Function::tan:
          return tan(a);
        case Function::exp:
          return exp(a);
        case Function::log:
          return log(a);
        case Function::sqrt:
          return sqrt(a);
        case Function::abs:
          return a < 0 ? Number(-a) : a;
        case Function::tanh:
          return tanh(a);
        case Function::sinh:
          return sinh(a);
        case Function::cosh:
          return cosh(a);
        case Function::atan:
          return atan(a);
        case Function::pos:
          return a > 0 ? a : Number(0.);
        case Function::step:
          return Number(a > 0 ? 1. : 0.);
        case Function::sign:
          return Number(a < 0 ? -1. : 1.);
        case Function::pow:
          return pow(a, b);
        case Function::max:
          return a > b ? a : b;
        case Function::min:
          return a < b ? a : b;
        case Function::less:
          return Number(a < b ? 1. : 0.);
        case Function::greater:
          return Number(a > b ? 1. : 0.);
        case Function::less_equal:
          return Number(a <= b ? 1. : 0.);
        case Function::greater_equal:
          return Number(a >= b ? 1. : 0.);
        case Function::equal:
          return Number(a == b ? 1. : 0.);
        case Function::not_equal:
          return Number(a != b ? 1. : 0.);
        case Function::logical_and:
          return Number(a != Number(0.) && b != Number(0.) ? 1. : 0.);
        case Function::logical_or:
          return Number(a != Number(0.) || b != Number(0.) ? 1. : 0.);
        case Function::conditional: // three arguments: see eval()
          break;
      }
    return Number(0.);
  }
} // namespace hemicontact
