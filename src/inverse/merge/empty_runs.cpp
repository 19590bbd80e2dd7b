#include "inverse/merge/empty_runs.hpp"

#include <optional>

#include "graph/nodes_below.hpp"
#include "inverse/merge/substitute.hpp"

namespace vern {

namespace {

// Where b is a's parts but for a's first (front) or last part, a repeat:
// that end.
enum class End { Front, Back };

std::optional<End> missing_run(const Grammar& g, const Split& a, const Split& b) {
  if (a.parts.size() != b.parts.size() + 1 || b.parts.empty() || !(a.axis == b.axis)) return std::nullopt;
  auto same_from = [&](std::size_t offset) {
    for (std::size_t i = 0; i < b.parts.size(); ++i)
      if (b.parts[i].child != a.parts[i + offset].child) return false;
    return true;
  };
  if (std::holds_alternative<Repeat>(g.op(a.parts.front().child)) && same_from(1)) return End::Front;
  if (std::holds_alternative<Repeat>(g.op(a.parts.back().child)) && same_from(0)) return End::Back;
  return std::nullopt;
}

// The nodes from `id` down through one-child operations (repeats,
// transforms: the storeys' repeat round a row), then the split below them.
struct Wrapped {
  std::vector<NodeId> chain;
  NodeId inner = 0;
};

Wrapped unwrap(const Grammar& g, NodeId id) {
  Wrapped w;
  while (true) {
    const Operation& op = g.op(id);
    if (!std::holds_alternative<Repeat>(op) && !std::holds_alternative<RepeatN>(op) &&
        !std::holds_alternative<Translate>(op) && !std::holds_alternative<Scale>(op) &&
        !std::holds_alternative<Rotate>(op))
      break;
    w.chain.push_back(id);
    id = node_children(op)[0];
  }
  w.inner = id;
  return w;
}

// Are two nodes the same operation but for their one child (and, for
// repeats, their tile sizes, which merging unites where they are alike)?
bool same_but_child(const Grammar& g, NodeId a, NodeId b) {
  const auto* ra = std::get_if<Repeat>(&g.op(a));
  const auto* rb = std::get_if<Repeat>(&g.op(b));
  if (ra || rb) return ra && rb && ra->axis == rb->axis;
  Operation x = g.op(a), y = g.op(b);
  *child_slots(x)[0] = 0;
  *child_slots(y)[0] = 0;
  return x == y;
}

}  // namespace

EmptyRuns pad_empty_runs(Grammar& g, NodeId root, SampleBook& book, RowBook& rows) {
  EmptyRuns out{root, 0, {}};
  std::vector<NodeId> replace;
  std::vector<std::pair<NodeId, NodeId>> padded;
  // The split b_id with a's run at its end, zero long; its notes too.
  auto pad = [&](NodeId b_id, const Split& a, End end) {
    const SplitPart& run = end == End::Front ? a.parts.front() : a.parts.back();
    Split now = std::get<Split>(g.op(b_id));
    const SplitPart empty{Size{Expr::number(0), run.size.relative}, run.child};
    const std::size_t at = end == End::Front ? 0 : now.parts.size();
    now.parts.insert(now.parts.begin() + static_cast<std::ptrdiff_t>(at), empty);
    const NodeId padded_id = g.intern({std::move(now), g.node(b_id).loc});
    if (const auto it = rows.find(b_id); it != rows.end()) {
      std::vector<LengthRow> with = it->second;
      for (LengthRow& r : with) r.lengths.insert(r.lengths.begin() + static_cast<std::ptrdiff_t>(at), 0.0);
      rows[padded_id] = std::move(with);
    }
    if (const auto it = book.find(b_id); it != book.end()) {
      std::vector<std::vector<Observation>> with = it->second;
      std::vector<Observation> zeros;
      if (!with.empty())
        for (const Observation& o : with.front()) zeros.push_back({0.0, o.count, o.example});
      with.insert(with.begin() + static_cast<std::ptrdiff_t>(at), std::move(zeros));
      book[padded_id] = std::move(with);
    }
    return padded_id;
  };
  // The rows a node stands for: a split, or a choice of splits (a
  // storey's row drawn anew storey by storey).
  auto rows_of = [&](NodeId id) {
    std::vector<NodeId> rows_here;
    if (std::holds_alternative<Split>(g.op(id))) rows_here.push_back(id);
    else if (const auto* c = std::get_if<Choose>(&g.op(id)))
      for (const ChooseOption& o : c->options) rows_here.push_back(o.child);
    return rows_here;
  };
  // A row of the shorter node padded with the run of a row of the longer
  // one that it matches; kNoReplacement where none does.
  auto padded_row = [&](NodeId row, const std::vector<NodeId>& longer_rows) -> NodeId {
    if (!std::holds_alternative<Split>(g.op(row))) return kNoReplacement;
    for (const NodeId other : longer_rows) {
      const auto* a = std::get_if<Split>(&g.op(other));
      if (!a) continue;
      if (const auto end = missing_run(g, *a, std::get<Split>(g.op(row)))) return pad(row, Split(*a), *end);
    }
    return kNoReplacement;
  };
  // The shorter node padded against the longer, each a split or, under
  // a repeat, a choice of rows (storeys whose bays were drawn storey by
  // storey): each row of the shorter gains the run of a row of the longer
  // whose parts it has but for that run. kNoReplacement where some row
  // does not.
  auto padded_inner = [&](NodeId shorter, NodeId longer) -> NodeId {
    const std::vector<NodeId> longer_rows = rows_of(longer);
    if (std::holds_alternative<Split>(g.op(shorter))) return padded_row(shorter, longer_rows);
    const auto* bc = std::get_if<Choose>(&g.op(shorter));
    if (!bc) return kNoReplacement;
    Choose now = *bc;  // a copy: padding interns
    for (ChooseOption& option : now.options) {
      const NodeId padded_id = padded_row(option.child, longer_rows);
      if (padded_id == kNoReplacement) return kNoReplacement;
      option.child = padded_id;
    }
    return g.intern({std::move(now), g.node(shorter).loc});
  };
  for (const NodeId id : nodes_below(g, root)) {
    const auto* choose = std::get_if<Choose>(&g.op(id));
    if (!choose) continue;
    const std::vector<ChooseOption> options = choose->options;  // a copy: interning may move the arena
    for (const ChooseOption& shorter : options) {
      const NodeId b_top = shorter.child;
      if (b_top < replace.size() && replace[b_top] != kNoReplacement) continue;
      const Wrapped b_wrap = unwrap(g, b_top);
      const Operation& b_inner = g.op(b_wrap.inner);
      if (!std::holds_alternative<Split>(b_inner) && !(std::holds_alternative<Choose>(b_inner) && !b_wrap.chain.empty()))
        continue;
      const bool b_choice = std::holds_alternative<Choose>(b_inner);
      for (const ChooseOption& longer : options) {
        if (longer.child == b_top) continue;
        const Wrapped a_wrap = unwrap(g, longer.child);
        if (a_wrap.chain.size() != b_wrap.chain.size()) continue;
        // A choice of rows only under a repeat (the storeys' tiles).
        if ((b_choice || std::holds_alternative<Choose>(g.op(a_wrap.inner))) && a_wrap.chain.empty()) continue;
        bool alike = true;
        for (std::size_t k = 0; k < a_wrap.chain.size() && alike; ++k)
          alike = same_but_child(g, a_wrap.chain[k], b_wrap.chain[k]);
        if (!alike) continue;
        NodeId padded_id = padded_inner(b_wrap.inner, a_wrap.inner);
        if (padded_id == kNoReplacement) continue;
        // The wrappers round it, rebuilt; their notes carry over.
        for (std::size_t k = b_wrap.chain.size(); k-- > 0;) {
          Operation op = g.op(b_wrap.chain[k]);
          *child_slots(op)[0] = padded_id;
          const NodeId rebuilt = g.intern({std::move(op), g.node(b_wrap.chain[k]).loc});
          out.replaced.push_back({b_wrap.chain[k], rebuilt});
          padded_id = rebuilt;
        }
        if (replace.size() <= b_top) replace.resize(b_top + 1, kNoReplacement);
        replace[b_top] = padded_id;
        padded.push_back({b_top, padded_id});
        break;
      }
    }
  }
  out.padded = padded.size();
  if (padded.empty()) return out;
  carry_samples(out.replaced, book);
  out.root = substitute_keeping_samples(g, root, replace, book, &out.replaced);
  return out;
}

}  // namespace vern
