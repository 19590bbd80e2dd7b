// The grammar language, as this parser reads it (docs/grammar.md says it for users):
//
//   file      := { line }
//   line      := NEWLINE | directive NEWLINE | constant NEWLINE | rule NEWLINE
//   directive := '@start' IDENT | '@scope' expr ',' expr ',' expr | '@primitives' STRING
//   constant  := IDENT '=' expr
//   rule      := IDENT [ '(' [ IDENT { ',' IDENT } ] ')' ] [ ':' expr ] ARROW op [ ':' expr ]
//   op        := 'split' '(' expr ')' '{' size ':' op { '|' size ':' op } '}'
//              | 'repeat' '(' expr ',' expr ')' '{' op '}'
//              | 'repeat' '(' expr ')' '{' expr ':' op '}'
//              | 'repeatN' '(' expr ',' expr ')' '{' op '}'
//              | 'I' '(' ( IDENT | STRING ) ')'
//              | 'nil'
//              | ( 'T' | 'S' ) '(' size ',' size ',' size ')' '{' op '}'
//              | 'R' '(' expr ',' expr ')' '{' op '}'
//              | 'comp' '(' 'f' ')' '{' FACE ':' op { '|' FACE ':' op } '}'
//              | ( 'colour' | 'color' ) '(' ( COLOURNAME | STRING | expr ',' expr ',' expr ) ')'
//              | IDENT [ '(' [ expr { ',' expr } ] ')' ]
//   size      := [ '~' ] expr
//   expr      := and { '||' and }        and := equality { '&&' equality }
//   equality  := relation { ('=='|'!=') relation }
//   relation  := sum { ('<'|'<='|'>'|'>=') sum }
//   sum       := product { ('+'|'-') product }
//   product   := unary { ('*'|'/'|'%') unary }
//   unary     := ( '-' | '!' ) unary | primary
//   primary   := NUMBER | '(' expr ')' | IDENT [ '(' [ expr { ',' expr } ] ')' ]
//
// ARROW is '-->', '->' or '→'; NEWLINE is reported only outside ( ) and { }.
// Rules sharing a label are alternatives: they become one Choose body when
// there are several, or when the only one has a condition or a priority.
#include "graph/parser.hpp"

#include <array>
#include <cctype>
#include <cmath>
#include <fstream>
#include <map>
#include <numbers>

#include "base/input_file.hpp"
#include "base/name_index.hpp"
#include "base/out_of_memory.hpp"
#include "base/stack_guard.hpp"
#include "base/suggest.hpp"
#include "graph/label.hpp"
#include "graph/lexer.hpp"
#include "graph/reserved_words.hpp"

namespace vern {

namespace {

struct NamedColour {
  std::string_view name;
  double r, g, b;
};
constexpr NamedColour kColours[] = {
    {"black", 0, 0, 0},        {"white", 1, 1, 1},          {"red", 0.8, 0.1, 0.1},
    {"green", 0.2, 0.6, 0.2},  {"blue", 0.15, 0.3, 0.8},    {"yellow", 0.95, 0.85, 0.2},
    {"orange", 0.95, 0.55, 0.1}, {"brown", 0.5, 0.3, 0.15}, {"grey", 0.5, 0.5, 0.5},
    {"gray", 0.5, 0.5, 0.5},   {"beige", 0.9, 0.85, 0.7},   {"brick", 0.65, 0.3, 0.2},
    {"glass", 0.55, 0.75, 0.85}, {"slate", 0.35, 0.4, 0.45}, {"sand", 0.85, 0.75, 0.55},
};


// The rule lines of one label read so far, as the Choose they become
// holds them (gathered in another form and copied, they cost twice).
struct Alternatives {
  std::size_t lines = 0;  // rule lines of the label, as the first pass counted them
  std::vector<ChooseOption> options;
  bool first_priority_written = false;  // a lone line without one needs no Choose
  SourceLoc first_loc;
};

struct RuleHeader {
  std::string label;
  std::vector<std::string> params;
  SourceLoc loc;
};

class Parser {
 public:
  Parser(std::string_view text, const std::string& source) : source_(source), text_(text), lexer_(text, source) {
    g_.source_name = source;
  }

  Grammar run() {
    declare_rules();
    while (peek().kind != TokenKind::End) {
      if (accept(TokenKind::Newline)) continue;
      if (peek().kind == TokenKind::Directive) {
        directive();
      } else if (peek().kind == TokenKind::Identifier && peek(1).kind == TokenKind::Assign) {
        constant();
      } else {
        rule();
      }
      end_of_line();
    }
    finish_rules();
    for (const auto& c : pending_calls_) check_call(c);
    return std::move(g_);
  }

 private:
  // ---- tokens ----
  // Token number pos_ + ahead, read from the text when first asked for.
  // Tokens are handed out as copies (a `const Token&` to one keeps it), so
  // only those not yet read are kept: never more than the look-ahead, where
  // holding the tokens of the file (or of a line of a million parts) took
  // some 40 times the memory of the text.
  Token peek(std::size_t ahead = 0) {
    const std::size_t passed = std::min(pos_ - first_, count_);  // more: read past the end, which stays End
    head_ = (head_ + passed) % ahead_.size();
    count_ -= passed;
    first_ = pos_;
    if (ahead >= ahead_.size()) throw Error(ErrorKind::Internal, "the grammar parser looks too far ahead");
    while (count_ <= ahead) ahead_[(head_ + count_++) % ahead_.size()] = lexer_.next();
    return ahead_[(head_ + ahead) % ahead_.size()];
  }
  Token next() {
    const Token t = peek();
    if (t.kind != TokenKind::End) ++pos_;
    return t;
  }
  bool accept(TokenKind k) {
    if (peek().kind != k) return false;
    ++pos_;
    return true;
  }
  // `hint` shows the construct being read as it is written: most of these
  // errors are a missing bracket, comma or ':', which that makes plain.
  Token expect(TokenKind k, std::string_view context, std::string_view hint) {
    if (peek().kind != k) {
      error(peek().loc,
            "expected " + std::string(token_kind_name(k)) + " " + std::string(context) + ", found " + describe(peek()),
            std::string(hint));
    }
    return next();
  }
  static std::string describe(const Token& t) {
    switch (t.kind) {
      case TokenKind::Identifier: return "'" + shown_name(t.text) + "'";
      case TokenKind::Number: return "the number " + shown_name(t.text);
      case TokenKind::Newline:
      case TokenKind::End: return token_kind_name(t.kind);
      default: return token_kind_name(t.kind);
    }
  }
  void end_of_line() {
    if (peek().kind == TokenKind::Newline || peek().kind == TokenKind::End) {
      accept(TokenKind::Newline);
      return;
    }
    error(peek().loc, "unexpected " + describe(peek()) + " after a complete line",
          "one rule, constant or directive per line; continue a rule only inside ( ) or { }");
  }
  void skip_newlines() {
    while (accept(TokenKind::Newline)) {
    }
  }
  [[noreturn]] void error(SourceLoc loc, const std::string& message, const std::string& hint) const {
    fail(ErrorKind::Input, source_, loc, message, hint);
  }

  // Operations and expressions are read by recursive descent, and every
  // later pass (derivation, evaluation, writing, checking) walks them
  // recursively too: a bound on nesting keeps a hostile file from running
  // any of them out of stack. No grammar a person writes comes near it.
  static constexpr int kMaxNesting = 256;
  // An expression node counts its arguments in 16 bits (graph/expr.hpp).
  static constexpr std::size_t kMaxArguments = 65535;
  // And a rule as many parameters: more than any rule needs, and each call
  // binds them all on the derivation's stack of arguments.
  static constexpr std::size_t kMaxParameters = kMaxArguments;

  class Nesting {
   public:
    Nesting(Parser& p, SourceLoc loc) : p_(p) {
      if (++p_.nesting_ > kMaxNesting)
        p_.error(loc, "operations or expressions nested more than " + std::to_string(kMaxNesting) + " deep",
                 "give the inner part a name: a rule for an operation, a constant for a value");
      // The commands' threads hold the bound (support/command_stack.hpp); a
      // smaller thread of a program that embeds the reader stops here.
      if (p_.stack_.exhausted())
        fail(ErrorKind::Limit, p_.source_, loc,
             "operations or expressions nested " + std::to_string(p_.nesting_) + " deep fill this thread's " +
                 p_.stack_.size_text() + " stack",
             "read the grammar on a thread with a larger stack, or give the inner part a name");
    }
    ~Nesting() { --p_.nesting_; }
    Nesting(const Nesting&) = delete;
    Nesting& operator=(const Nesting&) = delete;

   private:
    Parser& p_;
  };

  // The same bound on an expression tree's depth: a long chain such as
  // 1 + 1 + ... + 1 nests without nesting the text.
  void check_depth(const Expr& e) const {
    std::vector<std::uint32_t> depth(e.nodes().size(), 1);
    for (std::size_t i = 0; i < e.nodes().size(); ++i) {
      for (std::size_t c : e.children(i)) depth[i] = std::max(depth[i], depth[c] + 1);
      if (depth[i] > static_cast<std::uint32_t>(kMaxNesting))
        error(e.loc(i), "an expression nested more than " + std::to_string(kMaxNesting) + " deep",
              "split it into constants, or into rule parameters");
    }
  }

  // ---- pass 1: every rule label, so calls may name rules defined later ----
  // A line that starts with a name (not `name =`) is a rule when an arrow
  // follows before its end. The text is read a second time for this, a
  // token at a time: holding its tokens for the second pass cost more
  // memory than everything else the reader builds.
  void declare_rules() {
    // Lines that started with a name and have shown no arrow yet, each
    // with its bracket depth: the lexer reports newlines only outside
    // ( ) and { }, but a stray ')' takes this count below zero, and then
    // the line goes on to the next newline where it is back at zero.
    struct Candidate {
      std::string label;
      SourceLoc loc;
      int depth = 0;
    };
    std::vector<Candidate> open;
    Lexer lexer(text_, source_);
    Token t = lexer.next();
    bool line_start = true;
    while (t.kind != TokenKind::End) {
      Token following = lexer.next();
      std::size_t kept = 0;
      for (Candidate& c : open) {
        if (t.kind == TokenKind::Arrow) {
          declare_rule(c.label, c.loc);
          continue;
        }
        if (t.kind == TokenKind::Newline && c.depth == 0) continue;  // no arrow on its line
        if (t.kind == TokenKind::LParen || t.kind == TokenKind::LBrace) ++c.depth;
        if (t.kind == TokenKind::RParen || t.kind == TokenKind::RBrace) --c.depth;
        if (&open[kept] != &c) open[kept] = std::move(c);
        ++kept;
      }
      open.resize(kept);
      if (line_start && t.kind == TokenKind::Identifier && following.kind != TokenKind::Assign)
        open.push_back({std::string(t.text), t.loc});
      line_start = t.kind == TokenKind::Newline;
      t = std::move(following);
    }
    // Room for each label's lines at once: grown by doubling, 200,000
    // alternatives of one label held room for up to twice as many.
    for (Alternatives& a : alternatives_) a.options.reserve(a.lines);
    for (const auto& r : g_.rules) rule_names_.push_back(r.label);
  }

  void declare_rule(const std::string& label, SourceLoc loc) {
    const auto [it, added] = labels_.try_emplace(label, static_cast<RuleId>(g_.rules.size()));
    if (added) {
      g_.rules.push_back({label, {}, 0, loc});
      declared_params_.push_back(-1);
      alternatives_.emplace_back();
    }
    ++alternatives_[it->second].lines;
  }

  // ---- lines ----
  void directive() {
    const Token& d = next();
    if (d.value == "start") {
      const Token& name = expect(TokenKind::Identifier, "after @start (the start rule's label)", "write @start plot");
      start_label_ = std::string(name.text);
      start_loc_ = name.loc;
    } else if (d.value == "scope") {
      for (int i = 0; i < 3; ++i) {
        if (i) expect(TokenKind::Comma, "between the three @scope sizes (x, y, z)", "write @scope 12, 8, 9");
        g_.scope[i] = expression();
      }
    } else if (d.value == "primitives") {
      const Token& path =
          expect(TokenKind::String, "after @primitives (a quoted path)", "write @primitives \"style.prims.obj\"");
      g_.primitives = path.value;
      g_.primitives_loc = path.loc;
    } else {
      error(d.loc, "unknown directive '@" + std::string(d.value) + "'", "directives are @start, @scope and @primitives");
    }
  }

  void constant() {
    const Token& name = next();
    const std::string n(name.text);
    check_free_name(name, "a constant");
    if (constant_ids_.find(n))
      error(name.loc, "the constant '" + n + "' is defined twice", "a constant has one value: rename or delete one of them");
    next();  // '='
    skip_newlines();
    params_ = nullptr;
    param_ids_ = nullptr;
    Expr value = expression();
    // Added once its value is read: a constant uses only those above it.
    constant_ids_.add(n, static_cast<std::uint32_t>(g_.constants.size()));
    g_.constants.push_back({n, std::move(value), name.loc});
  }

  void check_free_name(const Token& name, const std::string& what) const {
    const std::string_view n = name.text;
    if (is_reserved_value_name(n))
      error(name.loc, "'" + std::string(n) + "' cannot name " + what + ": the language uses it", "choose another name");
  }

  void rule() {
    const Token& name = expect(TokenKind::Identifier, "at the start of a rule",
                               "a line is a rule (label --> operation), a constant (name = value) or a directive (@scope ...)");
    const std::string label(name.text);
    if (is_operation_word(label))
      error(name.loc, "'" + label + "' is an operation and cannot be a rule label", "choose another label");
    std::vector<std::string> params;
    NameIndex<std::uint32_t> param_ids;  // params by name: a long list is not read through per name
    if (accept(TokenKind::LParen)) {
      if (!accept(TokenKind::RParen)) {
        do {
          const Token& p = expect(TokenKind::Identifier, "(a parameter name)",
                                  "parameters are names: floors(n, height) --> ...; values go in calls");
          check_free_name(p, "a parameter");
          if (param_ids.find(p.text))
            error(p.loc, "the parameter '" + std::string(p.text) + "' is listed twice",
                  "give each parameter its own name");
          if (params.size() == kMaxParameters)
            error(p.loc, "'" + shown_name(label) + "' has more than " + std::to_string(kMaxParameters) + " parameters",
                  "pass fewer values: a rule can compute the others from them, or read constants");
          param_ids.add(p.text, static_cast<std::uint32_t>(params.size()));
          params.emplace_back(p.text);
        } while (accept(TokenKind::Comma));
        expect(TokenKind::RParen, "to close the parameter list", "write floors(n, height) --> ...");
      }
    }
    const auto declared = labels_.find(label);
    if (declared == labels_.end()) {
      // Pass 1 found no arrow on this line.
      while (peek().kind != TokenKind::Newline && peek().kind != TokenKind::End && peek().kind != TokenKind::Colon &&
             peek().kind != TokenKind::LBrace && peek().kind != TokenKind::Identifier)
        next();
      error(peek().loc, "expected '-->' in the rule for '" + label + "', found " + describe(peek()),
            "a rule reads: label(params) : condition --> operation : priority");
    }
    const RuleId id = declared->second;
    if (declared_params_[id] < 0) {
      declared_params_[id] = static_cast<int>(params.size());
      g_.rules[id].params = params;
      g_.rules[id].loc = name.loc;
    } else if (declared_params_[id] != static_cast<int>(params.size())) {
      error(name.loc,
            "'" + label + "' takes " + std::to_string(declared_params_[id]) + " parameters where it was first defined (" +
                std::to_string(g_.rules[id].loc.line) + ":" + std::to_string(g_.rules[id].loc.column) + "), here " +
                std::to_string(params.size()),
            "all rules of one label take the same parameters");
    }
    params_ = &params;
    param_ids_ = &param_ids;
    ChooseOption alt;
    if (accept(TokenKind::Colon)) alt.condition = expression();
    if (!accept(TokenKind::Arrow)) {
      error(peek().loc, "expected '-->' in the rule for '" + label + "', found " + describe(peek()),
            "a rule reads: label(params) : condition --> operation : priority");
    }
    skip_newlines();
    alt.child = operation();
    const bool priority_written = accept(TokenKind::Colon);
    alt.priority = priority_written ? expression() : Expr::number(1.0);
    params_ = nullptr;
    param_ids_ = nullptr;
    Alternatives& alts = alternatives_[id];
    if (alts.options.empty()) {
      alts.first_priority_written = priority_written;
      alts.first_loc = name.loc;
    }
    alts.options.push_back(std::move(alt));
  }

  void finish_rules() {
    for (RuleId id = 0; id < g_.rules.size(); ++id) {
      Alternatives& alts = alternatives_[id];
      if (alts.options.size() == 1 && alts.options[0].condition.empty() && !alts.first_priority_written) {
        g_.rules[id].body = alts.options[0].child;
        continue;
      }
      g_.rules[id].body = g_.add({Choose{std::move(alts.options)}, alts.first_loc});
    }
    if (g_.rules.empty()) error({1, 1}, "the grammar has no rules", "a rule reads: plot --> split(x){ ~1 : I(rect) }");
    if (!start_label_.empty()) {
      auto it = labels_.find(start_label_);
      if (it == labels_.end())
        error(start_loc_, "@start names '" + shown_name(start_label_) + "', which has no rule",
              suggest(start_label_, rule_names_, "the rules"));
      g_.start_rule = it->second;
      g_.start_written = true;
    }
    // Only a start rule that @start names must take no parameters here: a
    // default start rule may be replaced (generate --start), and derive()
    // refuses one with parameters when it runs.
    const Rule& start = g_.rules[g_.start_rule];
    if (g_.start_written && !start.params.empty())
      error(start_loc_, "the start rule '" + start.label + "' takes parameters",
            "the start rule runs with no arguments: add a rule such as 'plot --> " + start.label + "(...)'");
  }

  // ---- operations ----
  NodeId add(Operation op, SourceLoc loc) { return g_.add({std::move(op), loc}); }

  void open_brace(const std::string& what, const std::string& form) {
    expect(TokenKind::LBrace, "to open the body of " + what, form);
  }

  NodeId child_block(const std::string& what, const std::string& form) {
    open_brace(what, form);
    NodeId child = operation();
    expect(TokenKind::RBrace, "to close the body of " + what, form);
    return child;
  }

  Size size() {
    Size s;
    s.relative = accept(TokenKind::Tilde);
    s.value = expression();
    return s;
  }

  Expr axis_argument(const std::string& what) {
    Expr e = expression();
    if (auto v = e.literal(); v && !Value(*v).to_axis())
      error(e.loc(), "the axis of " + what + " is " + Value(*v).describe(), "an axis is x, y or z (or 0, 1, 2)");
    return e;
  }

  NodeId operation() {
    const Token& t = peek();
    const Nesting nesting(*this, t.loc);
    if (t.kind != TokenKind::Identifier) {
      error(t.loc, "expected an operation, found " + describe(t),
            "operations are split, repeat, repeatN, I(name), nil, T, S, R, comp, colour or a rule label");
    }
    const std::string_view word = t.text;
    const SourceLoc loc = t.loc;
    next();
    if (word == "split") {
      const std::string form = "write split(axis){ size : operation | size : operation }";
      expect(TokenKind::LParen, "after split", form);
      Split s;
      s.axis = axis_argument("split");
      expect(TokenKind::RParen, "after the axis of split", form);
      open_brace("split", form);
      do {
        SplitPart part;
        part.size = size();
        expect(TokenKind::Colon, "between a split size and its operation", form);
        part.child = operation();
        s.parts.push_back(std::move(part));
      } while (accept(TokenKind::Pipe));
      expect(TokenKind::RBrace, "or '|' after a split part", form);
      return add(std::move(s), loc);
    }
    if (word == "repeat") {
      const std::string form = "write repeat(axis, size){ operation }";
      expect(TokenKind::LParen, "after repeat", form);
      Repeat r;
      r.axis = axis_argument("repeat");
      if (accept(TokenKind::Comma)) {
        r.size = expression();
        expect(TokenKind::RParen, "after the tile size of repeat", form);
        r.child = child_block("repeat", form);
      } else {
        expect(TokenKind::RParen, "after the axis of repeat", form);
        open_brace("repeat", form);
        if (accept(TokenKind::Tilde))
          error(peek().loc, "a repeat's tile size is absolute", "write repeat(x, 2){ op } without '~'");
        r.size = expression();
        expect(TokenKind::Colon, "between the tile size and the operation of repeat", form);
        r.child = operation();
        expect(TokenKind::RBrace, "to close the body of repeat", form);
      }
      return add(std::move(r), loc);
    }
    if (word == "repeatN") {
      const std::string form = "write repeatN(axis, count){ operation }";
      expect(TokenKind::LParen, "after repeatN", form);
      RepeatN r;
      r.axis = axis_argument("repeatN");
      expect(TokenKind::Comma, "between the axis and the count of repeatN", form);
      r.count = expression();
      expect(TokenKind::RParen, "after the count of repeatN", form);
      r.child = child_block("repeatN", form);
      return add(std::move(r), loc);
    }
    if (word == "I") {
      expect(TokenKind::LParen, "after I", "write I(name), for example I(rect)");
      const Token& name = next();
      std::string label;
      if (name.kind == TokenKind::Identifier)
        label = std::string(name.text);
      else if (name.kind == TokenKind::String && !name.value.empty())
        label = name.value;  // checked below: a label is what every file can hold (graph/label.hpp)
      else
        error(name.loc, "expected a primitive name in I(...), found " + describe(name), "for example I(rect)");
      require_label(label, source_, name.loc, "the primitive name '" + shown_name(label) + "'");
      expect(TokenKind::RParen, "after the primitive name", "write I(name), for example I(rect)");
      return add(Primitive{g_.label_id(label)}, loc);
    }
    if (word == "nil") return add(Nil{}, loc);
    if (word == "T" || word == "S") {
      const std::string form = word == "T" ? "write T(dx, dy, dz){ operation }" : "write S(sx, sy, sz){ operation }";
      expect(TokenKind::LParen, std::string("after ") + std::string(word), form);
      std::array<Size, 3> sizes;
      for (int i = 0; i < 3; ++i) {
        if (i) expect(TokenKind::Comma, "between the three values of " + std::string(word), form);
        sizes[i] = size();
      }
      expect(TokenKind::RParen, "after the three values of " + std::string(word), form);
      const NodeId child = child_block(std::string(word), form);
      if (word == "T") return add(Translate{sizes, child}, loc);
      return add(Scale{sizes, child}, loc);
    }
    if (word == "R") {
      const std::string form = "write R(axis, angle){ operation }, the angle in radians";
      expect(TokenKind::LParen, "after R", form);
      Rotate r;
      r.axis = axis_argument("R");
      expect(TokenKind::Comma, "between the axis and the angle of R", form);
      r.angle = expression();
      expect(TokenKind::RParen, "after the angle of R", form);
      r.child = child_block("R", form);
      return add(std::move(r), loc);
    }
    if (word == "comp") {
      const std::string form = "write comp(f){ face : operation | face : operation }";
      expect(TokenKind::LParen, "after comp", form);
      const Token& f = expect(TokenKind::Identifier, "in comp(f)", form);
      if (f.text != "f") error(f.loc, "comp splits into faces: write comp(f)", form);
      expect(TokenKind::RParen, "after comp(f", form);
      open_brace("comp", form);
      Comp c;
      do {
        const Token& face =
            expect(TokenKind::Identifier, "(a face: top, bottom, front, back, left or right)", form);
        CompPart part;
        if (!find_face(face.text, part.face))
          error(face.loc, "'" + std::string(face.text) + "' is not a face", "faces are top, bottom, front, back, left, right");
        for (const auto& p : c.parts)
          if (p.face == part.face)
            error(face.loc, "the face '" + std::string(face.text) + "' is listed twice",
                  "give each face one operation (split or call a rule there to do more)");
        expect(TokenKind::Colon, "between a face and its operation", form);
        part.child = operation();
        c.parts.push_back(part);
      } while (accept(TokenKind::Pipe));
      expect(TokenKind::RBrace, "or '|' after a comp part", form);
      return add(std::move(c), loc);
    }
    if (word == "colour" || word == "color") return colour(loc);
    return call(t, loc);
  }

  NodeId colour(SourceLoc loc) {
    const std::string form = "write colour(red), colour(\"#rrggbb\") or colour(r, g, b) with r, g, b from 0 to 1";
    expect(TokenKind::LParen, "after colour", form);
    Colour c;
    const Token& first = peek();
    double rgb[3];
    if (first.kind == TokenKind::Identifier && peek(1).kind == TokenKind::RParen &&
        find_named_colour(first.text, rgb)) {
      next();
      c.rgb = {Expr::number(rgb[0], first.loc), Expr::number(rgb[1], first.loc), Expr::number(rgb[2], first.loc)};
    } else if (first.kind == TokenKind::String) {
      next();
      if (!parse_hex_colour(first.value, rgb))
        error(first.loc, "'" + std::string(first.value) + "' is not a colour",
              "write colour(\"#rrggbb\"), colour(red) or colour(r, g, b)");
      c.rgb = {Expr::number(rgb[0], first.loc), Expr::number(rgb[1], first.loc), Expr::number(rgb[2], first.loc)};
    } else if (first.kind == TokenKind::Identifier && peek(1).kind == TokenKind::RParen && !is_value_name(first.text)) {
      std::vector<std::string> names;
      for (const auto& n : kColours) names.emplace_back(n.name);
      error(first.loc, "unknown colour '" + shown_name(first.text) + "'", suggest(first.text, names, "the colours"));
    } else {
      c.rgb[0] = expression();
      expect(TokenKind::Comma, "between colour components (r, g, b from 0 to 1)", form);
      c.rgb[1] = expression();
      expect(TokenKind::Comma, "between colour components (r, g, b from 0 to 1)", form);
      c.rgb[2] = expression();
    }
    expect(TokenKind::RParen, "after the colour", form);
    return add(std::move(c), loc);
  }

  static bool parse_hex_colour(std::string_view s, double rgb[3]) {
    if (s.size() != 7 || s[0] != '#') return false;
    for (int i = 0; i < 3; ++i) {
      unsigned v = 0;
      for (int k = 0; k < 2; ++k) {
        const char c = s[1 + 2 * i + k];
        unsigned d;
        if (c >= '0' && c <= '9') d = unsigned(c - '0');
        else if (c >= 'a' && c <= 'f') d = unsigned(c - 'a' + 10);
        else if (c >= 'A' && c <= 'F') d = unsigned(c - 'A' + 10);
        else return false;
        v = v * 16 + d;
      }
      rgb[i] = v / 255.0;
    }
    return true;
  }

  bool is_value_name(std::string_view n) const {
    if (param_ids_ && param_ids_->find(n)) return true;
    return constant_ids_.find(n).has_value();
  }

  NodeId call(const Token& name, SourceLoc loc) {
    const std::string label(name.text);
    auto it = labels_.find(label);
    if (it == labels_.end()) {
      error(name.loc, "unknown rule '" + shown_name(label) + "'", suggest(label, rule_names_, "the rules"));
    }
    Call c;
    c.rule = it->second;
    if (accept(TokenKind::LParen)) {
      if (!accept(TokenKind::RParen)) {
        do c.args.push_back(expression());
        while (accept(TokenKind::Comma));
        expect(TokenKind::RParen, "to close the arguments of '" + label + "'",
               "write " + label + "(a, b), the arguments separated by commas");
      }
    }
    pending_calls_.push_back({c.rule, c.args.size(), name.loc});
    check_call(pending_calls_.back());
    return add(std::move(c), loc);
  }

  struct PendingCall {
    RuleId rule;
    std::size_t args;
    SourceLoc loc;
  };

  // The callee's parameter count is known once its first rule line has been
  // read; calls read before that are checked when the file is done.
  void check_call(const PendingCall& c) const {
    const int expected = declared_params_[c.rule];
    if (expected < 0 || static_cast<std::size_t>(expected) == c.args) return;
    const Rule& r = g_.rules[c.rule];
    std::string sig = r.label;
    if (!r.params.empty()) {
      sig += "(";
      for (std::size_t i = 0; i < r.params.size(); ++i) sig += (i ? ", " : "") + r.params[i];
      sig += ")";
    }
    error(c.loc,
          "'" + r.label + "' takes " + std::to_string(expected) + " argument" + (expected == 1 ? "" : "s") + ", given " +
              std::to_string(c.args),
          "it is defined at " + std::to_string(r.loc.line) + ":" + std::to_string(r.loc.column) + " as " + sig);
  }

  // ---- expressions ----
  Expr expression() {
    Expr e = binary_level(0);
    check_depth(e);
    return e;
  }

  struct Level {
    TokenKind token;
    BinaryOp op;
  };
  // Binary operator levels, loosest first.
  static const std::vector<std::vector<Level>>& levels() {
    static const std::vector<std::vector<Level>> table{
        {{TokenKind::OrOr, BinaryOp::Or}},
        {{TokenKind::AndAnd, BinaryOp::And}},
        {{TokenKind::Equal, BinaryOp::Eq}, {TokenKind::NotEqual, BinaryOp::Ne}},
        {{TokenKind::Less, BinaryOp::Lt},
         {TokenKind::LessEqual, BinaryOp::Le},
         {TokenKind::Greater, BinaryOp::Gt},
         {TokenKind::GreaterEqual, BinaryOp::Ge}},
        {{TokenKind::Plus, BinaryOp::Add}, {TokenKind::Minus, BinaryOp::Sub}},
        {{TokenKind::Star, BinaryOp::Mul}, {TokenKind::Slash, BinaryOp::Div}, {TokenKind::Percent, BinaryOp::Mod}},
    };
    return table;
  }

  Expr binary_level(std::size_t level) {
    if (level == levels().size()) return unary();
    Expr lhs = binary_level(level + 1);
    while (true) {
      const Token& t = peek();
      const Level* match = nullptr;
      for (const auto& l : levels()[level])
        if (l.token == t.kind) match = &l;
      if (!match) return lhs;
      next();
      Expr rhs = binary_level(level + 1);
      check_operand(lhs, *match);
      check_operand(rhs, *match);
      lhs = Expr::binary(match->op, std::move(lhs), std::move(rhs), t.loc);
    }
  }

  // Axes take part only in == and !=; an axis literal anywhere else is a type
  // error that can be reported now rather than at every derivation.
  void check_operand(const Expr& e, const Level& l) const {
    if (l.op == BinaryOp::Eq || l.op == BinaryOp::Ne) return;
    if (e.node(e.root()).kind == ExprKind::Axis)
      error(e.loc(), std::string("'") + operator_text(l.op) + "' expects numbers, found the axis " +
                         axis_name(static_cast<Axis>(e.node(e.root()).op)),
            "axes can only be compared with == and !=");
  }

  Expr unary() {
    const Token& t = peek();
    const Nesting nesting(*this, t.loc);
    if (t.kind == TokenKind::Minus || t.kind == TokenKind::Bang) {
      next();
      Expr operand = unary();
      if (operand.node(operand.root()).kind == ExprKind::Axis)
        error(operand.loc(), std::string("'") + std::string(t.text) + "' expects a number, found an axis",
              "axes can only be compared with == and !=");
      return Expr::unary(t.kind == TokenKind::Minus ? UnaryOp::Neg : UnaryOp::Not, std::move(operand), t.loc);
    }
    if (t.kind == TokenKind::Tilde)
      error(t.loc, "'~' marks a relative size and must come first", "write ~(a + b) : op, not a + ~b");
    return primary();
  }

  Expr primary() {
    const Token& t = next();
    if (t.kind == TokenKind::Number) return Expr::number(t.number, t.loc);
    if (t.kind == TokenKind::LParen) {
      Expr e = expression();
      expect(TokenKind::RParen, "to close '(' at " + std::to_string(t.loc.line) + ":" + std::to_string(t.loc.column),
             "add the missing ')' (or remove the extra '(')");
      return e;
    }
    if (t.kind != TokenKind::Identifier) {
      error(t.loc, "expected a value, found " + describe(t), "values are numbers, names, x y z, pi, or function calls");
    }
    const std::string_view n = t.text;
    if (peek().kind == TokenKind::LParen) {
      auto f = find_function(n);
      if (!f) {
        std::vector<std::string> names;
        for (const auto& info : function_table()) names.emplace_back(info.name);
        error(t.loc, "unknown function '" + shown_name(n) + "'", suggest(n, names, "the functions"));
      }
      next();
      std::vector<Expr> args;
      if (!accept(TokenKind::RParen)) {
        do args.push_back(expression());
        while (accept(TokenKind::Comma));
        expect(TokenKind::RParen, "to close the arguments of " + std::string(n), "write " + call_form(*f));
      }
      check_arity(*f, args.size(), t);
      if (*f == Function::Size && !params_)
        error(t.loc, "size() reads the size of the scope a rule's operation stands in, and here there is none",
              "constants and @scope are evaluated before any scope: use size() in a rule");
      if (args.size() > kMaxArguments)
        error(t.loc, std::string(n) + " is given " + std::to_string(args.size()) + " arguments, more than " +
                         std::to_string(kMaxArguments),
              "split the list: choice(choice(a, b), choice(c, d)) draws as evenly when the halves are equal");
      for (const auto& a : args)
        if (*f != Function::Size && a.node(a.root()).kind == ExprKind::Axis)
          error(a.loc(), std::string(n) + " expects numbers, found an axis", "axes can only be compared with == and !=");
      return Expr::call(*f, std::move(args), t.loc);
    }
    if (param_ids_)
      if (auto i = param_ids_->find(n)) return Expr::param(*i, t.loc);
    if (auto c = constant_ids_.find(n)) return Expr::constant(*c, t.loc);
    if (n == "x") return Expr::axis(Axis::X, t.loc);
    if (n == "y") return Expr::axis(Axis::Y, t.loc);
    if (n == "z") return Expr::axis(Axis::Z, t.loc);
    if (n == "pi") return Expr::number(std::numbers::pi, t.loc);
    if (n == "rand") return Expr::call(Function::Rand, {}, t.loc);
    if (auto f = find_function(n))
      error(t.loc, "the function '" + std::string(n) + "' needs its arguments", "write " + call_form(*f));
    if (names_no_number(n))
      error(t.loc, "'" + std::string(n) + "' is not a number here: a grammar's numbers are finite",
            "write a finite number, such as 1e30 for a size larger than any building");
    std::vector<std::string> known;
    if (params_) known = *params_;
    for (const auto& c : g_.constants) known.push_back(c.name);
    std::string hint = known.empty() ? "no constants or parameters are defined here: define it above as '" +
                                           shown_name(n) + " = value', or make it a parameter of the rule"
                                     : suggest(n, known, "the names in scope here");
    if (labels_.count(std::string(n))) hint += " ('" + shown_name(n) + "' is a rule, not a value)";
    if (!params_) hint += "; a constant can use only the constants defined above it";
    error(t.loc, "unknown name '" + shown_name(n) + "'", hint);
  }

  // inf, nan, Infinity: what other languages (and from_chars) read as a
  // number that is not finite, which a size, count or angle cannot be.
  static bool names_no_number(std::string_view n) {
    std::string lower(n);
    for (char& c : lower) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return lower == "inf" || lower == "infinity" || lower == "nan";
  }

  void check_arity(Function f, std::size_t n, const Token& t) const {
    const FunctionInfo& info = function_info(f);
    bool ok = static_cast<int>(n) >= info.min_args && (info.max_args < 0 || static_cast<int>(n) <= info.max_args);
    if (f == Function::Rand) ok = n == 0 || n == 2;
    if (ok) return;
    std::string expected;
    if (f == Function::Rand) expected = "0 or 2 arguments";
    else if (info.max_args < 0) expected = "at least " + std::to_string(info.min_args) + " argument" + (info.min_args == 1 ? "" : "s");
    else expected = std::to_string(info.min_args) + " argument" + (info.min_args == 1 ? "" : "s");
    error(t.loc, std::string(info.name) + " takes " + expected + ", given " + std::to_string(n), "write " + call_form(f));
  }

  // How a function is called, for hints: "min(a, ...)", "rand() or rand(a, b)".
  static std::string call_form(Function f) {
    const FunctionInfo& info = function_info(f);
    const std::string name(info.name);
    if (f == Function::Rand) return "rand() or rand(a, b)";
    if (f == Function::Size) return "size(x), size(y) or size(z)";
    std::string args;
    for (int i = 0; i < info.min_args; ++i) args += std::string(i ? ", " : "") + static_cast<char>('a' + i);
    if (info.max_args < 0) args += ", ...";
    return name + "(" + args + ")";
  }

  const std::string& source_;
  std::string_view text_;
  Lexer lexer_;
  // The tokens read from the text and not yet passed, a ring: token number
  // first_ + k is ahead_[(head_ + k) % 4], for k below count_. (A deque
  // made and freed a block every few tokens.)
  std::array<Token, 4> ahead_;
  std::size_t head_ = 0, count_ = 0, first_ = 0;
  std::size_t pos_ = 0;
  Grammar g_;
  std::map<std::string, RuleId> labels_;
  NameIndex<std::uint32_t> constant_ids_;  // g_.constants by name
  std::vector<std::string> rule_names_;
  std::vector<int> declared_params_;
  std::vector<Alternatives> alternatives_;
  std::vector<PendingCall> pending_calls_;
  const std::vector<std::string>* params_ = nullptr;     // of the rule being read
  const NameIndex<std::uint32_t>* param_ids_ = nullptr;  // the same by name
  std::string start_label_;
  SourceLoc start_loc_;
  int nesting_ = 0;
  const StackGuard& stack_ = StackGuard::for_this_thread();

};

}  // namespace

bool find_named_colour(std::string_view name, double rgb[3]) {
  for (const auto& c : kColours) {
    if (c.name == name) {
      rgb[0] = c.r, rgb[1] = c.g, rgb[2] = c.b;
      return true;
    }
  }
  return false;
}

Grammar parse_grammar(std::string_view text, const std::string& source_name) {
  return Parser(text, source_name).run();
}

namespace {

// The file's text in a string of its size: one copy of it, where a stream
// buffer copied out whole held two.
std::string whole_text(std::ifstream& in, const std::filesystem::path& path) {
  std::string text;
  std::error_code ec;
  if (const auto size = std::filesystem::file_size(path, ec); !ec) text.reserve(size);
  char block[1 << 16];
  while (in.read(block, sizeof block) || in.gcount() > 0) text.append(block, static_cast<std::size_t>(in.gcount()));
  if (in.bad()) fail(ErrorKind::Io, path.string(), {}, "cannot read the grammar file", "check the file and its disk");
  return text;
}

}  // namespace

Grammar read_grammar_file(const std::filesystem::path& path) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec))
    fail(ErrorKind::Io, path.string(), {}, "is a folder, not a grammar file", "name a .grm file");
  require_regular_file(path);
  std::ifstream in(path, std::ios::binary);
  if (!in) fail(ErrorKind::Io, path.string(), {}, "cannot open the grammar file", "check the path");
  const std::string name = path.string();
  return naming_out_of_memory(name, "while reading this grammar",
                              "read a smaller grammar (fewer rule lines), or free memory for the run",
                              [&] { return parse_grammar(whole_text(in, path), name); });
}

}  // namespace vern
