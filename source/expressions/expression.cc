#include <deal.II/base/utilities.h>

#include <hemicontact/base/exceptions.h>
#include <hemicontact/expressions/expression.h>

#include <algorithm>
#include <cctype>

namespace hemicontact
{
  namespace
  {
    /** Recursive-descent parser, loosest first: expr = disjunction [?
     *  expr : expr], disjunction = conjunction {|| conjunction}, conjunction =
     * comparison {&& comparison}, comparison = sum [(<|>|<=|>=|==|!=) sum], sum
     * = term {(+|-) term}, term = unary
     *  {(*|/) unary}, unary = (-|+) unary | power, power = primary [^
     *  unary]: as in muparser, -x^2 is -(x^2) and 2^3^2 is 2^9. */
    class Parser
    {
    public:
      Parser(const std::string                   &text,
             const std::vector<std::string>      &variables,
             const std::map<std::string, double> &constants,
             const std::string                   &parameter_name)
        : text(text)
        , variables(variables)
        , constants(constants)
        , parameter_name(parameter_name)
      {}

      std::unique_ptr<Expression::Node>
      parse()
      {
        if (text.size() > max_length)
          throw InputError("cannot parse '" + parameter_name +
                           "' = " + quoted_expression(text) +
                           ": it is longer than " + std::to_string(max_length) +
                           " characters, the most an expression may have.");
        auto node = expression();
        skip_space();
        if (position != text.size())
          fail("unexpected '" + text.substr(position, 1) + "'");
        return node;
      }

    private:
      using NodePtr = std::unique_ptr<Expression::Node>;

      /** Throw the InputError for @p what at the current position, with
       *  the sentence @p hint after it. */
      [[noreturn]] void
      fail(const std::string &what, const std::string &hint = "") const
      {
        throw InputError("cannot parse '" + parameter_name +
                         "' = " + quoted_expression(text) + ": " + what +
                         " at position " + std::to_string(position + 1) + "." +
                         (hint.empty() ? "" : " " + hint));
      }

      void
      skip_space()
      {
        while (position < text.size() && std::isspace(text[position]))
          ++position;
      }

      bool
      accept(const char c)
      {
        skip_space();
        if (position < text.size() && text[position] == c)
          {
            ++position;
            return true;
          }
        return false;
      }

      static NodePtr
      make(Expression::Node::Kind kind,
           const std::string     &op,
           std::vector<NodePtr>   args)
      {
        auto node  = std::make_unique<Expression::Node>();
        node->kind = kind;
        node->op   = op;
        node->args = std::move(args);
        return node;
      }

      /** Whether the text at the position starts with @p op (consumed). */
      bool
      accept(const std::string &op)
      {
        skip_space();
        if (text.compare(position, op.size(), op) != 0)
          return false;
        position += op.size();
        return true;
      }

      /** a op b for a comparison or logical operator: a function node. */
      NodePtr
      operation(const std::string &op, NodePtr a, NodePtr b)
      {
        NodePtr node = binary(op, std::move(a), std::move(b));
        node->kind   = Expression::Node::function;
        node->fn     = Expression::function_of(op);
        return node;
      }

      NodePtr
      expression()
      {
        NodePtr condition = disjunction();
        if (!accept('?'))
          return condition;
        const Nested nested(*this);
        NodePtr      if_true = expression();
        if (!accept(':'))
          fail("missing ':' of 'c ? a : b'");
        NodePtr node =
          operation("?:", std::move(condition), std::move(if_true));
        node->args.push_back(expression());
        return node;
      }

      NodePtr
      disjunction()
      {
        NodePtr left = conjunction();
        while (accept("||"))
          left = operation("||", std::move(left), conjunction());
        return left;
      }

      NodePtr
      conjunction()
      {
        NodePtr left = comparison();
        while (accept("&&"))
          left = operation("&&", std::move(left), comparison());
        return left;
      }

      NodePtr
      comparison()
      {
        NodePtr left = sum();
        for (;;)
          {
            // the two-character operators first
            const std::string *op = nullptr;
            for (const std::string &candidate : comparison_operators)
              if (accept(candidate))
                {
                  op = &candidate;
                  break;
                }
            if (op == nullptr)
              return left;
            left = operation(*op, std::move(left), sum());
          }
      }

      NodePtr
      sum()
      {
        NodePtr left = term();
        for (;;)
          {
            if (accept('+'))
              left = binary("+", std::move(left), term());
            else if (accept('-'))
              left = binary("-", std::move(left), term());
            else
              return left;
          }
      }

      NodePtr
      term()
      {
        NodePtr left = unary();
        for (;;)
          {
            if (accept('*'))
              left = binary("*", std::move(left), unary());
            else if (accept('/'))
              left = binary("/", std::move(left), unary());
            else
              return left;
          }
      }

      NodePtr
      unary()
      {
        if (accept('-'))
          {
            const Nested         nested(*this);
            std::vector<NodePtr> args;
            args.push_back(unary());
            return make(Expression::Node::unary, "-", std::move(args));
          }
        if (accept('+'))
          {
            const Nested nested(*this);
            return unary();
          }
        return power();
      }

      NodePtr
      power()
      {
        NodePtr base = primary();
        if (!accept('^'))
          return base;
        const Nested nested(*this);
        return binary("^", std::move(base), unary());
      }

      /** While it lives, one more level of nesting (parentheses, function
       *  arguments, signs, powers); too deep a nesting is refused rather
       *  than overflowing the stack. */
      class Nested
      {
      public:
        explicit Nested(Parser &parser)
          : parser(parser)
        {
          if (++parser.depth > max_depth)
            parser.fail("nesting deeper than " + std::to_string(max_depth) +
                        " levels");
        }
        ~Nested()
        {
          --parser.depth;
        }

      private:
        Parser &parser;
      };

      NodePtr
      binary(const std::string &op, NodePtr a, NodePtr b)
      {
        std::vector<NodePtr> args;
        args.push_back(std::move(a));
        args.push_back(std::move(b));
        return make(Expression::Node::binary, op, std::move(args));
      }

      NodePtr
      primary()
      {
        skip_space();
        if (position >= text.size())
          fail("unexpected end of expression");
        if (accept('('))
          {
            const Nested nested(*this);
            NodePtr      inner = expression();
            if (!accept(')'))
              fail("missing ')'");
            return inner;
          }
        const char c = text[position];
        if (std::isdigit(c) || c == '.')
          {
            std::size_t  length = 0;
            const double value  = std::stod(text.substr(position), &length);
            position += length;
            auto node   = std::make_unique<Expression::Node>();
            node->kind  = Expression::Node::constant;
            node->value = value;
            return node;
          }
        if (std::isalpha(c) || c == '_')
          {
            const std::size_t start = position;
            while (position < text.size() &&
                   (std::isalnum(text[position]) || text[position] == '_'))
              ++position;
            const std::string name = text.substr(start, position - start);
            if (accept('('))
              {
                const Nested nested(*this);
                return name == "if" ? if_function() : function(name);
              }
            for (unsigned int i = 0; i < variables.size(); ++i)
              if (variables[i] == name)
                {
                  auto node   = std::make_unique<Expression::Node>();
                  node->kind  = Expression::Node::variable;
                  node->index = i;
                  return node;
                }
            const auto constant = constants.find(name);
            if (constant == constants.end())
              fail("unknown name '" + name + "'");
            auto node   = std::make_unique<Expression::Node>();
            node->kind  = Expression::Node::constant;
            node->value = constant->second;
            return node;
          }
        fail("unexpected '" + std::string(1, c) + "'");
      }

      NodePtr
      function(const std::string &name)
      {
        const auto &names = Expression::function_names();
        const auto  found = std::find(names.begin(), names.end(), name);
        if (found == names.end())
          fail("unknown function '" + name + "'");
        const auto function =
          static_cast<Expression::Function>(found - names.begin());
        const bool           two_argument = Expression::is_binary(function);
        std::vector<NodePtr> args;
        args.push_back(expression());
        if (two_argument)
          {
            if (!accept(','))
              fail("'" + name + "' needs two arguments");
            args.push_back(expression());
          }
        if (!accept(')'))
          fail("missing ')' after the arguments of '" + name + "'");
        NodePtr node = make(Expression::Node::function, name, std::move(args));
        node->fn     = function;
        return node;
      }

      /** if(c, a, b), muparser's spelling of c ? a : b. */
      NodePtr
      if_function()
      {
        NodePtr condition = expression();
        if (!accept(','))
          fail("'if' needs three arguments, if(condition, a, b)");
        NodePtr if_true = expression();
        if (!accept(','))
          fail("'if' needs three arguments, if(condition, a, b)");
        NodePtr node =
          operation("?:", std::move(condition), std::move(if_true));
        node->args.push_back(expression());
        if (!accept(')'))
          fail("missing ')' after the arguments of 'if'");
        return node;
      }

      /** The longest expression read, in characters. */
      static constexpr std::size_t max_length = 20000;
      /** The deepest nesting read. */
      static constexpr unsigned int max_depth = 500;

      inline static const std::vector<std::string> comparison_operators =
        {"<=", ">=", "==", "!=", "<", ">"};

      const std::string                    text;
      const std::vector<std::string>      &variables;
      const std::map<std::string, double> &constants;
      const std::string                    parameter_name;
      std::size_t                          position = 0;
      unsigned int                         depth    = 0;
    };
  } // namespace

  const std::vector<std::string> &
  Expression::function_names()
  {
    static const std::vector<std::string> names = {
      "sin",  "cos",  "tan", "exp",  "log",  "sqrt", "abs", "tanh", "sinh",
      "cosh", "atan", "pos", "step", "sign", "pow",  "max", "min",  "<",
      ">",    "<=",   ">=",  "==",   "!=",   "&&",   "||",  "?:"};
    return names;
  }

  bool
  Expression::is_binary(const Function f)
  {
    return f >= Function::pow && f < Function::conditional;
  }

  bool
  Expression::is_condition(const Function f)
  {
    return f >= Function::less && f < Function::conditional;
  }

  std::string
  quoted_expression(const std::string &text)
  {
    constexpr std::size_t shown = 200;
    if (text.size() <= shown)
      return "'" + text + "'";
    return "'" + text.substr(0, shown) + "...' (" +
           std::to_string(text.size()) + " characters)";
  }

  Expression::Expression(const std::string                   &text,
                         const std::vector<std::string>      &variables,
                         const std::map<std::string, double> &constants,
                         const std::string                   &parameter_name)
    : root(Parser(text, variables, constants, parameter_name).parse())
  {}
  bool
  Expression::uses_variable(const unsigned int index) const
  {
    std::vector<const Node *> stack = {root.get()};
    while (!stack.empty())
      {
        const Node *node = stack.back();
        stack.pop_back();
        if (node->kind == Node::variable && node->index == index)
          return true;
        for (const auto &arg : node->args)
          stack.push_back(arg.get());
      }
    return false;
  }
} // namespace hemicontact
