#include "workload.hpp"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <iostream>

#include "base/atomic_file.hpp"
#include "base/error.hpp"
#include "base/number_format.hpp"
#include "eval/random_grammar.hpp"
#include "forward/random_stream.hpp"
#include "support/command_line.hpp"
#include "support/guarded_main.hpp"

namespace vern {

namespace {


// A box in whole millimetres: integer cuts give neighbours identical faces.
struct MmBox {
  std::array<std::int64_t, 3> lo{}, hi{};
};

class LayoutMaker {
 public:
  explicit LayoutMaker(const LayoutOptions& o) : o_(o), rng_(mix64(o.seed ^ 0x1a40u)) {}

  std::vector<LabelledBox> run() {
    // About 3 m per box on each axis: a city block of rooms.
    const auto side = static_cast<std::int64_t>(std::ceil(3000.0 * std::cbrt(static_cast<double>(o_.boxes))));
    MmBox root;
    root.hi = {side, side, std::max<std::int64_t>(3000, side / 2)};
    out_.reserve(o_.boxes);
    place(root, o_.boxes, 0, -1);
    return std::move(out_);
  }

 private:
  void place(const MmBox& box, std::size_t n, int level, int parent_axis) {
    if (n == 1) return leaf(box);
    // The longest axis other than the parent's: every level a real cut.
    int axis = -1;
    for (int a = 0; a < 3; ++a) {
      if (a == parent_axis) continue;
      if (axis < 0 || length(box, a) > length(box, axis)) axis = a;
    }
    const bool last = level + 1 >= o_.depth;
    const std::size_t k =
        last ? n : std::min<std::size_t>(n, 2 + static_cast<std::size_t>(rng_.uniform() * (o_.branching - 1)));
    if (length(box, axis) < static_cast<std::int64_t>(k)) too_thin(n);

    // Shares of the boxes: one each, the rest in proportion to random weights.
    std::vector<double> weight(k);
    double total = 0;
    for (double& w : weight) total += (w = rng_.uniform(1.0, 2.0));
    std::vector<std::size_t> count(k, 1);
    std::size_t given = k;
    for (std::size_t i = 0; i < k; ++i) {
      const auto extra = static_cast<std::size_t>(std::floor(static_cast<double>(n - k) * weight[i] / total));
      count[i] += extra;
      given += extra;
    }
    for (std::size_t i = 0; given < n; i = (i + 1) % k, ++given) ++count[i];

    // Lengths follow the shares, jittered; a gap (nil) gets an average share.
    std::vector<double> share(k);
    for (std::size_t i = 0; i < k; ++i) share[i] = static_cast<double>(count[i]) * rng_.uniform(0.8, 1.25);
    std::size_t gap = k;  // none
    if (!last && rng_.uniform() < o_.gaps) {
      gap = static_cast<std::size_t>(rng_.uniform() * static_cast<double>(k + 1));
      share.insert(share.begin() + static_cast<std::ptrdiff_t>(gap), static_cast<double>(n) / static_cast<double>(k));
      count.insert(count.begin() + static_cast<std::ptrdiff_t>(gap), 0);
    }
    double sum = 0;
    for (double s : share) sum += s;

    const std::int64_t from = box.lo[static_cast<std::size_t>(axis)];
    const std::int64_t span = length(box, axis);
    if (span < static_cast<std::int64_t>(share.size())) too_thin(n);
    double before = 0;
    std::int64_t cut = from;
    for (std::size_t i = 0; i < share.size(); ++i) {
      before += share[i];
      // Each piece at least 1 mm, and room left for the pieces after it.
      const auto remaining = static_cast<std::int64_t>(share.size() - i - 1);
      std::int64_t next = i + 1 == share.size() ? from + span
                                                : from + std::llround(static_cast<double>(span) * before / sum);
      next = std::clamp(next, cut + 1, from + span - remaining);
      MmBox piece = box;
      piece.lo[static_cast<std::size_t>(axis)] = cut;
      piece.hi[static_cast<std::size_t>(axis)] = next;
      if (count[i] > 0) place(piece, count[i], level + 1, axis);
      cut = next;
    }
  }

  [[noreturn]] void too_thin(std::size_t n) const {
    fail(ErrorKind::Usage, "--make-layout", {},
         std::to_string(n) + " boxes in a row at depth " + std::to_string(o_.depth) +
             " would be thinner than a millimetre",
         "raise --depth or --branching");
  }

  static std::int64_t length(const MmBox& b, int axis) {
    return b.hi[static_cast<std::size_t>(axis)] - b.lo[static_cast<std::size_t>(axis)];
  }

  void leaf(const MmBox& box) {
    LabelledBox b;
    b.label = kWorkloadLabels[static_cast<std::size_t>(rng_.uniform() * kWorkloadLabels.size())];
    b.object = b.label + "." + std::to_string(out_.size() + 1);
    for (glm::length_t a = 0; a < 3; ++a) {
      b.min[a] = static_cast<double>(box.lo[static_cast<std::size_t>(a)]) / 1000.0;
      b.max[a] = static_cast<double>(box.hi[static_cast<std::size_t>(a)]) / 1000.0;
    }
    b.mesh = static_cast<std::uint32_t>(out_.size());
    out_.push_back(std::move(b));
  }

  const LayoutOptions& o_;
  RandomStream rng_;
  std::vector<LabelledBox> out_;
};

void append_int(std::string& out, std::uint64_t v) {
  char buf[24];
  const auto r = std::to_chars(buf, buf + sizeof buf, v);
  out.append(buf, r.ptr);
}

}  // namespace

std::vector<LabelledBox> random_layout(const LayoutOptions& options) {
  if (options.boxes == 0 || options.boxes > (std::size_t{1} << 28) || options.depth < 1 || options.branching < 2 ||
      !(options.gaps >= 0 && options.gaps <= 1)) {
    fail(ErrorKind::Usage, "--make-layout", {}, "layout options out of range",
         "give 1 to 2^28 boxes, --depth >= 1, --branching >= 2 and --gaps in [0, 1]");
  }
  return LayoutMaker(options).run();
}

std::string layout_obj(const std::vector<LabelledBox>& boxes) {
  // Corner i has x from bit 0, y from bit 1, z from bit 2; each quad is
  // listed counter-clockwise seen from outside (-x, +x, -y, +y, -z, +z).
  static constexpr std::array<std::array<int, 4>, 6> kFaces = {
      {{0, 4, 6, 2}, {1, 3, 7, 5}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 2, 3, 1}, {4, 5, 7, 6}}};
  std::string out;
  out.reserve(boxes.size() * 320 + 64);
  out += "# A random guillotine layout (vern_bench --make-layout): one object per part.\n";
  out += "# up z\n";  // the boxes' own frame (io/obj_reader.hpp)
  std::uint64_t base = 1;
  for (const LabelledBox& b : boxes) {
    out += "o ";
    out += b.object;
    out += '\n';
    for (int i = 0; i < 8; ++i) {
      out += 'v';
      for (glm::length_t a = 0; a < 3; ++a) {
        out += ' ';
        append_number(out, ((i >> a) & 1) != 0 ? b.max[a] : b.min[a]);
      }
      out += '\n';
    }
    for (const auto& face : kFaces) {
      out += 'f';
      for (int corner : face) {
        out += ' ';
        append_int(out, base + static_cast<std::uint64_t>(corner));
      }
      out += '\n';
    }
    base += 8;
  }
  return out;
}

bool is_workload_command(const char* arg) {
  const std::string a = arg;
  return a == "--make-layout" || a == "--make-grammar";
}

namespace {

int run_workload(int argc, char** argv) {
  CommandLine cl("vern_bench", "vern_bench --make-layout N | --make-grammar R [options] -o FILE",
                 "Writes a synthetic workload for the benchmarks: a random guillotine layout of N\n"
                 "labelled boxes as OBJ (input for infer), or a random grammar of R rules.");
  cl.add({"--make-layout", "", 1, "N", "a layout of N boxes (1 to 2^28)"});
  cl.add({"--make-grammar", "", 1, "R", "a grammar of R rules"});
  cl.add({"--depth", "", 1, "D", "layout: levels of cuts at most (default 16)"});
  cl.add({"--branching", "", 1, "B", "pieces per cut at most (default 4)"});
  cl.add({"--gaps", "", 1, "P", "layout: chance that a cut leaves an empty piece (default 0.1)"});
  cl.add({"--seed", "-s", 1, "S", "seed (default 1)"});
  cl.add({"--output", "-o", 1, "FILE", "where to write (required)"});
  cl.add_standard_options(false);
  const ParsedCommandLine args = cl.parse(argc, argv);
  if (args.has("--help")) {
    std::cout << cl.help();
    return 0;
  }
  if (!args.has("--output")) throw Error(ErrorKind::Usage, "vern_bench: error: no output given\n  hint: add -o FILE");
  const auto seed = args.has("--seed") ? static_cast<std::uint64_t>(CommandLine::integer(args, "--seed", 0, 1LL << 53)) : 1;
  const int branching = args.has("--branching") ? static_cast<int>(CommandLine::integer(args, "--branching", 2, 1000)) : 4;
  std::string text;
  if (args.has("--make-layout")) {
    LayoutOptions o;
    o.boxes = static_cast<std::size_t>(CommandLine::integer(args, "--make-layout", 1, 1LL << 28));
    if (args.has("--depth")) o.depth = static_cast<int>(CommandLine::integer(args, "--depth", 1, 1000));
    if (args.has("--gaps")) o.gaps = CommandLine::number(args, "--gaps");
    o.branching = branching;
    o.seed = seed;
    text = layout_obj(random_layout(o));
  } else {
    GrammarOptions o;
    o.rules = static_cast<std::size_t>(CommandLine::integer(args, "--make-grammar", 1, 1LL << 24));
    o.branching = branching;
    o.seed = seed;
    text = random_grammar(o);
  }
  write_file_atomically(args.value("--output"), text);
  return 0;
}

}  // namespace

int workload_main(int argc, char** argv) { return guarded_main("vern_bench", run_workload, argc, argv); }

}  // namespace vern
