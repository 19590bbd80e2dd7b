#include "inverse/split_graph.hpp"

#include <algorithm>
#include <optional>
#include <unordered_map>

#include "graph/error.hpp"

namespace vern {

namespace {

class GraphBuilder {
 public:
  GraphBuilder(Grammar& grammar, const std::vector<LabelledBox>& boxes, const std::string& source,
               const std::vector<Orientation>& turns)
      : g_(grammar), boxes_(boxes), source_(source), turns_(turns) {}

  NodeId node(const SplitTree& t) {
    switch (t.kind) {
      case SplitTree::Kind::Leaf: return leaf(t.box);
      case SplitTree::Kind::Empty: return nil();
      case SplitTree::Kind::Unsplittable: unsplittable(t);
      case SplitTree::Kind::Split: break;
    }
    // A split of one part is that part (toOp: "if there is only one child").
    if (t.children.size() == 1) return node(t.children.front());
    Split split;
    split.axis = Expr::axis(static_cast<Axis>(t.axis));
    split.parts.reserve(t.children.size());
    for (const SplitTree& c : t.children) {
      const double length = c.max[t.axis] - c.min[t.axis];
      split.parts.push_back({Size{Expr::number(length), true}, node(c)});
    }
    return g_.intern(Node{std::move(split), {}});
  }

 private:
  // Every leaf of one label is one node: looked up once per label, not
  // once per part (a city has a million parts and a dozen labels).
  NodeId leaf(std::uint32_t box) {
    if (box >= boxes_.size()) {
      throw Error(ErrorKind::Internal, format_message(source_, {}, "a split tree names a box that does not exist (a bug)"));
    }
    const std::string& label = boxes_[box].label;
    if (box < turns_.size() && !turns_[box].empty()) return turned_primitive(g_, g_.label_id(label), turns_[box]);
    auto [it, fresh] = leaves_.try_emplace(label, 0);
    if (fresh) it->second = g_.intern(Node{Primitive{g_.label_id(label)}, {}});
    return it->second;
  }

  NodeId nil() {
    if (!nil_) nil_ = g_.intern(Node{Nil{}, {}});
    return *nil_;
  }

  // Straight cuts cannot represent the group. T/S placements could, later;
  // until then the user learns which parts to change.
  [[noreturn]] void unsplittable(const SplitTree& t) const {
    std::string names;
    const std::size_t shown = std::min<std::size_t>(t.children.size(), 8);
    for (std::size_t i = 0; i < shown; ++i) {
      names += (i == 0 ? "" : ", ") + describe_object(boxes_.at(t.children[i].box));
    }
    if (shown < t.children.size()) names += " and " + std::to_string(t.children.size() - shown) + " more";
    const LabelledBox& first = boxes_.at(t.children.front().box);
    const SourceLoc loc{first.line, first.line != 0 ? 1u : 0u};
    if (t.children.size() == 1) {
      fail(ErrorKind::Input, source_, loc,
           "part " + names + " is flat and lies inside a thicker empty space: no straight cut can separate it, "
           "because a cut never makes a part of zero thickness",
           "give the part some thickness, or make it flush with the building's outer bounds");
    }
    fail(ErrorKind::Input, source_, loc,
         "these " + std::to_string(t.children.size()) +
             " parts cannot be separated by straight cuts (e.g. a pinwheel): " + names,
         "inference cuts buildings with planes through whole groups of parts; split one of these parts in two "
         "so that a cut can pass between them");
  }

  Grammar& g_;
  const std::vector<LabelledBox>& boxes_;
  const std::string& source_;
  const std::vector<Orientation>& turns_;  // per box; empty: none turned
  std::unordered_map<std::string, NodeId> leaves_;  // label -> its primitive node
  std::optional<NodeId> nil_;
};

}  // namespace

NodeId split_graph(Grammar& grammar, const SplitTree& tree, const std::vector<LabelledBox>& boxes,
                   const std::string& source, const std::vector<Orientation>& turns) {
  return GraphBuilder(grammar, boxes, source, turns).node(tree);
}

NodeId example_graph(Grammar& grammar, const Example& example, const BoxSplitOptions& options,
                     const std::vector<Orientation>& turns) {
  const SplitTree tree = split_boxes(example.boxes, options, example.source);
  return split_graph(grammar, tree, example.boxes, example.source, turns);
}

}  // namespace vern
