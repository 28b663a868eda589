#include "prove/cpp_reader.hpp"

#include <algorithm>
#include <array>
#include <cctype>

namespace billiards::derive {

namespace {

struct Token {
  enum class Kind { identifier, number, punctuation, directive, string, end };
  Kind kind = Kind::end;
  std::string text;
  int line = 0;
};

bool identifier_char(char c) { return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '_'; }

// The text as tokens: comments dropped, a preprocessor line one token, `a::b` one identifier.
std::vector<Token> tokenize(const std::string& text) {
  static const std::array<std::string, 17> operators = {
      "<<=", ">>=", "::", "<<", ">>", "<=", ">=", "==", "!=", "&&", "||", "+=", "-=", "*=", "/=", "++", "--"};
  std::vector<Token> tokens;
  int line = 1;
  bool line_start = true;
  for (std::size_t i = 0; i < text.size();) {
    const char c = text[i];
    if (c == '\n') {
      ++line;
      line_start = true;
      ++i;
      continue;
    }
    if (std::isspace(static_cast<unsigned char>(c)) != 0) {
      ++i;
      continue;
    }
    if (text.compare(i, 2, "//") == 0) {
      i = std::min(text.find('\n', i), text.size());
      continue;
    }
    if (text.compare(i, 2, "/*") == 0) {
      const std::size_t end = text.find("*/", i + 2);
      if (end == std::string::npos) throw CppReadError(line, "a comment that does not end");
      line += static_cast<int>(std::count(text.begin() + static_cast<std::ptrdiff_t>(i),
                                          text.begin() + static_cast<std::ptrdiff_t>(end), '\n'));
      i = end + 2;
      continue;
    }
    const bool at_line_start = line_start;
    line_start = false;
    if (c == '#' && at_line_start) {
      const std::size_t end = std::min(text.find('\n', i), text.size());
      tokens.push_back({Token::Kind::directive, text.substr(i + 1, end - i - 1), line});
      i = end;
      continue;
    }
    if (c == '"') {
      std::size_t end = i + 1;
      while (end < text.size() && text[end] != '"' && text[end] != '\n') end += text[end] == '\\' ? 2 : 1;
      if (end >= text.size() || text[end] != '"') throw CppReadError(line, "a string that does not end");
      tokens.push_back({Token::Kind::string, text.substr(i, end + 1 - i), line});
      i = end + 1;
      continue;
    }
    if (std::isdigit(static_cast<unsigned char>(c)) != 0 ||
        (c == '.' && i + 1 < text.size() && std::isdigit(static_cast<unsigned char>(text[i + 1])) != 0)) {
      // A number: digits, letters, points, and a sign right after an exponent letter (1e-5, 0x1p-61f).
      const bool hexadecimal = text.compare(i, 2, "0x") == 0 || text.compare(i, 2, "0X") == 0;
      std::size_t end = i;
      while (end < text.size()) {
        const char d = text[end];
        const char before =
            end > i ? static_cast<char>(std::tolower(static_cast<unsigned char>(text[end - 1]))) : 0;
        const bool sign = (d == '-' || d == '+') && (hexadecimal ? before == 'p' : before == 'e');
        if (!identifier_char(d) && d != '.' && !sign) break;
        ++end;
      }
      tokens.push_back({Token::Kind::number, text.substr(i, end - i), line});
      i = end;
      continue;
    }
    if (identifier_char(c) ||
        (text.compare(i, 2, "::") == 0 && i + 2 < text.size() && identifier_char(text[i + 2]))) {
      std::size_t end = i;
      while (end < text.size()) {
        if (identifier_char(text[end])) {
          ++end;
        } else if (text.compare(end, 2, "::") == 0 && end + 2 < text.size() &&
                   identifier_char(text[end + 2])) {
          end += 2;
        } else {
          break;
        }
      }
      tokens.push_back({Token::Kind::identifier, text.substr(i, end - i), line});
      i = end;
      continue;
    }
    std::string op(1, c);
    for (const std::string& candidate : operators) {
      if (text.compare(i, candidate.size(), candidate) == 0) {
        op = candidate;
        break;
      }
    }
    tokens.push_back({Token::Kind::punctuation, op, line});
    i += op.size();
  }
  tokens.push_back({Token::Kind::end, "", line});
  return tokens;
}

// The types a template argument list of the subset holds.
bool is_template_argument(const std::string& name) {
  return name == "Scalar" || name == "Bits" || name == "float" || name == "double" || name == "int" ||
         name == "std::uint32_t" || name == "std::uint64_t";
}

class Parser {
 public:
  explicit Parser(std::vector<Token> tokens) : tokens_(std::move(tokens)) {}

  std::vector<CppFunction> functions() {
    std::vector<CppFunction> out;
    int depth = 0;  // namespaces entered
    while (peek().kind != Token::Kind::end) {
      const Token& token = peek();
      if (token.kind == Token::Kind::directive) {
        ++at_;
      } else if (token.text == "namespace") {
        while (peek().text != "{") take_any("a namespace's '{'");
        ++at_;
        ++depth;
      } else if (token.text == "}") {
        if (depth == 0) throw CppReadError(token.line, "a '}' that closes nothing");
        --depth;
        ++at_;
      } else if (token.text == "using") {
        skip_past(";");
      } else {
        if (auto function = declaration()) out.push_back(std::move(*function));
      }
    }
    return out;
  }

  CppExpression expression_only() {
    CppExpression e = expression();
    if (peek().kind != Token::Kind::end) fail("the end of the expression");
    return e;
  }

 private:
  const Token& peek(std::size_t ahead = 0) const {
    return tokens_[std::min(at_ + ahead, tokens_.size() - 1)];
  }

  [[noreturn]] void fail(const std::string& expected) const {
    const Token& t = peek();
    throw CppReadError(t.line,
                       "expected " + expected + ", found " +
                           (t.kind == Token::Kind::end ? std::string("the end") : "'" + t.text + "'"));
  }

  const Token& take_any(const std::string& expected) {
    if (peek().kind == Token::Kind::end) fail(expected);
    return tokens_[at_++];
  }

  void expect(const std::string& text) {
    if (peek().text != text || peek().kind == Token::Kind::string) fail("'" + text + "'");
    ++at_;
  }

  bool accept(const std::string& text) {
    if (peek().text != text || peek().kind == Token::Kind::string || peek().kind == Token::Kind::directive)
      return false;
    ++at_;
    return true;
  }

  std::string identifier(const std::string& expected) {
    if (peek().kind != Token::Kind::identifier) fail(expected);
    return tokens_[at_++].text;
  }

  void skip_past(const std::string& text) {
    while (!accept(text)) take_any("'" + text + "'");
  }

  // Skips a balanced `{ … }` starting at the '{'.
  void skip_braces() {
    expect("{");
    for (int depth = 1; depth > 0;) {
      const Token& t = take_any("a '}'");
      if (t.kind != Token::Kind::punctuation) continue;
      depth += t.text == "{" ? 1 : t.text == "}" ? -1 : 0;
    }
  }

  // A declaration at namespace scope: a template header, then a struct (passed over), an alias (passed
  // over) or a function definition (read).
  std::optional<CppFunction> declaration() {
    if (accept("template")) {
      expect("<");
      while (!accept(">")) take_any("the end of a template parameter list");
    }
    if (peek().text == "using") {
      skip_past(";");
      return std::nullopt;
    }
    if (peek().text == "struct") {
      while (peek().text != "{") take_any("a struct's '{'");
      skip_braces();
      expect(";");
      return std::nullopt;
    }
    CppFunction f;
    std::vector<std::string> head;
    while (peek().text != "(") {
      const Token& t = take_any("a function's '('");
      // A variable at namespace scope (`inline constexpr std::size_t largest_arity = 6;`) is no function.
      if (t.text == "=" && !head.empty()) {
        skip_past(";");
        return std::nullopt;
      }
      if (t.text == ";" || t.text == "{") throw CppReadError(t.line, "expected a function definition");
      head.push_back(t.text);
    }
    // name, or name < T > for an explicit specialisation
    if (head.size() >= 4 && head.back() == ">" && head[head.size() - 3] == "<") {
      f.specialization = head[head.size() - 2];
      head.resize(head.size() - 3);
    }
    if (head.empty()) fail("a function name");
    f.name = head.back();
    f.line = peek().line;
    head.pop_back();
    std::string result;
    for (const std::string& word : head) {
      if (word == "BILLIARDS_HOST_DEVICE" || word == "constexpr" || word == "inline" || word == "static")
        continue;
      result += (result.empty() || word == "<" || word == ">" || result.back() == '<' ? "" : " ") + word;
    }
    f.result = result;
    expect("(");
    while (!accept(")")) {
      std::vector<std::string> words;
      while (peek().text != "," && peek().text != ")") words.push_back(take_any("a parameter").text);
      if (words.size() < 2) fail("a parameter's type and name");
      std::string type;
      for (std::size_t i = 0; i + 1 < words.size(); ++i) type += (i ? " " : "") + words[i];
      f.parameters.emplace_back(type, words.back());
      accept(",");
    }
    accept("noexcept");
    expect("{");
    while (!accept("}")) f.body.push_back(statement());
    return f;
  }

  CppStatement statement() {
    const std::size_t first = at_;
    CppStatement s = unrecorded_statement();
    for (std::size_t i = first; i < at_ && i < tokens_.size(); ++i)
      s.tokens.push_back(tokens_[i].kind == Token::Kind::directive ? "#" + tokens_[i].text : tokens_[i].text);
    return s;
  }

  CppStatement unrecorded_statement() {
    CppStatement s;
    s.line = peek().line;
    if (peek().kind == Token::Kind::directive) {
      s.kind = CppStatement::Kind::directive;
      s.text = tokens_[at_++].text;
      return s;
    }
    if (accept("{")) {
      s.kind = CppStatement::Kind::block;
      while (!accept("}")) s.body.push_back(statement());
      return s;
    }
    if (accept("if")) {
      s.kind = CppStatement::Kind::if_;
      if (accept("constexpr")) s.type = "constexpr";
      expect("(");
      s.condition = expression();
      expect(")");
      s.body.push_back(statement());
      if (peek().text == "else") fail("no 'else' (the emitter prints none)");
      return s;
    }
    if (accept("for")) {
      s.kind = CppStatement::Kind::for_;
      expect("(");
      s.body.push_back(simple_statement());
      s.condition = expression();
      expect(";");
      CppStatement step;
      step.line = peek().line;
      if (accept("++")) {
        step.kind = CppStatement::Kind::increment;
        step.name = identifier("the loop's counter");
      } else {
        fail("'++' and the loop's counter");
      }
      s.body.push_back(step);
      expect(")");
      s.body.push_back(statement());
      return s;
    }
    if (accept("throw")) {
      s.kind = CppStatement::Kind::throw_;
      s.value = expression();
      expect(";");
      return s;
    }
    if (accept("return")) {
      s.kind = CppStatement::Kind::return_;
      if (peek().text == "{") {
        s.value = braced();
      } else {
        s.value = expression();
      }
      expect(";");
      return s;
    }
    return simple_statement();
  }

  // A declaration, alias, assignment or increment, with its ';'.
  CppStatement simple_statement() {
    CppStatement s;
    s.line = peek().line;
    if (accept("using")) {
      s.kind = CppStatement::Kind::alias;
      s.name = identifier("an alias name");
      const std::size_t aliased = at_;
      skip_past(";");
      // The aliased type is not read: kept as its tokens, so that printing it again gives them back.
      for (std::size_t i = aliased + 1; i + 1 < at_; ++i) s.text += (s.text.empty() ? "" : " ") + tokens_[i].text;
      return s;
    }
    // `name op value;` when an identifier is followed by an assignment operator.
    static const std::array<std::string, 5> assignments = {"=", "+=", "-=", "*=", "/="};
    if (peek().kind == Token::Kind::identifier &&
        std::find(assignments.begin(), assignments.end(), peek(1).text) != assignments.end()) {
      s.kind = CppStatement::Kind::assignment;
      s.name = tokens_[at_++].text;
      s.op = tokens_[at_++].text;
      s.value = expression();
      expect(";");
      return s;
    }
    // type words, then the name, '=' and the value
    s.kind = CppStatement::Kind::declaration;
    std::vector<std::string> words;
    while (peek().text != "=") {
      const Token& t = take_any("a declaration's '='");
      if (t.kind != Token::Kind::identifier)
        throw CppReadError(t.line, "expected a statement, found '" + t.text + "'");
      words.push_back(t.text);
    }
    if (words.size() < 2) fail("a declaration's type and name");
    s.name = words.back();
    for (std::size_t i = 0; i + 1 < words.size(); ++i) s.type += (i ? " " : "") + words[i];
    expect("=");
    s.value = expression();
    expect(";");
    return s;
  }

  CppExpression braced() {
    CppExpression e;
    e.kind = CppExpression::Kind::braced;
    e.line = peek().line;
    expect("{");
    while (!accept("}")) {
      e.operands.push_back(expression());
      if (peek().text != "}") expect(",");
    }
    return e;
  }

  CppExpression expression() {
    CppExpression condition = binary(0);
    if (!accept("?")) return condition;
    CppExpression e;
    e.kind = CppExpression::Kind::conditional;
    e.line = condition.line;
    e.operands.push_back(std::move(condition));
    e.operands.push_back(expression());
    expect(":");
    e.operands.push_back(expression());
    return e;
  }

  // Binary operators by C++'s precedence, loosest first.
  static int precedence(const std::string& op) {
    static const std::vector<std::vector<std::string>> levels = {
        {"||"}, {"&&"}, {"&"}, {"==", "!="}, {"<", "<=", ">", ">="}, {"<<", ">>"}, {"+", "-"}, {"*", "/"}};
    for (std::size_t level = 0; level < levels.size(); ++level) {
      if (std::find(levels[level].begin(), levels[level].end(), op) != levels[level].end())
        return static_cast<int>(level);
    }
    return -1;
  }

  CppExpression binary(int level) {
    if (level > 7) return unary();
    CppExpression left = binary(level + 1);
    while (peek().kind == Token::Kind::punctuation && precedence(peek().text) == level) {
      CppExpression e;
      e.kind = CppExpression::Kind::binary;
      e.text = tokens_[at_++].text;
      e.line = left.line;
      e.operands.push_back(std::move(left));
      e.operands.push_back(binary(level + 1));
      left = std::move(e);
    }
    return left;
  }

  CppExpression unary() {
    if (peek().kind == Token::Kind::punctuation && (peek().text == "-" || peek().text == "!")) {
      CppExpression e;
      e.kind = CppExpression::Kind::unary;
      e.line = peek().line;
      e.text = tokens_[at_++].text;
      e.operands.push_back(unary());
      return e;
    }
    return primary();
  }

  CppExpression primary() {
    CppExpression e;
    e.line = peek().line;
    if (peek().kind == Token::Kind::number || peek().kind == Token::Kind::string) {
      e.kind = CppExpression::Kind::literal;
      e.text = tokens_[at_++].text;
      return e;
    }
    if (accept("(")) {
      e = expression();
      expect(")");
      return e;
    }
    if (peek().kind != Token::Kind::identifier) fail("an expression");
    e.text = tokens_[at_++].text;
    // Template arguments: `name<T>` where T is one of the subset's types.
    if (peek().text == "<" && peek(1).kind == Token::Kind::identifier && is_template_argument(peek(1).text) &&
        peek(2).text == ">") {
      e.text += "<" + peek(1).text + ">";
      at_ += 3;
      if (peek().kind == Token::Kind::identifier && peek().text.rfind("::", 0) == 0)
        e.text += tokens_[at_++].text;
    }
    // A member, `r.first`, is one name.
    while (peek().text == "." && peek().kind == Token::Kind::punctuation && peek(1).kind == Token::Kind::identifier) {
      e.text += "." + peek(1).text;
      at_ += 2;
    }
    if (accept("[")) {
      e.kind = CppExpression::Kind::index;
      e.operands.push_back(expression());
      expect("]");
      return e;
    }
    if (!accept("(")) {
      e.kind = CppExpression::Kind::name;
      return e;
    }
    e.kind = CppExpression::Kind::call;
    while (!accept(")")) {
      e.operands.push_back(expression());
      if (peek().text != ")") expect(",");
    }
    return e;
  }

  std::vector<Token> tokens_;
  std::size_t at_ = 0;
};

}  // namespace

std::vector<CppFunction> read_functions(const std::string& text) {
  return Parser(tokenize(text)).functions();
}

CppExpression read_expression(const std::string& text) { return Parser(tokenize(text)).expression_only(); }

std::string spelled(const CppExpression& e) {
  using Kind = CppExpression::Kind;
  std::string out;
  switch (e.kind) {
    case Kind::literal:
    case Kind::name: return e.text;
    case Kind::unary: return e.text + spelled(e.operands.at(0));
    case Kind::binary:
      return "(" + spelled(e.operands.at(0)) + " " + e.text + " " + spelled(e.operands.at(1)) + ")";
    case Kind::conditional:
      return "(" + spelled(e.operands.at(0)) + " ? " + spelled(e.operands.at(1)) + " : " +
             spelled(e.operands.at(2)) + ")";
    case Kind::index: return e.text + "[" + spelled(e.operands.at(0)) + "]";
    case Kind::call:
    case Kind::braced:
      for (const CppExpression& operand : e.operands) out += (out.empty() ? "" : ", ") + spelled(operand);
      return e.kind == Kind::call ? e.text + "(" + out + ")" : "{" + out + "}";
  }
  return out;
}

namespace {

// C++'s precedence of a binary operator (its row in the standard's table, tighter first), written out
// here apart from the reader's table.
int binding(const std::string& op) {
  if (op == "*" || op == "/" || op == "%") return 5;
  if (op == "+" || op == "-") return 6;
  if (op == "<<" || op == ">>") return 7;
  if (op == "<" || op == "<=" || op == ">" || op == ">=") return 9;
  if (op == "==" || op == "!=") return 10;
  if (op == "&") return 11;
  if (op == "^") return 12;
  if (op == "|") return 13;
  if (op == "&&") return 14;
  if (op == "||") return 15;
  return 16;
}

// How loosely an expression binds as an operand: names, literals, calls and indexing 0, a negation 3,
// a binary operator its row, `?:` 16.
int looseness(const CppExpression& e) {
  switch (e.kind) {
    case CppExpression::Kind::unary: return 3;
    case CppExpression::Kind::binary: return binding(e.text);
    case CppExpression::Kind::conditional: return 16;
    default: return 0;
  }
}

std::string again(const CppExpression& e) {
  using Kind = CppExpression::Kind;
  const auto wrapped = [](const std::string& text) { return "(" + text + ")"; };
  std::string out;
  switch (e.kind) {
    case Kind::literal:
    case Kind::name: return e.text;
    case Kind::unary: {
      // The emitter negates one token as -x and anything longer as -(…).
      const std::string operand = again(e.operands.at(0));
      return e.text + (operand.find(' ') == std::string::npos ? operand : wrapped(operand));
    }
    case Kind::binary: {
      const int own = binding(e.text);
      const std::string left = again(e.operands.at(0)), right = again(e.operands.at(1));
      // Left to right: an operand of the same row groups to the left, on the right it needs parentheses.
      // As GCC's -Wparentheses asks, a bit operation or shift wraps every operation it takes, and ||
      // wraps an && it takes.
      const bool bits = own == 7 || (own >= 11 && own <= 13);
      const auto clarified = [&](const CppExpression& operand) {
        return (bits && operand.kind == Kind::binary) ||
               (e.text == "||" && operand.kind == Kind::binary && operand.text == "&&");
      };
      return (looseness(e.operands[0]) > own || clarified(e.operands[0]) ? wrapped(left) : left) + " " + e.text +
             " " + (looseness(e.operands[1]) >= own || clarified(e.operands[1]) ? wrapped(right) : right);
    }
    case Kind::conditional: {
      const std::string condition = again(e.operands.at(0));
      return (looseness(e.operands[0]) >= 16 ? wrapped(condition) : condition) + " ? " +
             again(e.operands.at(1)) + " : " + again(e.operands.at(2));
    }
    case Kind::index: return e.text + "[" + again(e.operands.at(0)) + "]";
    case Kind::call:
    case Kind::braced:
      for (const CppExpression& operand : e.operands) out += (out.empty() ? "" : ", ") + again(operand);
      return e.kind == Kind::call ? e.text + "(" + out + ")" : "{" + out + "}";
  }
  return out;
}

}  // namespace

std::string printed_again(const CppStatement& s) {
  using Kind = CppStatement::Kind;
  std::string out;
  switch (s.kind) {
    case Kind::directive: return "\n#" + s.text + "\n";
    case Kind::declaration: return s.type + " " + s.name + " = " + again(*s.value) + ";";
    case Kind::alias: return "using " + s.name + " = " + s.text + ";";
    case Kind::assignment: return s.name + " " + s.op + " " + again(*s.value) + ";";
    case Kind::increment: return "++" + s.name;
    case Kind::if_:
      return std::string("if ") + (s.type == "constexpr" ? "constexpr " : "") + "(" + again(*s.condition) + ") " +
             printed_again(s.body.at(0));
    case Kind::for_:
      return "for (" + printed_again(s.body.at(0)) + " " + again(*s.condition) + "; " + printed_again(s.body.at(1)) +
             ") " + printed_again(s.body.at(2));
    case Kind::return_: return "return " + again(*s.value) + ";";
    case Kind::throw_: return "throw " + again(*s.value) + ";";
    case Kind::block:
      for (const CppStatement& inner : s.body) out += printed_again(inner) + "\n";
      return "{\n" + out + "}";
  }
  return out;
}

bool reads_as_printed(const CppStatement& statement) {
  std::vector<std::string> tokens;
  try {
    for (const Token& t : tokenize(printed_again(statement))) {
      if (t.kind != Token::Kind::end) tokens.push_back(t.kind == Token::Kind::directive ? "#" + t.text : t.text);
    }
  } catch (const CppReadError&) {
    return false;
  }
  return tokens == statement.tokens;
}

}  // namespace billiards::derive
