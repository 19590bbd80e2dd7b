#include "eval/class_means.hpp"

#include <algorithm>

namespace vern {

namespace {

void add(ClassMeans& m, const StyleScores& s) {
  ++m.styles;
  for (std::size_t c = 0; c < m.precision.size(); ++c) {
    m.precision[c] += s.precision[c];
    m.recall[c] += s.recall[c];
  }
}

void divide(ClassMeans& m) {
  if (m.styles == 0) return;
  for (std::size_t c = 0; c < m.precision.size(); ++c) {
    m.precision[c] /= m.styles;
    m.recall[c] /= m.styles;
  }
}

}  // namespace

ClassTable class_means(const std::vector<StyleScores>& styles, const std::vector<std::uint32_t>& counts) {
  const ClassMeans empty{0, std::vector<double>(counts.size(), 0.0), std::vector<double>(counts.size(), 0.0)};
  ClassTable t;
  t.classes.assign(kStyleClasses.size(), empty);
  t.all = empty;
  const std::size_t largest =
      counts.empty() ? 0 : static_cast<std::size_t>(std::max_element(counts.begin(), counts.end()) - counts.begin());
  for (const StyleScores& s : styles) {
    add(t.all, s);
    for (StyleClass c : s.classes) add(t.classes[static_cast<std::size_t>(c)], s);
    if (!counts.empty() && s.precision[largest] <= 0.25) ++t.low_precision;
  }
  divide(t.all);
  for (ClassMeans& m : t.classes) divide(m);
  return t;
}

}  // namespace vern
