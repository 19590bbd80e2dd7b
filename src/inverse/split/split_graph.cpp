#include "inverse/split/split_graph.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>
#include <unordered_map>

#include "base/error.hpp"
#include "inverse/split/placements.hpp"

namespace vern {

namespace {

// What the user can change, for a group's warning and for its error.
constexpr const char* kThickenHint =
    "give the part some thickness, or make it flush with the building's outer bounds";
constexpr const char* kSplitOneHint = "split one of these parts in two so that a cut can pass between them";

class GraphBuilder {
 public:
  GraphBuilder(Grammar& grammar, const std::vector<LabelledBox>& boxes, const std::string& source,
               const std::vector<Orientation>& turns, const SplitGraphOptions& options)
      : g_(grammar), boxes_(boxes), source_(source), turns_(turns), options_(options) {}

  NodeId node(const SplitTree& t) {
    switch (t.kind) {
      case SplitTree::Kind::Leaf: return leaf(t.box);
      case SplitTree::Kind::Empty: return nil();
      case SplitTree::Kind::Unsplittable: return placed(t);
      case SplitTree::Kind::Comp: return comp(t);
      case SplitTree::Kind::Split: break;
    }
    // A split of one part is that part (toOp: "if there is only one child").
    if (t.children.size() == 1) return node(t.children.front());
    Split split;
    split.axis = Expr::axis(static_cast<Axis>(t.axis));
    split.parts.reserve(t.children.size());
    // The parts' sizes first, in lists this builder keeps (a list or two
    // per split made a fifth of the city's graph building), free again
    // before the children are built below.
    lengths_now_.clear();
    canonical_now_.clear();
    for (const SplitTree& c : t.children) {
      lengths_now_.push_back(c.max[t.axis] - c.min[t.axis]);
      canonical_now_.push_back(canonical_length(lengths_now_.back()));
    }
    const std::vector<double>& sizes = cuts_stay(lengths_now_, canonical_now_) ? canonical_now_ : lengths_now_;
    for (const double size : sizes) split.parts.push_back({Size{Expr::number(size), true}, 0});
    for (std::size_t i = 0; i < t.children.size(); ++i) split.parts[i].child = node(t.children[i]);
    return g_.intern(Node{std::move(split), {}});
  }

 private:
  // Lengths that differ by float noise (a coordinate summed in another
  // order, a modelling tool's single precision) are one length, the first
  // seen: equal parts must be one node, or a row of equal windows is
  // neither one repeat nor one rule. Within a sixteenth of the tolerance,
  // so a run of parts so joined moves no cut by more than the tolerance.
  double canonical_length(double length) {
    const double grain = options_.tolerance / 16;
    if (!(grain > 0) || !std::isfinite(length)) return length;
    const auto key = static_cast<std::int64_t>(std::llround(length / grain));
    for (const std::int64_t k : {key, key - 1, key + 1}) {
      const auto it = lengths_.find(k);
      if (it != lengths_.end() && std::abs(it->second - length) <= grain) return it->second;
    }
    lengths_.emplace(key, length);
    return length;
  }

  // Do the canonical lengths, sharing the split's length as relative sizes
  // do, put every cut within a quarter of the tolerance of the example's?
  // (Many parts each moved by a little could add up.)
  bool cuts_stay(const std::vector<double>& lengths, const std::vector<double>& canonical) const {
    double total = 0, shares = 0;
    for (std::size_t i = 0; i < lengths.size(); ++i) {
      total += lengths[i];
      shares += canonical[i];
    }
    if (!(shares > 0)) return false;
    double at = 0, now = 0;
    for (std::size_t i = 0; i + 1 < lengths.size(); ++i) {
      at += lengths[i];
      now += canonical[i] * total / shares;
      if (std::abs(now - at) > options_.tolerance / 4) return false;
    }
    return true;
  }

  // comp(f){ front : ... | left : ... }: each face's tree in its frame.
  NodeId comp(const SplitTree& t) {
    Comp op;
    for (std::size_t i = 0; i < t.children.size(); ++i) op.parts.push_back({t.faces[i], node(t.children[i])});
    return g_.intern(Node{std::move(op), {}});
  }

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

  // Straight cuts cannot represent the group: its parts are placed with
  // S(...) inside cuts at their min corners (placements.hpp), and the user
  // is told where, since such a group is copied, not generalised.
  NodeId placed(const SplitTree& t) {
    const auto node = place_group(g_, t, options_.tolerance, [&](std::uint32_t box) { return leaf(box); }, nil());
    if (!node) unsplittable(t);
    if (options_.placed != nullptr) options_.placed->push_back(*node);
    if (options_.warnings != nullptr) {
      const bool flat = t.children.size() == 1;
      const std::string what =
          flat ? "part " + names(t) + " is flat and lies inside a thicker empty space, which no straight cut can "
                                      "cut it out of: it is placed with S(...)"
               : "no straight cut separates these " + std::to_string(t.children.size()) +
                     " parts (e.g. a pinwheel): they are placed with S(...) at their corners: " + names(t);
      const std::string hint = flat ? std::string(kThickenHint)
                                    : std::string("a placed group is copied as it is, never varied; ") + kSplitOneHint;
      options_.warnings->push_back(format_warning(source_, where(t), what) + "\n  hint: " + hint);
    }
    return *node;
  }

  // The group's parts, as messages name them: the first eight.
  std::string names(const SplitTree& t) const {
    std::string out;
    const std::size_t shown = std::min<std::size_t>(t.children.size(), 8);
    for (std::size_t i = 0; i < shown; ++i) {
      out += (i == 0 ? "" : ", ") + describe_object(boxes_.at(t.children[i].box));
    }
    if (shown < t.children.size()) out += " and " + std::to_string(t.children.size() - shown) + " more";
    return out;
  }

  // The line of the group's first part.
  SourceLoc where(const SplitTree& t) const {
    const LabelledBox& first = boxes_.at(t.children.front().box);
    return SourceLoc{first.line, first.line != 0 ? 1u : 0u};
  }

  // A group not even placements separate (parts sharing their min corner):
  // the user learns which parts to change.
  [[noreturn]] void unsplittable(const SplitTree& t) const {
    if (t.children.size() == 1) {
      fail(ErrorKind::Input, source_, where(t),
           "part " + names(t) + " is flat and lies inside a thicker empty space: no straight cut can separate it, "
           "because a cut never makes a part of zero thickness",
           kThickenHint);
    }
    fail(ErrorKind::Input, source_, where(t),
         "these " + std::to_string(t.children.size()) +
             " parts cannot be separated by straight cuts (e.g. a pinwheel): " + names(t),
         std::string("inference cuts buildings with planes through whole groups of parts; ") + kSplitOneHint);
  }

  Grammar& g_;
  const std::vector<LabelledBox>& boxes_;
  const std::string& source_;
  const std::vector<Orientation>& turns_;  // per box; empty: none turned
  const SplitGraphOptions& options_;
  std::unordered_map<std::string, NodeId> leaves_;  // label -> its primitive node
  std::unordered_map<std::int64_t, double> lengths_;  // canonical_length, by length / grain
  std::vector<double> lengths_now_, canonical_now_;    // node's, for one split at a time
  std::optional<NodeId> nil_;
};

}  // namespace

NodeId split_graph(Grammar& grammar, const SplitTree& tree, const std::vector<LabelledBox>& boxes,
                   const std::string& source, const std::vector<Orientation>& turns,
                   const SplitGraphOptions& options) {
  return GraphBuilder(grammar, boxes, source, turns, options).node(tree);
}

NodeId example_graph(Grammar& grammar, const Example& example, const BoxSplitOptions& options,
                     const std::vector<Orientation>& turns, std::vector<std::string>* warnings) {
  const SplitTree tree = split_boxes(example.boxes, options, example.source);
  return split_graph(grammar, tree, example.boxes, example.source, turns, {options.tolerance, warnings});
}

}  // namespace vern
