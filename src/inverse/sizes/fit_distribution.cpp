#include "inverse/sizes/fit_distribution.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>

// Ceres stays in this translation unit (compile time).
#include <ceres/autodiff_first_order_function.h>
#include <ceres/gradient_problem.h>
#include <ceres/gradient_problem_solver.h>

#include "base/error.hpp"
#include "inverse/sizes/tidy_numbers.hpp"

namespace vern {

namespace {

// Negative log-likelihood of a normal(mu, exp(log_sigma)) truncated to
// [lo, hi], over weighted observations, without the constant terms.
struct TruncatedNormalCost {
  const std::vector<Observation>* data;
  double lo, hi;

  template <class T>
  bool operator()(const T* p, T* cost) const {
    using std::erf, std::log, std::exp, std::sqrt;
    const T mu = p[0];
    const T sigma = exp(p[1]);
    const T inv = T(1) / (sigma * T(std::numbers::sqrt2));
    const T mass = (erf((T(hi) - mu) * inv) - erf((T(lo) - mu) * inv)) * T(0.5);
    T total = T(0), n = T(0);
    for (const Observation& o : *data) {
      const T z = (T(o.value) - mu) / sigma;
      total += T(o.count) * (T(0.5) * z * z);
      n += T(o.count);
    }
    *cost = total + n * (log(sigma) + log(mass + T(1e-300)));
    return true;
  }
};

double total_count(const std::vector<Observation>& data) {
  double n = 0;
  for (const Observation& o : data) n += o.count;
  return n;
}

// Distinct values: sorted observations joined while a cluster spans at
// most the resolution; each cluster's middle stands for it.
std::vector<Observation> distinct(std::vector<Observation> data, double resolution) {
  std::sort(data.begin(), data.end(), [](const Observation& a, const Observation& b) { return a.value < b.value; });
  std::vector<Observation> out;
  double first = 0;
  for (const Observation& o : data) {
    if (!out.empty() && o.value - first <= resolution) {
      out.back().count += o.count;
      out.back().value = (first + o.value) / 2;
    } else {
      out.push_back(o);
      first = o.value;
    }
  }
  return out;
}

double normal_log_density(double z) { return -0.5 * z * z - 0.5 * std::log(2 * std::numbers::pi); }

double normal_cdf(double z) { return 0.5 * std::erfc(-z / std::numbers::sqrt2); }

// The observations with each example's value counted once: of the
// observations of one known example within the resolution of each other,
// the first stays.
std::vector<Observation> once_per_example(const std::vector<Observation>& observations, double resolution) {
  if (std::ranges::none_of(observations, [](const Observation& o) { return o.example >= 0; })) return observations;
  std::vector<Observation> sorted = observations;
  std::stable_sort(sorted.begin(), sorted.end(), [](const Observation& a, const Observation& b) {
    return a.example != b.example ? a.example < b.example : a.value < b.value;
  });
  std::vector<Observation> out;
  for (const Observation& o : sorted) {
    if (o.example >= 0 && !out.empty() && out.back().example == o.example && o.value - out.back().value <= resolution)
      continue;
    out.push_back(o);
  }
  return out;
}

// even_row (fit_distribution.hpp) of distinct values (distinct()), seen n
// times in all.
std::optional<std::vector<double>> row_through(const std::vector<Observation>& values, double n, double resolution) {
  if (values.size() < 3) return std::nullopt;
  double gap = values[1].value - values[0].value;
  for (std::size_t i = 2; i < values.size(); ++i) gap = std::min(gap, values[i].value - values[i - 1].value);
  const double first = values.front().value, span = values.back().value - first;
  for (int share = 1; share <= 4; ++share) {
    const double step = gap / share;
    const double points = std::round(span / step) + 1;
    if (step <= 10 * resolution || points > 2 * static_cast<double>(values.size())) break;
    const bool on_row = std::ranges::all_of(values, [&](const Observation& o) {
      const double at = (o.value - first) / step;
      return std::abs(at - std::round(at)) * step <= resolution;
    });
    if (!on_row) continue;
    // Some values must repeat: ten values spread evenly by design, each
    // seen once, are a range, and three pillars of 1.43, 2.145 and 2.86 m
    // over four plots say little.
    if (n < points + 2) return std::nullopt;
    // Spaced by the row's own step over its whole span: no drift.
    const double spaced = span / (points - 1);
    std::vector<double> out;
    for (double k = 0; k < points; ++k) out.push_back(first + k * spaced);
    return out;
  }
  return std::nullopt;
}

}  // namespace

namespace {

// The shortest decimal in [a, b] (a <= b).
double shortest_within(double a, double b) { return shortest_decimal((a + b) / 2, (b - a) / 2); }

}  // namespace

Distribution fit_distribution(const std::vector<Observation>& all, const FitOptions& options) {
  if (all.empty()) throw Error(ErrorKind::Internal, "error: a distribution fitted to no observations");
  const std::vector<Observation> observations = once_per_example(all, options.resolution);
  double lo_seen = observations[0].value, hi_seen = lo_seen;
  for (const Observation& o : observations) {
    lo_seen = std::min(lo_seen, o.value);
    hi_seen = std::max(hi_seen, o.value);
  }
  Distribution best;
  if (hi_seen - lo_seen <= options.resolution) {
    best.values = {(lo_seen + hi_seen) / 2};
    return best;
  }
  const double n = total_count(observations);
  if (options.uniform_only || n < 2) {
    best.kind = DistributionKind::Uniform;
    best.lo = lo_seen;
    best.hi = hi_seen;
    return best;
  }

  // Every model's probabilities are per resolution-wide bin.
  const double log_bin = std::log(options.resolution);
  const double widen = (hi_seen - lo_seen) / (n - 1);
  // The widened bounds estimate where the style stops, to a fraction of
  // the widening: each is the shortest decimal within a tenth of it (never
  // inside the values seen, nor below the floor). So they read as a person
  // writes them (rand(2, 19.4), not rand(2.05, 19.433333)), and the
  // examples' float noise stays out (19.433334 from a GLB where the OBJ of
  // the same Blender scene gave 19.433333).
  const double slack = widen / 10;
  const double lo = shortest_within(std::max(options.floor, lo_seen - widen - slack),
                                    std::max(options.floor, std::min(lo_seen - widen + slack, lo_seen)));
  const double hi = shortest_within(std::max(hi_seen + widen - slack, hi_seen), hi_seen + widen + slack);

  // rand(lo, hi).
  best.kind = DistributionKind::Uniform;
  best.lo = lo;
  best.hi = hi;
  best.bic = 2 * std::log(n) - 2 * n * (log_bin - std::log(hi - lo));

  // choice(...) of the values seen, when they repeat.
  const std::vector<Observation> values = distinct(observations, options.resolution);
  const auto m = static_cast<double>(values.size());
  // Values that repeat: a few values seen once beside them may be rare
  // choices, but where most distinct values are seen once (one value
  // seen again and again, the rest spread: a roof squeezed where its
  // building outgrew the plot) the spread is no list to choose from.
  const auto once = static_cast<double>(std::ranges::count_if(values, [](const Observation& o) { return o.count < 2; }));
  if (m <= n / 2 && once <= std::max(1.0, m / 4)) {
    const double bic = m * std::log(n) - 2 * n * std::log(1 / m);
    if (bic < best.bic) {
      best = {};
      best.kind = DistributionKind::Choice;
      for (const Observation& o : values) best.values.push_back(o.value);
      best.bic = bic;
    }
  }

  // choice(...) of every point of an evenly spaced row the values lie on.
  if (const auto row = row_through(values, n, options.resolution)) {
    const double points = static_cast<double>(row->size());
    const double bic = 3 * std::log(n) - 2 * n * std::log(1 / points);
    if (bic < best.bic) {
      best = {};
      best.kind = DistributionKind::Choice;
      best.values = *row;
      best.bic = bic;
    }
  }

  // tnormal(mu, sigma, lo, hi), started from the sample's mean and spread.
  double mean = 0;
  for (const Observation& o : observations) mean += o.count * o.value;
  mean /= n;
  double variance = 0;
  for (const Observation& o : observations) variance += o.count * (o.value - mean) * (o.value - mean);
  variance /= n;
  double p[2] = {mean, std::log(std::max(std::sqrt(variance), options.resolution))};
  ceres::GradientProblem problem(
      new ceres::AutoDiffFirstOrderFunction<TruncatedNormalCost, 2>(new TruncatedNormalCost{&observations, lo, hi}));
  ceres::GradientProblemSolver::Options solver;
  solver.max_num_iterations = 200;
  solver.logging_type = ceres::SILENT;
  ceres::GradientProblemSolver::Summary summary;
  ceres::Solve(solver, problem, p, &summary);
  const double mu = p[0], sigma = std::exp(p[1]);
  if (std::isfinite(mu) && std::isfinite(sigma) && sigma > 0) {
    const double mass = normal_cdf((hi - mu) / sigma) - normal_cdf((lo - mu) / sigma);
    double log_l = 0;
    for (const Observation& o : observations) {
      log_l += o.count * (normal_log_density((o.value - mu) / sigma) - std::log(sigma) - std::log(mass) + log_bin);
    }
    const double bic = 4 * std::log(n) - 2 * log_l;
    // A normal whose peak lies outside its range is a slope, not a bell:
    // tnormal(311, 38, 2.2, 8.2) says "more towards 8" in a way no one
    // reads; the range or the values seen say it plainly enough.
    const bool peaked = mu >= lo && mu <= hi;
    if (mass > 0 && peaked && bic < best.bic) {
      best = {};
      best.kind = DistributionKind::TruncatedNormal;
      best.mu = mu;
      best.sigma = sigma;
      best.lo = lo;
      best.hi = hi;
      best.bic = bic;
    }
  }
  return best;
}

std::optional<std::vector<double>> even_row(const std::vector<double>& seen, double resolution) {
  std::vector<Observation> observed;
  for (const double v : seen) observed.push_back({v, 1});
  return row_through(distinct(std::move(observed), resolution), static_cast<double>(seen.size()), resolution);
}

Distribution fit_size(const std::vector<Observation>& sizes, double resolution, bool uniform_only) {
  double smallest = sizes[0].value;
  for (const Observation& o : sizes) smallest = std::min(smallest, o.value);
  FitOptions fit;
  fit.resolution = resolution;
  fit.floor = smallest / 2;
  fit.uniform_only = uniform_only;
  return fit_distribution(sizes, fit);
}

Expr distribution_expr(const Distribution& d) {
  switch (d.kind) {
    case DistributionKind::Constant: return Expr::number(d.values.at(0));
    case DistributionKind::Choice: {
      std::vector<Expr> args;
      for (const double v : d.values) args.push_back(Expr::number(v));
      return Expr::call(Function::Choice, std::move(args));
    }
    case DistributionKind::Uniform: return Expr::call(Function::Rand, {Expr::number(d.lo), Expr::number(d.hi)});
    case DistributionKind::TruncatedNormal:
      return Expr::call(Function::TNormal,
                        {Expr::number(d.mu), Expr::number(d.sigma), Expr::number(d.lo), Expr::number(d.hi)});
  }
  return Expr::number(0);
}

std::optional<Distribution> written_distribution(const Expr& e) {
  if (const auto v = e.literal()) return Distribution{DistributionKind::Constant, {*v}};
  const ExprNode& root = e.node(e.root());
  if (root.kind != ExprKind::Call || e.nodes().size() != std::size_t{root.argc} + 1) return std::nullopt;
  std::vector<double> args;
  for (std::size_t i = 0; i + 1 < e.nodes().size(); ++i) {
    if (e.node(i).kind != ExprKind::Number) return std::nullopt;
    args.push_back(e.node(i).number);
  }
  Distribution d;
  switch (static_cast<Function>(root.op)) {
    case Function::Choice:
      d.kind = DistributionKind::Choice;
      d.values = std::move(args);
      std::ranges::sort(d.values);
      return d;
    case Function::Rand:
      if (args.size() != 2) return std::nullopt;
      d.kind = DistributionKind::Uniform;
      d.lo = std::min(args[0], args[1]);
      d.hi = std::max(args[0], args[1]);
      return d;
    case Function::TNormal:
      if (args.size() != 4) return std::nullopt;
      d.kind = DistributionKind::TruncatedNormal;
      d.mu = args[0];
      d.sigma = args[1];
      d.lo = args[2];
      d.hi = args[3];
      return d;
    default: return std::nullopt;
  }
}

Distribution short_decimals(Distribution d, double tolerance) {
  for (double& v : d.values) v = shortest_decimal(v, tolerance);
  d.lo = shortest_decimal(d.lo, tolerance);
  d.hi = shortest_decimal(d.hi, tolerance);
  if (d.kind == DistributionKind::TruncatedNormal) {
    d.mu = shortest_decimal(d.mu, std::max(tolerance, d.sigma * 0.01));
    d.sigma = shortest_decimal(d.sigma, std::max(tolerance, d.sigma * 0.01));
  }
  return d;
}

Expr count_expr(std::vector<double> counts) {
  std::sort(counts.begin(), counts.end());
  counts.erase(std::unique(counts.begin(), counts.end()), counts.end());
  if (counts.size() == 1) return Expr::number(counts[0]);
  if (counts.back() - counts.front() + 1 == static_cast<double>(counts.size()))
    return Expr::call(Function::RandInt, {Expr::number(counts.front()), Expr::number(counts.back())});
  std::vector<Expr> seen;
  for (double c : counts) seen.push_back(Expr::number(c));
  return Expr::call(Function::Choice, std::move(seen));
}

}  // namespace vern
