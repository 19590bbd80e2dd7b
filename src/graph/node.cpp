#include "graph/node.hpp"

#include <array>

#include "graph/overload.hpp"

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
  std::vector<NodeId> out;
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

std::vector<const Expr*> node_expressions(const Operation& op) {
  std::vector<const Expr*> out;
  std::visit(Overload{
                 [&](const Split& s) {
                   out.push_back(&s.axis);
                   for (const auto& p : s.parts) out.push_back(&p.size.value);
                 },
                 [&](const Repeat& r) { out.insert(out.end(), {&r.axis, &r.size}); },
                 [&](const RepeatN& r) { out.insert(out.end(), {&r.axis, &r.count}); },
                 [&](const Choose& c) {
                   for (const auto& o : c.options) out.insert(out.end(), {&o.condition, &o.priority});
                 },
                 [&](const Call& c) {
                   for (const auto& a : c.args) out.push_back(&a);
                 },
                 [&](const Translate& t) {
                   for (const auto& s : t.offset) out.push_back(&s.value);
                 },
                 [&](const Scale& s) {
                   for (const auto& z : s.size) out.push_back(&z.value);
                 },
                 [&](const Rotate& r) { out.insert(out.end(), {&r.axis, &r.angle}); },
                 [&](const Colour& c) { out.insert(out.end(), {&c.rgb[0], &c.rgb[1], &c.rgb[2]}); },
                 [](const auto&) {},
             },
             op);
  return out;
}

}  // namespace vern
