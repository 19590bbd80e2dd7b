// Comparing sets of derived buildings: are two samples in the same style?
//
// Inference is judged by whether its grammar makes buildings like the
// source grammar's (issue 4's evaluation). Two summaries of a building
// are compared across samples:
//   - structure: how many parts of each label a building has;
//   - sizes: the sizes (x, y, z) of the parts of each label, and of the
//     start scope.
// Each is a set of one-dimensional distributions, compared by the
// 1-Wasserstein (earth mover's) distance divided by the reference's mean,
// so 0.1 reads "off by about a tenth of a typical value". A label one
// sample has and the other lacks counts as 1.
#pragma once

#include <string>
#include <vector>

#include "forward/derive.hpp"

namespace vern {

// The 1-Wasserstein distance between the empirical distributions of two
// samples (each value weighing 1/size). 0 when both are empty; the other's
// mean magnitude when one is.
double wasserstein1(std::vector<double> a, std::vector<double> b);

struct StyleDistance {
  double structure = 0;  // mean over labels
  double sizes = 0;      // mean over (label, axis) pairs and the start scope's axes
};

StyleDistance style_distance(const std::vector<Derivation>& reference, const std::vector<Derivation>& candidate);

// Do two derivations hold the same labelled part boxes (world bounds
// within `tolerance`), in any order? Novelty means: the same as no example.
bool same_layout(const Derivation& a, const Derivation& b, double tolerance);

}  // namespace vern
