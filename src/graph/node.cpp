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
  std::visit(Overload{
                 [&](const Split& s) {
                   for (const auto& p : s.parts) out.push_back(p.child);
                 },
                 [&](const Repeat& r) { out.push_back(r.child); },
                 [&](const RepeatN& r) { out.push_back(r.child); },
                 [&](const Choose& c) {
                   for (const auto& o : c.options) out.push_back(o.child);
                 },
                 [&](const Translate& t) { out.push_back(t.child); },
                 [&](const Scale& s) { out.push_back(s.child); },
                 [&](const Rotate& r) { out.push_back(r.child); },
                 [&](const Comp& c) {
                   for (const auto& p : c.parts) out.push_back(p.child);
                 },
                 [](const auto&) {},
             },
             op);
  return out;
}

}  // namespace vern
