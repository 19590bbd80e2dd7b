// Results of random styles read per class (evaluate --random-styles): for
// each class, how many styles contain it and their mean precision and
// recall at each example count, beside the mean over all styles.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "eval/random_style.hpp"

namespace vern {

// One style's scores, one per example count (in the order of the counts).
// An inference that failed scores 0 in both: a failure is a miss, never a
// style left out of the mean.
struct StyleScores {
  std::vector<StyleClass> classes;
  std::vector<double> precision, recall;
};

struct ClassMeans {
  std::uint32_t styles = 0;               // styles that contain the class (all styles for the overall row)
  std::vector<double> precision, recall;  // per count; 0 where no style contains it
};

struct ClassTable {
  std::vector<ClassMeans> classes;  // in kStyleClasses order
  ClassMeans all;
  // Styles whose precision at the largest example count is at most 0.25.
  std::uint32_t low_precision = 0;
};

// `counts`: the example counts, as many as each style has scores.
ClassTable class_means(const std::vector<StyleScores>& styles, const std::vector<std::uint32_t>& counts);

}  // namespace vern
