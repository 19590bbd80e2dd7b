#include "eval/precision_recall.hpp"

#include <algorithm>
#include <atomic>
#include <filesystem>
#include <optional>

#include <unistd.h>

#include "base/error.hpp"
#include "base/parallel_for.hpp"
#include "forward/derive.hpp"
#include "forward/layout_faults.hpp"
#include "forward/primitive_library.hpp"
#include "forward/variants.hpp"
#include "graph/writer.hpp"
#include "inverse/check/check.hpp"
#include "inverse/infer.hpp"
#include "inverse/load/derived_example.hpp"
#include "io/obj_writer.hpp"

namespace fs = std::filesystem;

namespace vern {

namespace {

// Seeds: examples 1..N (as evaluate and the demo draw them), the inferred
// grammar's variants from 1001, fresh source samples from 5001: no fresh
// sample is an example.
constexpr std::uint64_t kVariantSeed = 1001;
constexpr std::uint64_t kFreshSeed = 5001;

Derivation derive_one(const Grammar& g, std::uint64_t seed, std::optional<glm::dvec3> size) {
  DeriveOptions o;
  o.seed = seed;
  o.size = size;
  return derive(g, o);
}

// A folder of its own under the system's temporary folder, removed with it.
class ScratchFolder {
 public:
  ScratchFolder() {
    static std::atomic<unsigned> counter{0};
    std::error_code ec;
    const fs::path base = fs::temp_directory_path(ec);  // TMPDIR, when it names a folder
    if (ec) {
      throw Error(ErrorKind::Io, "error: cannot find a folder for temporary files: " + ec.message() +
                                     "\n  hint: set TMPDIR to a folder that exists, or unset it");
    }
    for (unsigned attempt = 0;; ++attempt) {
      path_ = base / ("vern-precision-" + std::to_string(::getpid()) + "-" + std::to_string(counter++));
      if (fs::create_directory(path_, ec)) return;
      if (attempt > 100) throw Error(ErrorKind::Io, path_.string() + ": error: cannot create a scratch folder");
    }
  }
  ~ScratchFolder() {
    std::error_code ec;
    fs::remove_all(path_, ec);
  }
  ScratchFolder(const ScratchFolder&) = delete;
  ScratchFolder& operator=(const ScratchFolder&) = delete;
  const fs::path& path() const { return path_; }

 private:
  fs::path path_;
};

// The example as a user hands it over: written as labelled OBJ with the
// primitives' meshes (so turned parts show their turn) and read back.
Example through_obj(const Derivation& d, std::uint32_t index, const fs::path& folder) {
  const fs::path file = folder / (variant_name(index) + ".obj");
  OutputFiles scratch(OutputFiles::Durability::Scratch);  // removed with the folder
  write_obj(single(d, index), PrimitiveLibrary::builtin(), file, scratch);
  scratch.commit();
  return load_example(file);
}

// Whether `g` derives `building` on the plot [0, size]; a check that needs
// more than max_steps steps is a miss that says so.
CheckResult derives(const Grammar& g, const Example& building, glm::dvec3 size, std::uint64_t max_steps) {
  CheckOptions o;
  o.witness = false;
  o.max_steps = max_steps;
  try {
    return check_example(g, building.boxes, size, o);
  } catch (const Error& e) {
    if (e.kind() != ErrorKind::Limit) throw;
    CheckResult r;
    r.mismatch = std::string("cannot check: ") + e.what();
    return r;
  }
}

// Runs `judge` on count items in parallel and counts the hits, keeping the
// first miss (lowest index) for the notes.
template <class Judge>
Share count_hits(std::uint32_t count, unsigned threads, std::uint64_t first_seed, Judge judge) {
  std::vector<CheckResult> results(count);
  parallel_for(count, threads, [&](std::size_t i) { results[i] = judge(i); });
  Share s;
  s.total = count;
  for (std::uint32_t i = 0; i < count; ++i) {
    if (results[i].derivable) {
      ++s.hits;
      continue;
    }
    if (results[i].mismatch.find("cannot check") != std::string::npos) ++s.undecided;
    if (s.first_miss.empty()) s.first_miss = "seed " + std::to_string(first_seed + i) + ": " + results[i].mismatch;
  }
  return s;
}

// A fresh source sample as inference would see it: at the origin, its
// extent its plot.
Example as_seen(const Derivation& d) { return at_origin(example_from_derivation(d, "building")); }

}  // namespace

Share self_recall(const Grammar& source, const PrecisionRecallOptions& options) {
  return count_hits(options.samples, options.threads, kFreshSeed, [&](std::size_t i) {
    const Example seen = as_seen(derive_one(source, kFreshSeed + i, std::nullopt));
    return derives(source, seen, example_size(seen), options.max_check_steps);
  });
}

PrecisionRecall precision_recall(const Grammar& source, const PrecisionRecallOptions& options) {
  PrecisionRecall r;
  r.examples = options.examples;

  std::vector<Example> examples(options.examples);
  {
    ScratchFolder folder;
    std::vector<Derivation> derived(options.examples);
    parallel_for(options.examples, options.threads,
                 [&](std::size_t i) { derived[i] = derive_one(source, 1 + i, std::nullopt); });
    for (std::uint32_t i = 0; i < options.examples; ++i) examples[i] = through_obj(derived[i], i, folder.path());
  }
  InferOptions io;
  io.threads = options.threads;
  const Inference learnt = infer(examples, io);
  r.inferred = description_length(learnt.grammar);
  r.inferred_text = write_grammar(learnt.grammar);
  r.inferred_lines = static_cast<std::size_t>(std::count(r.inferred_text.begin(), r.inferred_text.end(), '\n'));

  std::vector<CheckResult> reproduced(examples.size());
  parallel_for(examples.size(), options.threads, [&](std::size_t i) {
    const Example placed = at_origin(examples[i]);
    CheckOptions o;
    o.witness = false;
    reproduced[i] = check_example(learnt.grammar, placed.boxes, example_size(placed), o);
  });
  for (std::size_t i = 0; i < examples.size(); ++i) {
    if (reproduced[i].derivable) {
      ++r.reproduced;
    } else if (r.first_unreproduced.empty()) {
      r.first_unreproduced = examples[i].source + ": " + reproduced[i].mismatch;
    }
  }

  // Variant i is drawn on example (i mod N)'s plot, or that plot widened,
  // and judged where it stands: its plot starts at the origin.
  auto precision_on = [&](double widen) {
    std::vector<std::string> faults(options.samples);
    Share s = count_hits(options.samples, options.threads, kVariantSeed, [&](std::size_t i) {
      glm::dvec3 plot = example_size(examples[i % examples.size()]);
      plot.x *= widen;
      const Derivation v = derive_one(learnt.grammar, kVariantSeed + i, plot);
      const LayoutFaults f = find_faults(v);
      if (!f.valid()) faults[i] = "seed " + std::to_string(kVariantSeed + i) + ": " + f.first;
      return derives(source, example_from_derivation(v, "variant"), plot, options.max_check_steps);
    });
    for (const std::string& f : faults) {
      if (f.empty()) continue;
      ++r.invalid;
      if (r.first_invalid.empty()) r.first_invalid = f;
    }
    return s;
  };
  r.precision = precision_on(1.0);
  r.precision_wider = precision_on(options.wider);

  r.recall = count_hits(options.samples, options.threads, kFreshSeed, [&](std::size_t i) {
    const Example seen = as_seen(derive_one(source, kFreshSeed + i, std::nullopt));
    return derives(learnt.grammar, seen, example_size(seen), options.max_check_steps);
  });
  return r;
}

}  // namespace vern
