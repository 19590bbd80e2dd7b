#include "eval/random_style.hpp"

#include <algorithm>
#include <cmath>
#include <set>

#include "base/number_format.hpp"
#include "forward/random_stream.hpp"

namespace vern {

namespace {

// Two decimals at most, as a person writes sizes.
double tidy(double v) { return std::round(v * 100) / 100; }
std::string num(double v) { return format_number(tidy(v)); }
// Up to the next half metre: plot bounds never fall below what they must hold.
double ceil_half(double v) { return std::ceil(v * 2 - 1e-9) / 2; }

// A size as the grammar writes it, and the least and the most it can be.
struct Size {
  std::string text;
  double lo = 0, hi = 0;
};

// The least share a relative part gets among parts: its least against the
// others' most.
double least_share(const Size& part, const std::vector<Size>& others) {
  double rest = 0;
  for (const Size& o : others) rest += o.hi;
  return part.lo / (part.lo + rest);
}

template <std::size_t N>
using Words = std::array<std::string_view, N>;

// Bay kinds of the main front: what stands between the two wall parts.
enum class Bay : std::uint8_t { Window, Balcony, Pair, Panel };
constexpr std::array<Bay, 4> kBays{Bay::Window, Bay::Balcony, Bay::Pair, Bay::Panel};

enum class Plan : std::uint8_t { Single, Row, Hall, L, U, Courtyard };
enum class Top : std::uint8_t { Leaf, Pavilion };
// Where the special tile goes: the ground floor, each storey, or the annexes.
enum class Special : std::uint8_t { None, Ground, Storeys, Annexes };

class StyleMaker {
 public:
  explicit StyleMaker(std::uint64_t seed) : seed_(seed), rng_(mix64(seed ^ 0x57a1e5u)) {}

  RandomStyle run() {
    for (std::size_t i = 0; i < kStyleClasses.size(); ++i) on_[i] = rng_.uniform() < kStyleClasses[i].rate;
    choose_words();
    choose_plan();
    choose_front();
    choose_plan_sizes();
    choose_plot();
    RandomStyle style;
    style.text = write();
    for (std::size_t i = 0; i < kStyleClasses.size(); ++i)
      if (on_[i]) style.classes.push_back(kStyleClasses[i].id);
    return style;
  }

 private:
  bool on(StyleClass c) const { return on_[static_cast<std::size_t>(c)]; }
  bool chance(double p) { return rng_.uniform() < p; }
  // a..b, both included.
  int integer(int a, int b) { return a + static_cast<int>(rng_.uniform() * (b - a + 1)); }
  // A value in [a, b] on a grid of `step`.
  double step(double a, double b, double s) { return tidy(std::round(rng_.uniform(a, b) / s) * s); }
  template <std::size_t N>
  std::string_view pick(const Words<N>& words) {
    return words[static_cast<std::size_t>(rng_.uniform() * N)];
  }

  // A rule name from a pool of building words, unique in the style.
  template <std::size_t N>
  std::string rule_name(const Words<N>& words) {
    std::string name(pick(words));
    for (int i = 2; used_names_.count(name) != 0; ++i) name = std::string(pick(words)) + std::to_string(i);
    used_names_.insert(name);
    return name;
  }

  // A size in [lo, hi] that is either written as one number or, in a style
  // with continuous sizes and at about half of the places that allow it,
  // drawn from a range (rand) or a truncated normal (tnormal) within it.
  Size free_size(double lo, double hi, double grid, bool relative) {
    const std::string tilde = relative ? "~" : "";
    if (on(StyleClass::ContinuousSizes) && chance(0.5)) return drawn_size(lo, hi, grid, tilde);
    const double v = step(lo, hi, grid);
    return {tilde + num(v), v, v};
  }
  Size drawn_size(double lo, double hi, double grid, const std::string& tilde) {
    ++draws_;
    const double a = step(lo, lo + (hi - lo) * 0.4, grid);
    const double b = std::max(tidy(a + grid), step(lo + (hi - lo) * 0.6, hi, grid));
    if (chance(0.5)) return {tilde + "rand(" + num(a) + ", " + num(b) + ")", a, b};
    const double mu = tidy((a + b) / 2), sigma = tidy(std::max(0.01, (b - a) / 4));
    return {tilde + "tnormal(" + num(mu) + ", " + num(sigma) + ", " + num(a) + ", " + num(b) + ")", a, b};
  }

  void choose_words() {
    static constexpr Words<6> kWall{"wall", "brick", "stone", "render", "masonry", "rect"};
    static constexpr Words<4> kWindow{"window", "glazing", "casement", "pane"};
    static constexpr Words<3> kDoor{"door", "entrance", "portal"};
    static constexpr Words<4> kPillar{"pillar", "pier", "column", "pilaster"};
    static constexpr Words<4> kShop{"shopfront", "display", "vitrine", "glass"};
    static constexpr Words<3> kBalcony{"balcony", "railing", "loggia"};
    static constexpr Words<4> kCornice{"cornice", "slab", "band", "ledge"};
    static constexpr Words<3> kPlinth{"plinth", "podium", "base"};
    static constexpr Words<3> kTier{"tier", "stage", "drum"};
    static constexpr Words<3> kPanel{"panel", "blind", "infill"};
    wall_ = pick(kWall);
    annex_wall_ = chance(0.5) ? wall_ : std::string(pick(kWall));
    window_ = pick(kWindow);
    door_ = pick(kDoor);
    pillar_ = pick(kPillar);
    shop_ = pick(kShop);
    balcony_ = pick(kBalcony);
    cornice_ = pick(kCornice);
    plinth_ = pick(kPlinth);
    tier_ = pick(kTier);
    panel_ = pick(kPanel);
  }

  void choose_plan() {
    if (on(StyleClass::Wings)) {
      plan_ = std::array{Plan::L, Plan::U, Plan::Courtyard}[static_cast<std::size_t>(integer(0, 2))];
    } else {
      // Shared sizes and tiles, a special tile with no ground floor left
      // for it, and empty space in a style whose crown is tiers need annexes
      // beside the main block.
      const bool annexes = on(StyleClass::SharedSize) || on(StyleClass::SharedTile) ||
                           (on(StyleClass::AlignedRepeat) && on(StyleClass::SpecialTile)) ||
                           (on(StyleClass::NilGap) && on(StyleClass::RecursiveTiers));
      // A special tile on the annexes wants them long: a hall's aisles run
      // the whole plot.
      const bool long_annexes = on(StyleClass::AlignedRepeat) && on(StyleClass::SpecialTile);
      plan_ = long_annexes ? Plan::Hall
              : annexes    ? (chance(0.5) ? Plan::Row : Plan::Hall)
                           : std::array{Plan::Single, Plan::Row, Plan::Hall}[static_cast<std::size_t>(integer(0, 2))];
    }
    ground_zone_ = on(StyleClass::GroundFloor) || on(StyleClass::AlignedRepeat) || on(StyleClass::LinearSize);
    if (on(StyleClass::SpecialTile)) {
      special_ = on(StyleClass::AlignedRepeat) ? Special::Annexes : ground_zone_ ? Special::Ground : Special::Storeys;
    }
    // Empty space: a yard in a row; else a pavilion with air on both sides,
    // on the main roof, or on the annexes' roofs where the main one is tiers
    // (check cannot place a part whose edges neither boxes nor its parent's
    // edges show: air inside the last tier's set-in margins).
    yard_ = on(StyleClass::NilGap) && plan_ == Plan::Row;
    const bool pavilion = on(StyleClass::NilGap) && !yard_;
    top_ = pavilion && !on(StyleClass::RecursiveTiers) ? Top::Pavilion : Top::Leaf;
    annex_pavilion_ = pavilion && on(StyleClass::RecursiveTiers);
    piers_ = on(StyleClass::ConstantInVarying) && chance(0.5);
    cornice_zone_ = on(StyleClass::ConstantInVarying) && !piers_;
  }

  bool has_annexes() const { return plan_ != Plan::Single; }
  // Annex facades along y: wings of L, U and courtyard plans.
  bool annexes_y() const { return plan_ == Plan::L || plan_ == Plan::U || plan_ == Plan::Courtyard; }
  bool annexes_x() const { return plan_ == Plan::Row || plan_ == Plan::Hall || plan_ == Plan::Courtyard; }
  // Annex walls are a share of the height, unless they share one height h.
  bool annex_walls_share() const { return has_annexes() && (!on(StyleClass::SharedSize) || annexes_y()); }

  // The main front: bays, storeys, ground floor, roof.
  void choose_front() {
    tile_ = step(3.0, 4.5, 0.1);
    storey_ = step(2.8, 3.6, 0.1);
    annex_tile_ = on(StyleClass::SharedTile) ? tile_ : far_tile(2.6, 5.0);
    shop_tile_ = on(StyleClass::SharedTile) ? tile_ : far_tile(3.0, 5.0);
    k_most_ = integer(2, 4);
    annex_k_most_ = integer(1, 3);
    door_width_ = step(1.0, std::min(1.6, tile_ - 1.2), 0.1);
    door_height_ = step(2.1, 2.4, 0.1);
    sill_ = step(0.6, 0.9, 0.1);
    lintel_ = step(0.2, 0.3, 0.1);
    balcony_height_ = step(0.8, 0.9, 0.1);
    pillar_width_ = step(0.2, 0.4, 0.1);
    cornice_height_ = step(0.3, 0.8, 0.1);
    pier_width_ = step(0.4, 1.0, 0.1);
    margin_ = step(0.5, 1.5, 0.1);
    tiers_most_ = integer(3, 6);
    pavilion_air_ = step(0.3, 1.0, 0.1);

    // Bay kinds: one for the whole front, or 2-3 chosen once per building.
    std::array<Bay, 4> kinds = kBays;
    for (std::size_t i = kinds.size(); i > 1; --i)
      std::swap(kinds[i - 1], kinds[static_cast<std::size_t>(rng_.uniform() * static_cast<double>(i))]);
    // A choice per tile takes a kind of its own: two kinds at most are
    // kept per building then.
    const bool per_tile = on(StyleClass::TileChoice);
    const std::size_t count =
        on(StyleClass::KeptChoice) ? static_cast<std::size_t>(integer(2, per_tile ? 2 : 3)) : 1;
    bay_kinds_.assign(kinds.begin(), kinds.begin() + static_cast<std::ptrdiff_t>(count));
    odd_bay_ = kinds[count];  // above the door bay, or the special one
    if (per_tile) {
      tile_bay_ = kinds[count + 1];
      tile_odds_ = integer(2, 4);
    }

    if (on(StyleClass::LinearSize)) {
      podium_lo_ = step(3.5, 4.5, 0.1);
      podium_hi_ = tidy(podium_lo_ + step(1.0, 2.5, 0.1));
      slope_ = std::array{0.5, 1.5, 2.0, 2.5, 3.0}[static_cast<std::size_t>(integer(0, 4))];
      // At least one storey above the podium.
      const double least = std::max(0.5, storey_ + 0.5 - slope_ * podium_lo_);
      offset_ = tidy(std::ceil(rng_.uniform(least, std::max(least, 6.0)) * 2) / 2);
    } else if (on(StyleClass::GroundFloor)) {
      ground_ = free_size(3.6, 5.0, 0.1, false);
    }
    const double crown = on(StyleClass::RecursiveTiers) ? 0.8 * tiers_most_ : 1.0;
    if (!on(StyleClass::LinearSize)) {
      roof_share_ = chance(0.5);
      roof_ = roof_share_ ? free_size(0.25, 0.6, 0.05, true)
                          : free_size(std::max(1.5, crown), std::max(3.5, crown + 2), 0.1, false);
    }
    if (annex_walls_share()) annex_walls_ = free_size(1.2, 3.0, 0.1, true);
    window_width_ = on(StyleClass::MixedSplit) ? step(0.9, 0.35 * tile_, 0.1) : step(1.0, 2.5, 0.1);
    annex_window_ = on(StyleClass::MixedSplit) ? step(0.8, 0.35 * annex_tile_, 0.1) : step(1.0, 2.5, 0.1);
    // A style with continuous sizes has at least one: the windows' width.
    if (on(StyleClass::ContinuousSizes) && (draws_ == 0 || chance(0.3))) {
      const double hi = on(StyleClass::MixedSplit) ? 0.35 * tile_ : 2.5;
      window_size_ = drawn_size(window_width_ * 0.8, std::max(window_width_ * 0.8 + 0.3, hi), 0.05,
                                on(StyleClass::MixedSplit) ? "" : "~");
    } else {
      window_size_ = {(on(StyleClass::MixedSplit) ? "" : "~") + num(window_width_), window_width_, window_width_};
    }

    // What the main block must hold: across (x), in depth (y), in height.
    const bool k_row = on(StyleClass::AlignedRepeat) || special_ == Special::Ground || special_ == Special::Storeys;
    const double tiers = on(StyleClass::RecursiveTiers) ? 2 * margin_ * (tiers_most_ - 1) + 2.5 : 0.0;
    main_width_ = std::max({2 * tile_, k_row ? tile_ * (k_most_ + 2) : 0.0, tiers,
                            ground_zone_ && !k_row ? 2 * shop_tile_ : 0.0}) +
                  (piers_ ? 2 * pier_width_ : 0.0);
    main_depth_ = std::max(5.0, tiers);
    const double cornice = cornice_zone_ ? cornice_height_ : 0.0;
    if (on(StyleClass::LinearSize)) {
      main_height_ = podium_hi_ * (1 + slope_) + offset_ + cornice + crown;
    } else {
      const double ground = on(StyleClass::GroundFloor) ? ground_.hi : on(StyleClass::AlignedRepeat) ? storey_ : 0.0;
      main_height_ =
          ground + cornice +
          (roof_share_ ? std::max(storey_ * (1 + roof_.hi), crown * (1 + roof_.lo) / roof_.lo) : roof_.hi + storey_);
    }
    annex_length_ = special_ == Special::Annexes ? annex_tile_ * (annex_k_most_ + 2) : annex_tile_;
  }

  double far_tile(double lo, double hi) {
    const double gap = step(0.6, 1.2, 0.1);
    return tile_ + gap <= hi && (tile_ - gap < lo || chance(0.5)) ? tidy(tile_ + gap) : tidy(tile_ - gap);
  }

  // The plan's sizes, and what the plot must be at least to hold them.
  void choose_plan_sizes() {
    double x = main_width_, y = main_depth_, z = main_height_;
    if (annex_walls_share()) {
      // Annex walls a share of the height: tall enough for a door.
      z = std::max(z, (door_height_ + 0.6) * (1 + annex_walls_.lo) / annex_walls_.lo);
    }
    switch (plan_) {
      case Plan::Single:
        break;
      case Plan::Row: {
        main_share_ = free_size(1.5, 3.0, 0.1, true);
        const int annexes = on(StyleClass::SharedSize) ? 2 : integer(1, 2);
        for (int i = 0; i < annexes; ++i) row_annex_.push_back(free_size(0.6, 1.4, 0.1, true));
        if (yard_) yard_size_ = free_size(0.3, 0.8, 0.1, true);
        std::vector<Size> others = row_annex_;
        if (yard_) others.push_back(yard_size_);
        x = std::max(x, main_width_ / least_share(main_share_, others));
        for (std::size_t i = 0; i < row_annex_.size(); ++i) {
          std::vector<Size> rest{main_share_};
          if (yard_) rest.push_back(yard_size_);
          for (std::size_t j = 0; j < row_annex_.size(); ++j)
            if (j != i) rest.push_back(row_annex_[j]);
          x = std::max(x, std::max(annex_length_, 3.0) / least_share(row_annex_[i], rest));
        }
        row_main_at_ = integer(0, static_cast<int>(row_annex_.size()));
        yard_at_ = integer(1, static_cast<int>(row_annex_.size()));
        break;
      }
      case Plan::Hall: {
        main_share_ = free_size(1.5, 3.0, 0.1, true);
        aisle_ = free_size(0.6, 1.2, 0.1, true);
        x = std::max(x, annex_length_);
        y = std::max(main_depth_ / least_share(main_share_, {aisle_, aisle_}),
                     3.0 / least_share(aisle_, {aisle_, main_share_}));
        break;
      }
      case Plan::L: {
        wing_left_ = chance(0.5);
        if (on(StyleClass::SharedSize)) {
          depth_ = shared_range(std::max(5.0, main_depth_));
          y = std::max(y, depth_.hi + std::max(annex_length_, 3.0));
          x = std::max(x, depth_.hi + 4);
        } else {
          range_ = free_size(0.5, 1.2, 0.05, true);
          wing_ = free_size(0.4, 0.9, 0.05, true);
          const Size one{"~1", 1, 1};
          y = std::max(main_depth_ / least_share(range_, {one}),
                       std::max(annex_length_, 3.0) / least_share(one, {range_}));
          x = std::max({x, 4 / least_share(wing_, {one}), 4 / least_share(one, {wing_})});
        }
        break;
      }
      case Plan::U: {
        court_ = free_size(0.4, 1.0, 0.05, true);
        const Size one{"~1", 1, 1};
        y = std::max({y, main_depth_ / least_share(one, {court_}), annex_length_});
        if (on(StyleClass::SharedSize)) {
          depth_ = shared_range(4.0);
          x = std::max(x, main_width_ + 2 * depth_.hi);
        } else {
          // Wings of different shares: one size drawn once is the shared class's.
          const double a = step(0.6, 1.0, 0.05);
          double b = step(0.6, 1.0, 0.05);
          if (std::abs(a - b) < 0.1) b = tidy(a > 0.8 ? a - 0.2 : a + 0.2);
          wing_a_ = {"~" + num(a), a, a};
          wing_b_ = {"~" + num(b), b, b};
          middle_ = free_size(2.0, 3.5, 0.1, true);
          x = std::max({x, main_width_ / least_share(middle_, {wing_a_, wing_b_}),
                        4 / least_share(wing_a_, {middle_, wing_b_})});
        }
        break;
      }
      case Plan::Courtyard: {
        if (on(StyleClass::SharedSize)) {
          depth_ = shared_range(std::max(5.0, main_depth_));
          x = std::max(x, main_width_ + 2 * depth_.hi);
          x = std::max(x, annex_length_ + 2 * depth_.hi);
          y = std::max({y, 2 * depth_.hi + 4, annex_length_});
        } else {
          // Four depths in metres, no two alike.
          for (double& d : court_depths_) d = step(4.0, 7.0, 0.1);
          court_depths_[1] = std::max(court_depths_[1], tidy(std::ceil(main_depth_ * 10) / 10));
          for (std::size_t i = 1; i < court_depths_.size(); ++i)
            for (std::size_t j = 0; j < i; ++j)
              if (std::abs(court_depths_[i] - court_depths_[j]) < 0.05)
                court_depths_[i] = tidy(court_depths_[i] + 0.3 * static_cast<double>(i));
          const double sides = court_depths_[0] + court_depths_[3];
          x = std::max({x, main_width_ + sides, annex_length_ + sides});
          y = std::max({y, court_depths_[1] + court_depths_[2] + 4, annex_length_});
        }
        break;
      }
    }
    if (on(StyleClass::SharedSize) && !annexes_y()) {
      // Annex walls of one height h, drawn once; the roofs above take the rest.
      height_ = shared_range(std::max(4.0, door_height_ + 0.6));
      z = std::max(z, height_.hi + 1.5);
    }
    least_ = {x, y, z};
  }

  // A size drawn once per building (passed down as a parameter).
  Size shared_range(double lo) {
    const double a = tidy(std::ceil(rng_.uniform(lo, lo + 1.0) * 10) / 10);
    const double b = tidy(a + step(1.0, 3.0, 0.1));
    return {"rand(" + num(a) + ", " + num(b) + ")", a, b};
  }

  void choose_plot() {
    const std::array<double, 3> base{8.0, 6.0, 5.0};
    for (std::size_t i = 0; i < 3; ++i) {
      const double lo = ceil_half(std::max(least_[i], base[i]) * step(1.0, 1.25, 0.05));
      plot_[i] = {lo, ceil_half(lo * (1 + step(0.3, 0.8, 0.05)))};
    }
  }

  // ---- writing ----

  std::string write() {
    std::string out = "# A random style (evaluate --random-styles), seed " + std::to_string(seed_) + ".\n# Classes:";
    for (std::size_t i = 0; i < kStyleClasses.size(); ++i)
      if (on_[i]) out += " " + std::string(kStyleClasses[i].name);
    out += "\n";
    names();
    rules_.clear();
    write_plan();
    write_main();
    write_annexes();
    out += "@start " + plot_name_ + "\n@scope ";
    for (std::size_t i = 0; i < 3; ++i)
      out += (i ? ", " : "") + std::string("rand(") + num(plot_[i][0]) + ", " + num(plot_[i][1]) + ")";
    out += "\n\n";
    for (const std::string& r : rules_) out += r + "\n";
    return out;
  }

  void names() {
    plot_name_ = rule_name(Words<4>{"plot", "site", "lot", "parcel"});
    plan_name_ = rule_name(Words<4>{"layout", "plan", "estate", "ensemble"});
    main_name_ = rule_name(Words<6>{"hall", "block", "house", "range", "front", "mansion"});
    body_name_ = rule_name(Words<4>{"body", "mass", "core", "shell"});
    ground_name_ = rule_name(Words<4>{"ground", "groundFloor", "shops", "arcade"});
    storey_name_ = rule_name(Words<4>{"storey", "floor", "level", "upper"});
    row_name_ = rule_name(Words<3>{"row", "sequence", "rhythm"});
    bay_name_ = rule_name(Words<4>{"bay", "opening", "travee", "unit"});
    odd_name_ = rule_name(Words<3>{"axis", "feature", "accent"});
    door_bay_name_ = rule_name(Words<3>{"doorBay", "entry", "porch"});
    shop_name_ = rule_name(Words<3>{"shop", "store", "booth"});
    tiers_name_ = rule_name(Words<4>{"tiers", "pagoda", "stack", "setback"});
    pavilion_name_ = rule_name(Words<3>{"pavilion", "lantern", "belvedere"});
    leaf_name_ = rule_name(Words<4>{"cap", "covering", "ridge", "gables"});
    annex_x_ = rule_name(Words<5>{"annex", "aisle", "side", "shed", "lodge"});
    annex_y_ = rule_name(Words<4>{"wing", "arm", "flank", "ell"});
    annex_bay_x_ = annex_x_ + "Bay";
    annex_bay_y_ = annex_y_ + "Bay";
    annex_row_x_ = annex_x_ + "Row";
    annex_row_y_ = annex_y_ + "Row";
    annex_door_x_ = annex_x_ + "Door";
    annex_door_y_ = annex_y_ + "Door";
    annex_leaf_ = rule_name(Words<3>{"annexRoof", "lowRoof", "sideRoof"});
  }

  void rule(const std::string& text) { rules_.push_back(text); }

  // ---- the plan ----

  std::string main_call() {
    std::vector<std::string> args;
    if (on(StyleClass::LinearSize)) args.push_back("rand(" + num(podium_lo_) + ", " + num(podium_hi_) + ")");
    if (on(StyleClass::AlignedRepeat)) args.push_back("randint(0, " + std::to_string(k_most_) + ")");
    if (on(StyleClass::KeptChoice)) args.push_back("randint(0, " + std::to_string(bay_kinds_.size() - 1) + ")");
    return main_name_ + call_args(args);
  }
  static std::string call_args(const std::vector<std::string>& args) {
    if (args.empty()) return "";
    std::string s = "(";
    for (std::size_t i = 0; i < args.size(); ++i) s += (i ? ", " : "") + args[i];
    return s + ")";
  }
  std::string main_params() const {
    std::vector<std::string> p;
    if (on(StyleClass::LinearSize)) p.push_back("u");
    if (on(StyleClass::AlignedRepeat)) p.push_back("k");
    if (on(StyleClass::KeptChoice)) p.push_back("b");
    return call_args(p);
  }
  // An annex: its rule, with the shared wall height where there is one.
  std::string annex(bool along_y) const { return (along_y ? annex_y_ : annex_x_) + (annex_walls_share() ? "" : "(h)"); }

  void write_plan() {
    const bool shared = on(StyleClass::SharedSize);
    // The start rule takes no parameters: a size drawn once is drawn there
    // and passed to the plan.
    const std::string plan = shared ? plan_name_ + (annexes_y() ? "(d)" : "(h)") : plot_name_;
    if (shared) rule(plot_name_ + " --> " + plan_name_ + "(" + (annexes_y() ? depth_.text : height_.text) + ")");
    switch (plan_) {
      case Plan::Single:
        rule(plot_name_ + " --> " + main_call());
        break;
      case Plan::Row: {
        std::vector<std::string> parts;
        for (std::size_t i = 0; i < row_annex_.size(); ++i) parts.push_back(row_annex_[i].text + " : " + annex(false));
        parts.insert(parts.begin() + row_main_at_, main_share_.text + " : " + main_call());
        if (yard_) parts.insert(parts.begin() + yard_at_, yard_size_.text + " : nil");
        std::string body = "split(x){ ";
        for (std::size_t i = 0; i < parts.size(); ++i) body += (i ? " | " : "") + parts[i];
        rule(plan + " --> " + body + " }");
        break;
      }
      case Plan::Hall:
        rule(plan + " --> split(y){ " + aisle_.text + " : " + annex(false) + " | " + main_share_.text + " : " +
             main_call() + " | " + aisle_.text + " : " + annex(false) + " }");
        break;
      case Plan::L: {
        const std::string range = shared ? "d" : range_.text;
        const std::string wing = (shared ? "d" : wing_.text) + " : " + annex(true);
        const std::string garden =
            wing_left_ ? "split(x){ " + wing + " | ~1 : nil }" : "split(x){ ~1 : nil | " + wing + " }";
        rule(plan + " --> split(y){ " + range + " : " + main_call() + " | ~1 : " + garden + " }");
        break;
      }
      case Plan::U: {
        const std::string middle = "split(y){ " + court_.text + " : nil | ~1 : " + main_call() + " }";
        if (shared)
          rule(plan + " --> split(x){ d : " + annex(true) + " | ~1 : " + middle + " | d : " + annex(true) + " }");
        else
          rule(plan + " --> split(x){ " + wing_a_.text + " : " + annex(true) + " | " + middle_.text + " : " + middle +
               " | " + wing_b_.text + " : " + annex(true) + " }");
        break;
      }
      case Plan::Courtyard: {
        std::array<std::string, 4> d{"d", "d", "d", "d"};
        if (!shared)
          for (std::size_t i = 0; i < 4; ++i) d[i] = num(court_depths_[i]);
        rule(plan + " --> split(x){ " + d[0] + " : " + annex(true) + " | ~1 : split(y){ " + d[1] + " : " + main_call() +
             " | ~1 : nil | " + d[2] + " : " + annex(false) + " } | " + d[3] + " : " + annex(true) + " }");
        break;
      }
    }
  }

  // ---- the main block ----

  std::string bay_call() const { return bay_name_ + (on(StyleClass::KeptChoice) ? "(b)" : ""); }

  void write_main() {
    const bool linear = on(StyleClass::LinearSize), aligned = on(StyleClass::AlignedRepeat);
    const std::string params = main_params();
    std::vector<std::string> zones;
    if (ground_zone_) {
      const std::string size = linear ? "u" : on(StyleClass::GroundFloor) ? ground_.text : num(storey_);
      std::string ground = ground_name_;
      if (aligned)
        ground += "(k)";
      else if (special_ == Special::Ground)
        ground += "(randint(0, " + std::to_string(k_most_) + "))";
      zones.push_back(size + " : " + ground);
    }
    std::vector<std::string> storey_args;
    if (aligned) storey_args.push_back("k");
    if (on(StyleClass::KeptChoice)) storey_args.push_back("b");
    const std::string storeys = "repeat(z, " + num(storey_) + "){ " + storey_name_ + call_args(storey_args) + " }";
    zones.push_back((linear ? num(slope_) + " * u + " + num(offset_) : "~1") + " : " + storeys);
    if (cornice_zone_) zones.push_back(num(cornice_height_) + " : I(" + cornice_ + ")");
    std::string crown;
    if (on(StyleClass::RecursiveTiers))
      crown = tiers_name_ + "(randint(2, " + std::to_string(tiers_most_) + "))";
    else
      crown = top_ == Top::Pavilion ? pavilion_name_ : leaf_name_;
    zones.push_back((linear ? "~1" : roof_.text) + " : " + crown);
    std::string elevation = "split(z){ ";
    for (std::size_t i = 0; i < zones.size(); ++i) elevation += (i ? " | " : "") + zones[i];
    elevation += " }";
    if (piers_) {
      const std::string pier = num(pier_width_) + " : I(" + pillar_ + ")";
      rule(main_name_ + params + " --> split(x){ " + pier + " | ~1 : " + body_name_ + params + " | " + pier + " }");
      rule(body_name_ + params + " --> " + elevation);
    } else {
      rule(main_name_ + params + " --> " + elevation);
    }

    write_ground();
    write_storeys();
    write_bays();
    write_crown();
  }

  // A run of tiles along `axis` with a special one after `index` of them:
  // `t * k : repeatN(x, k){ tile } | t : special | ~1 : repeat(x, t){ tile }`.
  static std::string run_with(const std::string& axis, double tile, const std::string& index,
                              const std::string& tile_call, const std::string& special) {
    return "split(" + axis + "){ " + num(tile) + " * " + index + " : repeatN(" + axis + ", " + index + "){ " +
           tile_call + " } | " + num(tile) + " : " + special + " | ~1 : repeat(" + axis + ", " + num(tile) + "){ " +
           tile_call + " } }";
  }

  void write_ground() {
    if (!ground_zone_) return;
    const bool shops = on(StyleClass::GroundFloor);
    const std::string tile = shops ? shop_name_ : bay_name_ + (on(StyleClass::KeptChoice) ? "(0)" : "");
    if (on(StyleClass::AlignedRepeat) || special_ == Special::Ground) {
      rule(ground_name_ + "(k) --> " + run_with("x", tile_, "k", tile, door_bay_name_));
      rule(door_bay_name_ + " --> " + door_bay("x", door_width_, wall_));
    } else if (shops) {
      rule(ground_name_ + " --> repeat(x, " + num(shop_tile_) + "){ " + shop_name_ + " }");
    } else {
      rule(ground_name_ + " --> I(" + plinth_ + ")");
    }
    if (shops) {
      const std::string side = on(StyleClass::MixedSplit) ? num(pillar_width_) : "~1";
      const std::string glass =
          on(StyleClass::MixedSplit) ? "~1" : "~" + num(std::round(shop_tile_ / pillar_width_ / 2));
      rule(shop_name_ + " --> split(x){ " + side + " : I(" + pillar_ + ") | " + glass + " : I(" + shop_ + ") | " +
           side + " : I(" + pillar_ + ") }");
    }
  }

  std::string door_bay(const std::string& axis, double width, const std::string& wall) const {
    return "split(" + axis + "){ ~1 : I(" + wall + ") | " + num(width) + " : split(z){ " + num(door_height_) + " : I(" +
           door_ + ") | ~1 : I(" + wall + ") } | ~1 : I(" + wall + ") }";
  }

  void write_storeys() {
    const bool kept = on(StyleClass::KeptChoice);
    if (on(StyleClass::AlignedRepeat)) {
      rule(storey_name_ + (kept ? "(k, b)" : "(k)") + " --> " + run_with("x", tile_, "k", bay_call(), odd_name_));
    } else if (special_ == Special::Storeys) {
      // Each storey draws where its special bay stands.
      rule(storey_name_ + (kept ? "(b)" : "") + " --> " + row_name_ + "(randint(0, " + std::to_string(k_most_) + ")" +
           (kept ? ", b)" : ")"));
      rule(row_name_ + (kept ? "(k, b)" : "(k)") + " --> " + run_with("x", tile_, "k", bay_call(), odd_name_));
    } else {
      rule(storey_name_ + (kept ? "(b)" : "") + " --> repeat(x, " + num(tile_) + "){ " + bay_call() + " }");
    }
  }

  void write_bays() {
    // With a choice per tile, each bay is its kind or, at lower odds, a
    // kind of the tiles' own, drawn bay by bay.
    const bool per_tile = on(StyleClass::TileChoice);
    const std::string odds = per_tile ? " : " + std::to_string(tile_odds_) : "";
    if (on(StyleClass::KeptChoice)) {
      for (std::size_t i = 0; i < bay_kinds_.size(); ++i) {
        const std::string head = bay_name_ + "(b) : b == " + std::to_string(i) + " --> ";
        rule(head + bay(bay_kinds_[i]) + odds);
        if (per_tile) rule(head + bay(tile_bay_));
      }
    } else {
      rule(bay_name_ + " --> " + bay(bay_kinds_[0]) + odds);
      if (per_tile) rule(bay_name_ + " --> " + bay(tile_bay_));
    }
    if (on(StyleClass::AlignedRepeat) || special_ == Special::Storeys) rule(odd_name_ + " --> " + bay(odd_bay_));
  }

  // A bay of the main front: wall | opening | wall along x, the opening
  // `window_size_` wide (metres, or a share when splits are not mixed).
  std::string bay(Bay kind) const {
    const bool mixed = on(StyleClass::MixedSplit);
    const std::string wall = "I(" + wall_ + ")";
    std::string opening;
    switch (kind) {
      case Bay::Window:
        opening = mixed ? "split(z){ " + num(sill_) + " : " + wall + " | ~1 : I(" + window_ + ") | " + num(lintel_) +
                              " : " + wall + " }"
                        : "split(z){ ~1 : " + wall + " | ~2 : I(" + window_ + ") | ~0.5 : " + wall + " }";
        break;
      case Bay::Balcony:
        opening = mixed ? "split(z){ " + num(balcony_height_) + " : I(" + balcony_ + ") | ~1 : I(" + window_ + ") | " +
                              num(lintel_) + " : " + wall + " }"
                        : "split(z){ ~1 : I(" + balcony_ + ") | ~2 : I(" + window_ + ") }";
        break;
      case Bay::Pair:
        opening = "split(x){ ~1 : I(" + window_ + ") | ~0.4 : " + wall + " | ~1 : I(" + window_ + ") }";
        break;
      case Bay::Panel:
        opening = "I(" + panel_ + ")";
        break;
    }
    return "split(x){ ~1 : " + wall + " | " + window_size_.text + " : " + opening + " | ~1 : " + wall + " }";
  }

  void write_crown() {
    if (on(StyleClass::RecursiveTiers)) {
      const std::string m = num(margin_) + " : nil";
      rule(tiers_name_ + "(n) : n > 1 --> split(z){ ~1 : I(" + tier_ + ") | ~(n - 1) : split(x){ " + m +
           " | ~1 : split(y){ " + m + " | ~1 : " + tiers_name_ + "(n - 1) | " + m + " } | " + m + " } }");
      rule(tiers_name_ + "(n) : n <= 1 --> " + (top_ == Top::Pavilion ? pavilion_name_ : leaf_name_));
    }
    if (top_ == Top::Pavilion) {
      const std::string air = "~" + num(pavilion_air_) + " : nil";
      rule(pavilion_name_ + " --> split(x){ " + air + " | ~1 : " + leaf_name_ + " | " + air + " }");
    }
    // The main roof is turned where the style turns roofs and has no annexes.
    const bool turned = on(StyleClass::TurnedRoof) && !has_annexes();
    if (on(StyleClass::Alternatives)) {
      std::vector<std::string> pieces{roof_piece(turned), "I(hip)", "I(pyramid)",
                                      turned ? "I(roof)" : "R(z, pi / 2){ I(roof) }"};
      const std::size_t count = static_cast<std::size_t>(integer(2, 3));
      for (std::size_t i = 0; i < count; ++i) {
        const int priority = i == 0 ? integer(2, 4) : integer(1, 2);
        rule(leaf_name_ + " --> " + pieces[i] + " : " + std::to_string(priority));
      }
    } else {
      rule(leaf_name_ + " --> " +
           (turned ? roof_piece(true) : std::string(pick(Words<3>{"I(roof)", "I(hip)", "I(pyramid)"}))));
    }
  }

  static std::string roof_piece(bool turned) { return turned ? "R(z, pi / 2){ I(roof) }" : "I(roof)"; }

  // ---- the annexes ----

  void write_annexes() {
    if (!has_annexes()) return;
    for (const bool along_y : {false, true}) {
      if (along_y ? !annexes_y() : !annexes_x()) continue;
      const std::string axis = along_y ? "y" : "x";
      const std::string& bay = along_y ? annex_bay_y_ : annex_bay_x_;
      const std::string& row = along_y ? annex_row_y_ : annex_row_x_;
      const std::string& door = along_y ? annex_door_y_ : annex_door_x_;
      // The special tile goes on the annexes that run along y where there
      // are such, else along x.
      const bool special = special_ == Special::Annexes && along_y == annexes_y();
      const std::string walls = special ? row + "(randint(0, " + std::to_string(annex_k_most_) + "))"
                                        : "repeat(" + axis + ", " + num(annex_tile_) + "){ " + bay + " }";
      const std::string height = annex_walls_share() ? annex_walls_.text : "h";
      rule(annex(along_y) + " --> split(z){ " + height + " : " + walls + " | ~1 : " + annex_leaf_ + " }");
      if (special) {
        rule(row + "(k) --> " + run_with(axis, annex_tile_, "k", bay, door));
        rule(door + " --> " + door_bay(axis, std::min(door_width_, annex_tile_ - 1.2), annex_wall_));
      }
      const std::string wall = "I(" + annex_wall_ + ")";
      const std::string width = on(StyleClass::MixedSplit) ? num(annex_window_) : "~" + num(annex_window_);
      rule(bay + " --> split(" + axis + "){ ~1 : " + wall + " | " + width + " : I(" + window_ + ") | ~1 : " + wall +
           " }");
    }
    const std::string piece =
        on(StyleClass::TurnedRoof) ? roof_piece(true) : std::string(pick(Words<2>{"I(roof)", "I(hip)"}));
    const std::string air = "~" + num(pavilion_air_) + " : nil";
    rule(annex_leaf_ + " --> " +
         (annex_pavilion_ ? "split(x){ " + air + " | ~1 : " + piece + " | " + air + " }" : piece));
  }

  std::uint64_t seed_;
  RandomStream rng_;
  std::array<bool, kStyleClasses.size()> on_{};
  std::set<std::string> used_names_;
  std::vector<std::string> rules_;
  int draws_ = 0;

  // Labels of the parts (primitive names).
  std::string wall_, annex_wall_, window_, door_, pillar_, shop_, balcony_, cornice_, plinth_, tier_, panel_;
  // Rule names.
  std::string plot_name_, plan_name_, main_name_, body_name_, ground_name_, storey_name_, row_name_, bay_name_,
      odd_name_, door_bay_name_, shop_name_, tiers_name_, pavilion_name_, leaf_name_, annex_x_, annex_y_, annex_bay_x_,
      annex_bay_y_, annex_row_x_, annex_row_y_, annex_door_x_, annex_door_y_, annex_leaf_;

  Plan plan_ = Plan::Single;
  Top top_ = Top::Leaf;
  Special special_ = Special::None;
  bool ground_zone_ = false, yard_ = false, piers_ = false, cornice_zone_ = false, roof_share_ = false;
  bool wing_left_ = false, annex_pavilion_ = false;

  double tile_ = 0, storey_ = 0, annex_tile_ = 0, shop_tile_ = 0;
  int k_most_ = 0, annex_k_most_ = 0, tiers_most_ = 0;
  double door_width_ = 0, door_height_ = 0, sill_ = 0, lintel_ = 0, balcony_height_ = 0, pillar_width_ = 0;
  double cornice_height_ = 0, pier_width_ = 0, margin_ = 0, pavilion_air_ = 0;
  double podium_lo_ = 0, podium_hi_ = 0, slope_ = 0, offset_ = 0;
  double window_width_ = 0, annex_window_ = 0;
  std::vector<Bay> bay_kinds_;
  Bay odd_bay_ = Bay::Window;
  Bay tile_bay_ = Bay::Window;  // a tile's other kind
  int tile_odds_ = 1;           // a bay of its kind against one of tile_bay_, tile by tile
  Size ground_, roof_, annex_walls_, window_size_;
  double main_width_ = 0, main_depth_ = 0, main_height_ = 0, annex_length_ = 0;

  Size main_share_, yard_size_, aisle_, range_, wing_, court_, wing_a_, wing_b_, middle_, depth_, height_;
  std::vector<Size> row_annex_;
  std::ptrdiff_t row_main_at_ = 0, yard_at_ = 0;
  std::array<double, 4> court_depths_{};
  std::array<double, 3> least_{};
  std::array<std::array<double, 2>, 3> plot_{};
};

}  // namespace

std::string_view class_name(StyleClass c) { return kStyleClasses[static_cast<std::size_t>(c)].name; }

bool RandomStyle::has(StyleClass c) const { return std::find(classes.begin(), classes.end(), c) != classes.end(); }

RandomStyle random_style(std::uint64_t seed) { return StyleMaker(seed).run(); }

std::uint64_t random_style_seed(std::uint64_t run_seed, std::uint32_t index) {
  return child_key(mix64(run_seed), index);
}

}  // namespace vern
