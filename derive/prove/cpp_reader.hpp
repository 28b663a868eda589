// A reader for the subset of C++ the emitter prints: function templates and their specialisations, whose
// bodies are declarations, assignments, `if`, `for`, `return` and preprocessor lines, over expressions of
// names, literals, calls (with template arguments), unary and binary operators and `?:`. The emitted text
// is read back with it and proven again (read_back.hpp): what is proven is the text that ships. It
// knows C++'s grammar for this subset, nothing of what the names mean.
#pragma once

#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace billiards::derive {

/// The text could not be read: the line (1-based) and what was expected there.
class CppReadError : public std::runtime_error {
 public:
  CppReadError(int line, const std::string& what)
      : std::runtime_error("line " + std::to_string(line) + ": " + what), line_(line) {}
  int line() const { return line_; }

 private:
  int line_;
};

/// An expression.
struct CppExpression {
  enum class Kind {
    literal,      ///< a number or a string as spelled: 4096, 3.5, 0x1p-61f, "m1"
    name,         ///< an identifier, possibly qualified, or a member: m1, r.first,
                  ///< std::numeric_limits<Scalar>::min_exponent
    call,         ///< `text(operands…)`; text is the callee with its template arguments: Scalar, std::sqrt,
                  ///< smallest_normal<Scalar>, static_cast<Bits>
    unary,        ///< `text operand`: - or !
    binary,       ///< `operand text operand`: + - * / < <= > >= == != && || & << >>
    conditional,  ///< `a ? b : c`
    braced,       ///< `{a, b}` (a returned pair)
    index,        ///< `text[operand]`: a[0]
  };
  Kind kind = Kind::literal;
  std::string text;
  std::vector<CppExpression> operands;
  int line = 0;
};

/// A statement of a function body.
struct CppStatement {
  enum class Kind {
    directive,    ///< a preprocessor line, `text` without its '#': "if !defined(__CUDA_ARCH__)", "endif"
    declaration,  ///< `type name = value;` (type: "const Scalar", "Scalar", "auto", "constexpr int", …)
    alias,        ///< `using name = …;` (the aliased type is not read)
    assignment,   ///< `name op value;`, op "=", "/=", …
    increment,    ///< `++name;`
    if_,          ///< `if (condition) body` or `if constexpr (condition) { body }`
    for_,         ///< `for (body[0]; condition; body[1]) body[2]`
    return_,      ///< `return value;`
    throw_,       ///< `throw value;`
    block,        ///< `{ body }`
  };
  Kind kind = Kind::block;
  std::string type;  ///< a declaration's type; "constexpr" for `if constexpr`
  std::string name;  ///< declared or assigned name
  std::string op;    ///< an assignment's operator
  std::string text;  ///< a directive's text
  std::optional<CppExpression> value;
  std::optional<CppExpression> condition;
  std::vector<CppStatement> body;
  int line = 0;
  /// The tokens the statement was read from, in order (a preprocessor line is one token, `#` and all),
  /// for the round trip: printed_again(statement) must read as these.
  std::vector<std::string> tokens;
};

/// A function (or function template) definition.
struct CppFunction {
  std::string name;            ///< without template arguments: plain_mass_low
  std::string specialization;  ///< the explicit specialisation's argument, "float" for name<float>; or ""
  std::string result;          ///< the result type as written, qualifiers dropped: Scalar, bool, float
  std::vector<std::pair<std::string, std::string>> parameters;  ///< (type, name) in order
  std::vector<CppStatement> body;
  int line = 0;  ///< where its name stands
};

/// Every function defined in `text` (a header the emitter printed), in order. Namespaces are entered;
/// structs, aliases and preprocessor lines outside functions are passed over. Throws CppReadError for
/// anything outside the subset.
std::vector<CppFunction> read_functions(const std::string& text);

/// Parses one expression (for tests and diagnostics). Throws CppReadError.
CppExpression read_expression(const std::string& text);

/// The statement written back as the emitter prints C++, from what was read: operators spaced,
/// parentheses only where C++'s precedence and left-to-right grouping need them, and around a negated
/// operand that is more than one token. Its own table of C++'s precedence, not the reader's: where
/// the reader grouped an expression otherwise than C++ does, the text differs from the one read.
std::string printed_again(const CppStatement& statement);

/// Whether printed_again(statement) reads as the very tokens the statement was read from: the round
/// trip that shows the reader kept the printed text's grouping, and so its order of rounding.
bool reads_as_printed(const CppStatement& statement);

/// The expression written back in C++ with every operator spaced and every operation parenthesised, for
/// messages: ((a + b) * c).
std::string spelled(const CppExpression& e);

}  // namespace billiards::derive
