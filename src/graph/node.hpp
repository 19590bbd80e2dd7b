// The operation nodes of the operation graph (thesis chapter 5).
//
// A node is one operation; its children are NodeIds into the owning
// Grammar's arena. Calls name rules by index, never nodes, so the node arena
// is a DAG even when the grammar recurses, and hash-consing is bottom-up.
// Every kind is a plain struct; a Node is a variant of them plus the place
// in the source it came from (which takes no part in equality or hashing).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <string_view>
#include <utility>
#include <variant>
#include <vector>

#include "base/triple.hpp"
#include "graph/expr.hpp"

namespace vern {

using NodeId = std::uint32_t;
using RuleId = std::uint32_t;
using LabelId = std::uint32_t;  // a primitive's name, interned in the Grammar

// `~e` (relative: a share of what the absolute sizes leave) or `e` (metres).
// In T and S a relative size is a multiple of the scope's current size.
struct Size {
  Expr value;
  bool relative = false;
  friend bool operator==(const Size&, const Size&) = default;
};

struct SplitPart {
  Size size;
  NodeId child = 0;
  friend bool operator==(const SplitPart&, const SplitPart&) = default;
};

// split(axis){ s1 : op1 | s2 : op2 | ... }
struct Split {
  Expr axis;
  std::vector<SplitPart> parts;
  friend bool operator==(const Split&, const Split&) = default;
};

// repeat(axis, size){ op }: max(1, ceil(L / size)) equal tiles.
struct Repeat {
  Expr axis;
  Expr size;
  NodeId child = 0;
  friend bool operator==(const Repeat&, const Repeat&) = default;
};

// How many tiles repeat makes on a length: ceil, forgiving float noise
// (0.7 / 0.1 is 7.000000000000001 and means 7). derive(), check and
// inference must agree on it to the last bit. A tile so small that the
// quotient overflows (1e-320) makes infinitely many, which every limit
// refuses: not the 1 that ceil(inf - inf), NaN, would leave below.
inline double repeat_tile_count(double length, double tile) {
  const double q = length / tile;
  if (std::isinf(q)) return q;
  return std::max(1.0, std::ceil(q - 1e-9 * std::max(1.0, q)));
}

// repeatN(axis, n){ op }: round(n) equal tiles, none if n <= 0.
struct RepeatN {
  Expr axis;
  Expr count;
  NodeId child = 0;
  friend bool operator==(const RepeatN&, const RepeatN&) = default;
};

// One alternative of a choose: taken with probability proportional to its
// priority among those whose condition holds. An empty condition holds.
struct ChooseOption {
  Expr condition;
  Expr priority;
  NodeId child = 0;
  friend bool operator==(const ChooseOption&, const ChooseOption&) = default;
};

// The alternatives of a rule label (or, from inference, of the examples).
struct Choose {
  std::vector<ChooseOption> options;
  friend bool operator==(const Choose&, const Choose&) = default;
};

// label(args): run a rule with these argument values.
struct Call {
  RuleId rule = 0;
  std::vector<Expr> args;
  friend bool operator==(const Call&, const Call&) = default;
};

// I(name): a terminal.
struct Primitive {
  LabelId label = 0;
  friend bool operator==(const Primitive&, const Primitive&) = default;
};

struct Nil {
  friend bool operator==(const Nil&, const Nil&) = default;
};

// T(dx, dy, dz){ op }: move along the scope's own axes.
struct Translate {
  Triple<Size> offset;
  NodeId child = 0;
  friend bool operator==(const Translate&, const Translate&) = default;
};

// S(sx, sy, sz){ op }: resize, origin kept.
struct Scale {
  Triple<Size> size;
  NodeId child = 0;
  friend bool operator==(const Scale&, const Scale&) = default;
};

// R(axis, angle){ op }: turn about the scope's centre (radians).
struct Rotate {
  Expr axis;
  Expr angle;
  NodeId child = 0;
  friend bool operator==(const Rotate&, const Rotate&) = default;
};

enum class Face : std::uint8_t { Top, Bottom, Front, Back, Left, Right };
const char* face_name(Face f);
bool find_face(std::string_view name, Face& out);

struct CompPart {
  Face face = Face::Top;
  NodeId child = 0;
  friend bool operator==(const CompPart&, const CompPart&) = default;
};

// comp(f){ face : op | ... }: faces as zero-thickness scopes.
struct Comp {
  std::vector<CompPart> parts;
  friend bool operator==(const Comp&, const Comp&) = default;
};

// colour(r, g, b): a `rect` terminal with that colour (components in 0..1).
struct Colour {
  Triple<Expr> rgb;  // red, green, blue
  friend bool operator==(const Colour&, const Colour&) = default;
};

using Operation = std::variant<Split, Repeat, RepeatN, Choose, Call, Primitive, Nil, Translate, Scale, Rotate,
                               Comp, Colour>;

// The operation's name as the grammar spells it ("split", "repeatN", ...).
const char* operation_name(const Operation& op);

struct Node {
  Operation op;
  SourceLoc loc;
};

// Calls f(child) for each of the node's children in order, allocating
// nothing: for traversals that visit every node of a large graph.
template <class F>
void for_each_child(const Operation& op, F f) {
  if (const auto* s = std::get_if<Split>(&op)) {
    for (const auto& p : s->parts) f(p.child);
  } else if (const auto* c = std::get_if<Choose>(&op)) {
    for (const auto& o : c->options) f(o.child);
  } else if (const auto* r = std::get_if<Repeat>(&op)) {
    f(r->child);
  } else if (const auto* n = std::get_if<RepeatN>(&op)) {
    f(n->child);
  } else if (const auto* t = std::get_if<Translate>(&op)) {
    f(t->child);
  } else if (const auto* z = std::get_if<Scale>(&op)) {
    f(z->child);
  } else if (const auto* o = std::get_if<Rotate>(&op)) {
    f(o->child);
  } else if (const auto* m = std::get_if<Comp>(&op)) {
    for (const auto& p : m->parts) f(p.child);
  }
}

// The node's children in order (split parts, choose options, ...).
std::vector<NodeId> node_children(const Operation& op);

// The same children as places to rewrite them, in the same order.
std::vector<NodeId*> child_slots(Operation& op);

// The children mapped through f, and whether any changed. The ids are read
// before f runs, so f may add nodes to the grammar op lives in (which can
// move its arena): op is not touched after the first call.
template <class F>
std::pair<std::vector<NodeId>, bool> map_children(const Operation& op, F f) {
  std::vector<NodeId> children = node_children(op);
  bool changed = false;
  for (NodeId& c : children) {
    const NodeId mapped = f(c);
    changed = changed || mapped != c;
    c = mapped;
  }
  return {std::move(children), changed};
}

// The node's own expressions in order (axes, sizes, conditions,
// priorities, arguments, ...); empty ones (an absent condition) included.
std::vector<const Expr*> node_expressions(const Operation& op);

// The same expressions as places to rewrite them, in the same order.
std::vector<Expr*> expression_slots(Operation& op);

}  // namespace vern
