#include "graph/node.hpp"

#include <array>
#include <type_traits>

#include "base/overload.hpp"

namespace vern {

namespace {
constexpr std::array<const char*, 6> kFaceNames{"top", "bottom", "front", "back", "left", "right"};
}  // namespace

const char* face_name(Face f) { return kFaceNames[static_cast<std::size_t>(f)]; }

bool find_face(std::string_view name, Face& out) {
  for (std::size_t i = 0; i < kFaceNames.size(); ++i) {
    if (name == kFaceNames[i]) {
      out = static_cast<Face>(i);
      return true;
    }
  }
  return false;
}

const char* operation_name(const Operation& op) {
  return std::visit(Overload{
                        [](const Split&) { return "split"; },
                        [](const Repeat&) { return "repeat"; },
                        [](const RepeatN&) { return "repeatN"; },
                        [](const Choose&) { return "choose"; },
                        [](const Call&) { return "call"; },
                        [](const Primitive&) { return "I"; },
                        [](const Nil&) { return "nil"; },
                        [](const Translate&) { return "T"; },
                        [](const Scale&) { return "S"; },
                        [](const Rotate&) { return "R"; },
                        [](const Comp&) { return "comp"; },
                        [](const Colour&) { return "colour"; },
                    },
                    op);
}

std::vector<NodeId> node_children(const Operation& op) {
  std::size_t count = 0;
  for_each_child(op, [&](NodeId) { ++count; });
  std::vector<NodeId> out;
  out.reserve(count);  // one allocation, not one per doubling (long splits)
  for_each_child(op, [&](NodeId c) { out.push_back(c); });
  return out;
}

std::vector<NodeId*> child_slots(Operation& op) {
  std::vector<NodeId*> out;
  std::visit(Overload{
                 [&](Split& s) {
                   for (auto& p : s.parts) out.push_back(&p.child);
                 },
                 [&](Repeat& r) { out.push_back(&r.child); },
                 [&](RepeatN& r) { out.push_back(&r.child); },
                 [&](Choose& c) {
                   for (auto& o : c.options) out.push_back(&o.child);
                 },
                 [&](Translate& t) { out.push_back(&t.child); },
                 [&](Scale& s) { out.push_back(&s.child); },
                 [&](Rotate& r) { out.push_back(&r.child); },
                 [&](Comp& c) {
                   for (auto& p : c.parts) out.push_back(&p.child);
                 },
                 [](auto&) {},
             },
             op);
  return out;
}

namespace {

// Both spellings of "the node's expressions" (to read, to rewrite): Op is
// Operation or const Operation, Out a vector of pointers to match.
template <class Op, class Out>
void collect_expressions(Op& op, Out& out) {
  std::visit(
      [&](auto& o) {
        using T = std::remove_cvref_t<decltype(o)>;
        if constexpr (std::is_same_v<T, Split>) {
          out.push_back(&o.axis);
          for (auto& p : o.parts) out.push_back(&p.size.value);
        } else if constexpr (std::is_same_v<T, Repeat>) {
          out.insert(out.end(), {&o.axis, &o.size});
        } else if constexpr (std::is_same_v<T, RepeatN>) {
          out.insert(out.end(), {&o.axis, &o.count});
        } else if constexpr (std::is_same_v<T, Choose>) {
          for (auto& c : o.options) out.insert(out.end(), {&c.condition, &c.priority});
        } else if constexpr (std::is_same_v<T, Call>) {
          for (auto& a : o.args) out.push_back(&a);
        } else if constexpr (std::is_same_v<T, Translate>) {
          for (auto& s : o.offset) out.push_back(&s.value);
        } else if constexpr (std::is_same_v<T, Scale>) {
          for (auto& s : o.size) out.push_back(&s.value);
        } else if constexpr (std::is_same_v<T, Rotate>) {
          out.insert(out.end(), {&o.axis, &o.angle});
        } else if constexpr (std::is_same_v<T, Colour>) {
          out.insert(out.end(), {&o.rgb[0], &o.rgb[1], &o.rgb[2]});
        }
      },
      op);
}

}  // namespace

std::vector<const Expr*> node_expressions(const Operation& op) {
  std::vector<const Expr*> out;
  collect_expressions(op, out);
  return out;
}

std::vector<Expr*> expression_slots(Operation& op) {
  std::vector<Expr*> out;
  collect_expressions(op, out);
  return out;
}

}  // namespace vern
