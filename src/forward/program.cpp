#include "forward/program.hpp"

#include "base/overload.hpp"

namespace vern {

namespace {

OpKind kind_of(const Operation& op) {
  return std::visit(Overload{
                        [](const Split&) { return OpKind::Split; },
                        [](const Repeat&) { return OpKind::Repeat; },
                        [](const RepeatN&) { return OpKind::RepeatN; },
                        [](const Choose&) { return OpKind::Choose; },
                        [](const Call&) { return OpKind::Call; },
                        [](const Primitive&) { return OpKind::Primitive; },
                        [](const Nil&) { return OpKind::Nil; },
                        [](const Translate&) { return OpKind::Translate; },
                        [](const Scale&) { return OpKind::Scale; },
                        [](const Rotate&) { return OpKind::Rotate; },
                        [](const Comp&) { return OpKind::Comp; },
                        [](const Colour&) { return OpKind::Colour; },
                    },
                    op);
}

std::uint32_t size32(std::size_t n) { return static_cast<std::uint32_t>(n); }

}  // namespace

Program compile(const Grammar& g) {
  Program p;
  p.grammar = &g;
  const std::size_t n = g.node_count();
  // First every node's kind and table slot, so parents can refer to
  // children (and calls to rule bodies) that come later in the arena.
  p.nodes.resize(n);
  std::array<std::uint32_t, 12> used{};
  std::size_t parts = 0, options = 0, args = 0, faces = 0;
  for (NodeId id = 0; id < n; ++id) {
    const Operation& op = g.op(id);
    Target& t = p.nodes[id];
    t.kind = kind_of(op);
    t.node = id;
    if (const auto* prim = std::get_if<Primitive>(&op)) {
      t.index = prim->label;
      continue;
    }
    // repeat and repeatN share a table, as do T and S.
    OpKind table = t.kind == OpKind::RepeatN ? OpKind::Repeat : t.kind == OpKind::Scale ? OpKind::Translate : t.kind;
    t.index = used[static_cast<std::size_t>(table)]++;
    if (const auto* s = std::get_if<Split>(&op)) parts += s->parts.size();
    if (const auto* c = std::get_if<Choose>(&op)) options += c->options.size();
    if (const auto* c = std::get_if<Call>(&op)) args += c->args.size();
    if (const auto* c = std::get_if<Comp>(&op)) faces += c->parts.size();
  }
  // Every table at its final size at once: grown by doubling, each held
  // up to twice its size, and half as much again while it moved (a grammar
  // of 200,000 alternatives has as many options).
  const auto count = [&](OpKind k) { return used[static_cast<std::size_t>(k)]; };
  p.splits.reserve(count(OpKind::Split));
  p.parts.reserve(parts);
  p.repeats.reserve(count(OpKind::Repeat));
  p.chooses.reserve(count(OpKind::Choose));
  p.options.reserve(options);
  p.calls.reserve(count(OpKind::Call));
  p.args.reserve(args);
  p.transforms.reserve(count(OpKind::Translate));
  p.rotates.reserve(count(OpKind::Rotate));
  p.comps.reserve(count(OpKind::Comp));
  p.faces.reserve(faces);
  p.colours.reserve(count(OpKind::Colour));
  for (NodeId id = 0; id < n; ++id) {
    std::visit(Overload{
                   [&](const Split& op) {
                     SplitOp s{ExprCode::axis(op.axis), size32(p.parts.size()), size32(op.parts.size())};
                     s.literal = true;
                     for (const SplitPart& part : op.parts) {
                       const CompiledExpr size = p.code.number(part.size.value);
                       if (size.form == ExprForm::Literal && size.literal >= 0)
                         (part.size.relative ? s.relative : s.absolute) += size.literal;
                       else
                         s.literal = false;
                       p.parts.push_back({size, part.size.relative, p.nodes[part.child]});
                     }
                     if (!s.literal) s.absolute = s.relative = 0.0;
                     p.splits.push_back(s);
                   },
                   [&](const Repeat& op) {
                     p.repeats.push_back({ExprCode::axis(op.axis), p.code.number(op.size), p.nodes[op.child]});
                   },
                   [&](const RepeatN& op) {
                     p.repeats.push_back({ExprCode::axis(op.axis), p.code.number(op.count), p.nodes[op.child]});
                   },
                   [&](const Choose& op) {
                     p.chooses.push_back({size32(p.options.size()), size32(op.options.size())});
                     for (const ChooseOption& o : op.options)
                       p.options.push_back({p.code.number(o.condition), p.code.number(o.priority), p.nodes[o.child]});
                   },
                   [&](const Call& op) {
                     p.calls.push_back({op.rule, p.nodes[g.rules[op.rule].body], size32(p.args.size()), size32(op.args.size())});
                     for (const Expr& a : op.args) p.args.push_back(p.code.value(a));
                   },
                   [&](const Primitive&) {},
                   [&](const Nil&) {},
                   [&](const Translate& op) {
                     TransformOp t;
                     for (int i = 0; i < 3; ++i) {
                       t.amount[i] = p.code.number(op.offset[i].value);
                       t.relative[i] = op.offset[i].relative;
                     }
                     t.child = p.nodes[op.child];
                     p.transforms.push_back(t);
                   },
                   [&](const Scale& op) {
                     TransformOp t;
                     for (int i = 0; i < 3; ++i) {
                       t.amount[i] = p.code.number(op.size[i].value);
                       t.relative[i] = op.size[i].relative;
                     }
                     t.child = p.nodes[op.child];
                     p.transforms.push_back(t);
                   },
                   [&](const Rotate& op) {
                     p.rotates.push_back({ExprCode::axis(op.axis), p.code.number(op.angle), p.nodes[op.child]});
                   },
                   [&](const Comp& op) {
                     p.comps.push_back({size32(p.faces.size()), size32(op.parts.size())});
                     for (const CompPart& part : op.parts) p.faces.push_back({part.face, p.nodes[part.child]});
                   },
                   [&](const Colour& op) {
                     p.colours.push_back({{p.code.number(op.rgb[0]), p.code.number(op.rgb[1]), p.code.number(op.rgb[2])}});
                   },
               },
               g.op(id));
  }
  return p;
}

}  // namespace vern
