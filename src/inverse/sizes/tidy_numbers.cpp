#include "inverse/sizes/tidy_numbers.hpp"

#include <array>
#include <cmath>
#include <optional>

#include "inverse/merge/equal_options.hpp"
#include "inverse/merge/merge.hpp"

namespace vern {

namespace {

// 10^0 .. 10^17, exact as doubles (what std::pow(10, d) gives, without the
// call: tidying calls this for every number of a million-part grammar).
constexpr std::array<double, 18> kPowersOfTen = {1e0,  1e1,  1e2,  1e3,  1e4,  1e5,  1e6,  1e7,  1e8,
                                                 1e9,  1e10, 1e11, 1e12, 1e13, 1e14, 1e15, 1e16, 1e17};

}  // namespace

double shortest_decimal(double v, double tolerance, int direction) {
  if (v == 0.0 || !std::isfinite(v)) return v;
  for (const double scale : kPowersOfTen) {
    double r;
    if (direction < 0) r = std::floor(v * scale) / scale;
    else if (direction > 0) r = std::ceil(v * scale) / scale;
    else r = std::round(v * scale) / scale;
    if (std::abs(r - v) <= tolerance) return r;
  }
  return v;
}

std::optional<std::vector<double>> whole_ratios(const std::vector<double>& sizes, double tolerance, int max_whole) {
  double smallest = 0, largest = 0, total = 0;
  for (double s : sizes) {
    if (!(s > 0)) return std::nullopt;
    smallest = smallest == 0 ? s : std::min(smallest, s);
    largest = std::max(largest, s);
    total += s;
  }
  // Do whole numbers n, as shares of the sizes' total, put every cut within
  // the tolerance of where the sizes put it?
  auto cuts_hold = [&](const std::vector<double>& n) {
    double units = 0;
    for (double k : n) units += k;
    double at = 0, whole = 0;
    for (std::size_t i = 0; i + 1 < n.size(); ++i) {
      at += sizes[i];
      whole += n[i];
      if (std::abs(whole * total / units - at) > tolerance) return false;
    }
    return true;
  };
  // The smallest part is some whole k of the unit; try k = 1, 2, ...
  std::vector<double> out;
  out.reserve(sizes.size());
  for (int k = 1; k <= max_whole; ++k) {
    const double unit = smallest / k;
    // The largest part is the likeliest to fail (most splits have no whole
    // ratios), and once it needs more than max_whole units it does for
    // every larger k too (the unit only shrinks): no k beyond can work.
    const double most = std::round(largest / unit);
    if (most > max_whole) break;
    // Quick rejections, the largest part first (most splits have no whole
    // ratios at all). Within a tolerance every part is within 2 tolerance
    // of its n units of the fitted unit, and that unit within 2 tolerance /
    // k of this one: a part further from n of these units fails.
    auto near = [&](double s, double n) {
      return std::abs(s / unit - n) <= 1e-9 * n || std::abs(s - n * unit) <= 2 * tolerance * (1 + n / k);
    };
    if (!near(largest, most)) continue;
    out.clear();
    bool in_range = true, exact = true;
    for (double s : sizes) {
      const double n = std::round(s / unit);
      if (n < 1 || n > max_whole || !near(s, n)) {
        in_range = false;
        break;
      }
      exact = exact && std::abs(s / unit - n) <= 1e-9 * n;
      out.push_back(n);
    }
    if (in_range && (exact || (tolerance > 0 && cuts_hold(out)))) return out;
  }
  return std::nullopt;
}

namespace {

// Rounds the numbers below a node. A node whose numbers are already as
// short as they get and whose children did not change is kept without a
// copy (most of a million-part building); that needs the graph interned,
// as inference builds it, since intern would return the node itself.
class Tidier {
 public:
  Tidier(Grammar& g, double tolerance) : g_(g), tol_(tolerance), memo_(g.node_count(), kNotYet) {}

  NodeId run(NodeId id) {
    if (id >= memo_.size()) memo_.resize(g_.node_count(), kNotYet);
    if (memo_[id] != kNotYet) return memo_[id];
    NodeId out = id;
    const Operation& here = g_.op(id);
    if (std::holds_alternative<Split>(here)) {
      out = tidy_split(id);
    } else if (std::holds_alternative<Choose>(here) || std::holds_alternative<Repeat>(here) ||
               std::holds_alternative<RepeatN>(here) || std::holds_alternative<Rotate>(here) ||
               std::holds_alternative<Scale>(here) || std::holds_alternative<Comp>(here)) {
      out = tidy_other(id);
    }
    memo_[id] = out;
    return out;
  }

 private:
  static constexpr NodeId kNotYet = static_cast<NodeId>(-1);

  Expr tidy(const Expr& e) const {
    if (auto v = e.literal()) return Expr::number(shortest_decimal(*v, tol_));
    if (auto r = literal_range(e))
      return range_expr({shortest_decimal(r->lo, tol_), shortest_decimal(r->hi, tol_)}, 0.0);
    return tidy_distribution(e);
  }

  // Fitted distributions (fit_distribution.hpp) of literal arguments:
  // choice(...) values within the tolerance; tnormal's support like a
  // range's, its mean and spread to a hundredth of the spread (they
  // shape the variants, not which examples derive).
  Expr tidy_distribution(const Expr& e) const {
    const ExprNode& root = e.node(e.root());
    if (root.kind != ExprKind::Call || e.nodes().size() != std::size_t{root.argc} + 1) return e;
    std::vector<double> args;
    for (std::size_t i = 0; i + 1 < e.nodes().size(); ++i) {
      if (e.node(i).kind != ExprKind::Number) return e;
      args.push_back(e.node(i).number);
    }
    const auto f = static_cast<Function>(root.op);
    std::vector<Expr> out;
    if (f == Function::Choice) {
      for (const double v : args) out.push_back(Expr::number(shortest_decimal(v, tol_)));
    } else if (f == Function::TNormal && args.size() == 4) {
      const double fine = std::max(tol_, args[1] / 100);
      out = {Expr::number(shortest_decimal(args[0], fine)), Expr::number(shortest_decimal(args[1], fine)),
             Expr::number(shortest_decimal(args[2], tol_)), Expr::number(shortest_decimal(args[3], tol_))};
    } else {
      return e;
    }
    return Expr::call(f, std::move(out));
  }

  // Choose, repeat, repeatN, rotate, S: few in a grammar, so always copied.
  NodeId tidy_other(NodeId id) {
    Operation op = g_.op(id);  // a copy: running the children may grow the arena
    if (auto* c = std::get_if<Choose>(&op)) {
      for (auto& o : c->options) {
        o.child = run(o.child);
        if (auto p = o.priority.literal()) o.priority = Expr::number(shortest_decimal(*p, 1e-9 * *p));
      }
      // Alternatives that differed only in numbers now written alike (a
      // lone share's weight, which every weight writes as ~1) are one.
      if (join_equal_options(*c) && c->options.size() == 1 && c->options[0].condition.empty())
        return c->options[0].child;
    } else if (auto* tiles = std::get_if<RepeatN>(&op)) {
      tiles->child = run(tiles->child);
    } else if (auto* repeat = std::get_if<Repeat>(&op)) {
      repeat->child = run(repeat->child);
      // A tile size rounds up, never down: a tile a hair smaller than
      // L / n would make ceil(L / size) one tile more.
      if (auto v = repeat->size.literal()) {
        repeat->size = Expr::number(shortest_decimal(*v, tol_, +1));
      } else {
        repeat->size = tidy(repeat->size);
      }
    } else if (auto* turn = std::get_if<Rotate>(&op)) {
      turn->child = run(turn->child);
    } else if (auto* faces = std::get_if<Comp>(&op)) {
      for (CompPart& face : faces->parts) face.child = run(face.child);
    } else if (auto* resize = std::get_if<Scale>(&op)) {
      // A placed part's size (placements.hpp): off by at most the tolerance.
      // A relative one is a ratio to its piece, rounded where it was made
      // (the tolerance in metres is not one in ratios).
      resize->child = run(resize->child);
      for (Size& size : resize->size)
        if (!size.relative) size.value = tidy(size.value);
    }
    return g_.intern({std::move(op), g_.node(id).loc});
  }

  // Is e exactly the literal v (as Expr::number(v) would be)?
  static bool is_number(const Expr& e, double v) {
    return e.nodes().size() == 1 && e.node(0) == ExprNode{.kind = ExprKind::Number, .number = v};
  }

  NodeId tidy_split(NodeId id) {
    // The children first: they may grow the arena, so the split is looked
    // up again for each. Their tidied ids wait on a stack that the calls
    // inside leave as they found it, so no split allocates its own list.
    const std::size_t n = std::get<Split>(g_.op(id)).parts.size();
    const std::size_t base = children_.size();
    bool same = true;
    for (std::size_t i = 0; i < n; ++i) {
      const NodeId child = std::get<Split>(g_.op(id)).parts[i].child;
      const NodeId tidied = run(child);
      same = same && tidied == child;
      children_.push_back(tidied);
    }
    // The new sizes: literals as numbers, anything else as an expression.
    // Scratch lists shared by every split: nothing below runs a child.
    const Split& s = std::get<Split>(g_.op(id));  // no nodes are added until the end
    number_.assign(n, 0.0);
    other_.assign(n, std::nullopt);
    // Relative sizes only matter as ratios to each other (the absolute
    // parts take their metres first, whatever the relative ones say), so
    // literal ones become small whole ratios where they have them, beside
    // absolute parts too: ~0.40383 : 1.2 : ~0.80767 is ~1 : 1.2 : ~2.
    relative_.clear();
    bool relative_literals = true;
    for (const auto& p : s.parts) {
      if (!p.size.relative) continue;
      if (const auto v = p.size.value.literal()) relative_.push_back(*v);
      else relative_literals = false;
    }
    std::optional<std::vector<double>> ratios;
    if (relative_literals && !relative_.empty()) ratios = whole_ratios(relative_, tol_);
    // Other literal sizes: round the cut positions, not the sizes, so
    // errors do not add up along a split of many parts; each size is then
    // the difference of two short decimals (cleaned of binary noise).
    double position = 0, rounded_previous = 0;
    std::size_t next_ratio = 0;
    for (std::size_t i = 0; i < n; ++i) {
      if (ratios && s.parts[i].size.relative) {
        number_[i] = (*ratios)[next_ratio++];
        continue;
      }
      const auto v = s.parts[i].size.value.literal();
      if (!v) {
        // Past a range the cut positions are unknown: start again.
        other_[i] = tidy(s.parts[i].size.value);
        position = rounded_previous = 0;
        continue;
      }
      position += *v;
      const double rounded = shortest_decimal(position, tol_);
      number_[i] = shortest_decimal(rounded - rounded_previous, 1e-12 * std::max(1.0, rounded));
      rounded_previous = rounded;
    }
    for (std::size_t i = 0; i < n && same; ++i)
      same = other_[i] ? *other_[i] == s.parts[i].size.value : is_number(s.parts[i].size.value, number_[i]);
    if (same) {
      children_.resize(base);
      return id;
    }

    // Built afresh rather than copied: the old sizes would only be thrown away.
    Split tidied;
    tidied.axis = s.axis;
    tidied.parts.reserve(n);
    for (std::size_t i = 0; i < n; ++i) {
      Expr size = other_[i] ? std::move(*other_[i]) : Expr::number(number_[i]);
      tidied.parts.push_back({Size{std::move(size), s.parts[i].size.relative}, children_[base + i]});
    }
    children_.resize(base);
    return g_.intern({std::move(tidied), g_.node(id).loc});  // s may be stale from here
  }

  Grammar& g_;
  double tol_;
  std::vector<NodeId> memo_;  // by node id: its tidied node, or kNotYet
  std::vector<NodeId> children_;  // tidied children of the splits being tidied, innermost last
  std::vector<double> number_, relative_;  // scratch of the split being tidied
  std::vector<std::optional<Expr>> other_;
};

}  // namespace

NodeId tidy_numbers(Grammar& g, NodeId root, double tolerance) { return Tidier(g, tolerance).run(root); }

}  // namespace vern
