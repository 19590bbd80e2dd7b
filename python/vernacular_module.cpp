// The Python module vernacular._vernacular: the public C++ API
// (include/vernacular/) for Python, with parts as NumPy arrays and
// errors as exceptions carrying their kind and location. The package
// vernacular (python/vernacular/__init__.py) is what users import.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <vernacular/vernacular.hpp>

namespace py = pybind11;
namespace v = vernacular;

namespace {

// Each part's label, origin, axes and size as arrays, row i for part i:
// what NumPy code works with, without a Python object per part.
py::dict part_arrays(const v::Building& b) {
  using namespace pybind11::literals;
  const auto n = static_cast<py::ssize_t>(b.parts.size());
  py::array_t<double> origins({n, py::ssize_t{3}}), sizes({n, py::ssize_t{3}}), axes({n, py::ssize_t{3}, py::ssize_t{3}});
  auto o = origins.mutable_unchecked<2>();
  auto s = sizes.mutable_unchecked<2>();
  auto a = axes.mutable_unchecked<3>();
  py::list labels;
  for (py::ssize_t i = 0; i < n; ++i) {
    const v::Part& p = b.parts[static_cast<std::size_t>(i)];
    labels.append(p.label);
    for (py::ssize_t k = 0; k < 3; ++k) {
      o(i, k) = p.origin[static_cast<std::size_t>(k)];
      s(i, k) = p.size[static_cast<std::size_t>(k)];
      for (py::ssize_t j = 0; j < 3; ++j) a(i, k, j) = p.axes[static_cast<std::size_t>(k)][static_cast<std::size_t>(j)];
    }
  }
  py::dict out;
  out["labels"] = py::module_::import("numpy").attr("array")(labels, "dtype"_a = "str");
  out["origins"] = origins;
  out["axes"] = axes;
  out["sizes"] = sizes;
  return out;
}

v::DeriveOptions derive_options(std::uint64_t seed, std::optional<v::Vec3> plot, bool strict,
                                std::uint32_t max_depth, std::uint64_t max_parts, std::uint64_t max_operations) {
  v::DeriveOptions o;
  o.seed = seed;
  o.plot = plot;
  o.strict = strict;
  o.max_depth = max_depth;
  o.max_parts = max_parts;
  o.max_operations = max_operations;
  return o;
}

v::Buildings buildings_mode(const std::string& mode) {
  if (mode == "apart") return v::Buildings::Apart;
  if (mode == "parts") return v::Buildings::Parts;
  if (mode == "groups") return v::Buildings::Groups;
  if (mode == "file") return v::Buildings::File;
  throw v::Failure(v::Error{v::ErrorKind::Usage, {}, "buildings='" + mode + "' is none of the modes",
                            "buildings is 'apart' (the default), 'parts', 'groups' or 'file'"});
}

}  // namespace

PYBIND11_MODULE(_vernacular, m) {
  using namespace pybind11::literals;
  m.doc() = "Vernacular: example buildings into a grammar of their style, and the grammar into new buildings.";
  m.attr("__version__") = v::version();

  // Failures become the exception class of their kind, made in Python
  // (vernacular/__init__.py hands them over with _set_errors).
  // Kept past the interpreter's end (never destroyed: there would be no
  // Python left to release it to).
  static py::object& error_classes = *new py::object();
  m.def("_set_errors", [](py::dict classes) { error_classes = classes; });
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const v::Failure& f) {
      const v::Error& e = f.error();
      py::gil_scoped_acquire gil;
      py::object cls = error_classes ? error_classes[py::str(v::to_string(e.kind))] : py::reinterpret_borrow<py::object>(PyExc_RuntimeError);
      py::object exc = cls(f.what());
      if (error_classes) {
        exc.attr("kind") = v::to_string(e.kind);
        exc.attr("file") = e.location.file;
        exc.attr("line") = e.location.line;
        exc.attr("column") = e.location.column;
        exc.attr("message") = e.message;
        exc.attr("hint") = e.hint;
      }
      PyErr_SetObject(cls.ptr(), exc.ptr());
    }
  });

  py::class_<v::Grammar>(m, "Grammar", "A grammar: rules that derive buildings. Grammar.read(file) or Grammar.parse(text).")
      .def_static("read", &v::Grammar::read, "file"_a, "Reads a grammar file (its @primitives relative to its folder).")
      .def_static("parse", &v::Grammar::parse, "text"_a, "name"_a = "<text>", "folder"_a = ".",
                  "Parses grammar text; name stands for the file in errors, folder is where @primitives are found.")
      .def("text", &v::Grammar::text, "The grammar's text as Vernacular writes it.")
      .def("save", &v::Grammar::save, "file"_a, "Writes the text to file (atomically).")
      .def_property_readonly("start", &v::Grammar::start)
      .def_property_readonly("rule_count", &v::Grammar::rule_count)
      .def_property_readonly("file", [](const v::Grammar& g) { return g.file().string(); })
      .def("__repr__", [](const v::Grammar& g) {
        return "<vernacular.Grammar start=" + g.start() + ", " + std::to_string(g.rule_count()) + " rules>";
      });

  py::class_<v::Building>(m, "Building", "A derived building: its parts as arrays, on its plot.")
      .def_property_readonly("plot", [](const v::Building& b) { return b.plot; })
      .def_property_readonly("warnings", [](const v::Building& b) { return b.warnings; })
      .def_property_readonly("parts", &part_arrays,
                             "dict of arrays: labels (n,), origins (n, 3), axes (n, 3, 3: each part's x, y, z axis), "
                             "sizes (n, 3)")
      .def("__len__", [](const v::Building& b) { return b.parts.size(); });

  m.def(
      "derive",
      [](const v::Grammar& g, std::uint64_t seed, std::optional<v::Vec3> plot, bool strict, std::uint32_t max_depth,
         std::uint64_t max_parts, std::uint64_t max_operations) {
        const v::DeriveOptions o = derive_options(seed, plot, strict, max_depth, max_parts, max_operations);
        py::gil_scoped_release release;
        return v::derive(g, o);
      },
      "grammar"_a, "seed"_a = 1, "plot"_a = std::nullopt, "strict"_a = false, "max_depth"_a = 1000,
      "max_parts"_a = 1'000'000, "max_operations"_a = 200'000'000,
      "Derives one building (the same seed, the same building).");
  m.def(
      "derive_many",
      [](const v::Grammar& g, std::uint32_t count, std::uint64_t seed, std::optional<v::Vec3> plot, unsigned threads) {
        const v::DeriveOptions o = derive_options(seed, plot, false, 1000, 1'000'000, 200'000'000);
        py::gil_scoped_release release;
        return v::derive_many(g, count, o, threads);
      },
      "grammar"_a, "count"_a, "seed"_a = 1, "plot"_a = std::nullopt, "threads"_a = 0,
      "count buildings, the i-th with seed + i.");

  m.def(
      "shard",
      [](std::uint32_t total, std::uint32_t k, std::uint32_t n) {
        const v::Slice s = v::shard(total, k, n);
        return py::make_tuple(s.first, s.count);
      },
      "total"_a, "k"_a, "n"_a,
      "(first, count): shard k (1..n) of a run of total buildings, as generate --shard k/n; "
      "derive_many(g, count, seed=seed + first) derives its buildings.");

  py::class_<v::Example>(m, "Example", "An example building: read from a file, or made with Example.from_boxes.")
      .def_static(
          "from_boxes",
          [](const std::vector<std::string>& labels, py::array_t<double, py::array::c_style | py::array::forcecast> boxes,
             const std::string& source) {
            if (boxes.ndim() != 3 || boxes.shape(1) != 2 || boxes.shape(2) != 3 ||
                static_cast<std::size_t>(boxes.shape(0)) != labels.size())
              throw v::Failure(v::Error{v::ErrorKind::Usage, {source}, "boxes must be an (n, 2, 3) array, n = len(labels)",
                                        "give each part's lowest and highest corner: boxes[i] = [[x0, y0, z0], [x1, y1, z1]]"});
            auto b = boxes.unchecked<3>();
            std::vector<v::ExamplePart> parts(labels.size());
            for (std::size_t i = 0; i < labels.size(); ++i) {
              parts[i].label = labels[i];
              for (py::ssize_t k = 0; k < 3; ++k) {
                parts[i].min[static_cast<std::size_t>(k)] = b(static_cast<py::ssize_t>(i), 0, k);
                parts[i].max[static_cast<std::size_t>(k)] = b(static_cast<py::ssize_t>(i), 1, k);
              }
            }
            return v::Example::from_parts(std::move(parts), source);
          },
          "labels"_a, "boxes"_a, "source"_a = "<memory>",
          "An example made in memory: each part's label and box, boxes an (n, 2, 3) array of lowest and highest "
          "corners (z up, metres).")
      .def_property_readonly("source", &v::Example::source)
      .def_property_readonly("notes", &v::Example::notes)
      .def_property_readonly("labels", [](const v::Example& e) {
        py::list out;
        for (const v::ExamplePart& p : e.parts()) out.append(p.label);
        return out;
      })
      .def_property_readonly("boxes", [](const v::Example& e) {
        const auto n = static_cast<py::ssize_t>(e.parts().size());
        py::array_t<double> boxes({n, py::ssize_t{2}, py::ssize_t{3}});
        auto b = boxes.mutable_unchecked<3>();
        for (py::ssize_t i = 0; i < n; ++i)
          for (py::ssize_t k = 0; k < 3; ++k) {
            b(i, 0, k) = e.parts()[static_cast<std::size_t>(i)].min[static_cast<std::size_t>(k)];
            b(i, 1, k) = e.parts()[static_cast<std::size_t>(i)].max[static_cast<std::size_t>(k)];
          }
        return boxes;
      }, "array (n, 2, 3): each part's lowest and highest corner")
      .def("__len__", [](const v::Example& e) { return e.parts().size(); })
      .def("__repr__", [](const v::Example& e) {
        return "<vernacular.Example " + e.source() + ", " + std::to_string(e.parts().size()) + " parts>";
      });

  m.def(
      "read_examples",
      [](const std::vector<std::filesystem::path>& paths, double tolerance, const std::string& buildings,
         const std::string& up, bool outside_files, std::size_t max_parts) {
        v::ReadOptions o;
        o.tolerance = tolerance;
        o.buildings = buildings_mode(buildings);
        if (up != "y" && up != "z")
          throw v::Failure(v::Error{v::ErrorKind::Usage, {}, "up='" + up + "' is no axis", "up is 'y' or 'z'"});
        o.obj_up = up == "z" ? v::UpAxis::Z : v::UpAxis::Y;
        o.outside_files = outside_files;
        o.max_parts = max_parts;
        py::gil_scoped_release release;
        return v::read_examples(paths, o);
      },
      "paths"_a, "tolerance"_a = 0.0, "buildings"_a = "apart", "up"_a = "y", "outside_files"_a = false,
      "max_parts"_a = 10000, "Reads example files (.obj, .gltf, .glb) and folders of them.");

  py::class_<v::InferResult>(m, "InferResult", "What infer() found: the grammar, and what to know about it.")
      .def_readonly("grammar", &v::InferResult::grammar)
      .def_readonly("tolerance", &v::InferResult::tolerance)
      .def_readonly("warnings", &v::InferResult::warnings)
      .def_readonly("examples", &v::InferResult::examples)
      .def("save", &v::InferResult::save, "file"_a, "Writes STYLE.grm and its meshes beside it (STYLE.prims.obj).");

  m.def(
      "infer",
      [](const std::vector<v::Example>& examples, double tolerance, const std::string& start,
         bool uniform_distributions, bool joint_sizes, bool twin_rules, const std::vector<std::string>& stack,
         unsigned threads) {
        v::InferOptions o;
        o.tolerance = tolerance;
        o.start = start;
        o.uniform_distributions = uniform_distributions;
        o.joint_sizes = joint_sizes;
        o.twin_rules = twin_rules;
        o.stack = stack;
        o.threads = threads;
        py::gil_scoped_release release;
        return v::infer(examples, o);
      },
      "examples"_a, "tolerance"_a = 0.0, "start"_a = "building", "uniform_distributions"_a = false,
      "joint_sizes"_a = true, "twin_rules"_a = true, "stack"_a = std::vector<std::string>{}, "threads"_a = 0,
      "Infers a grammar that derives every example and new buildings in their style.");

  py::class_<v::Verdict>(m, "Verdict", "check()'s answer.")
      .def_readonly("derivable", &v::Verdict::derivable)
      .def_readonly("witness", &v::Verdict::witness)
      .def_readonly("reason", &v::Verdict::reason)
      .def("__bool__", [](const v::Verdict& d) { return d.derivable; });

  m.def(
      "check",
      [](const v::Grammar& g, const v::Example& e, double tolerance, std::uint64_t max_steps,
         const std::vector<std::string>& stack) {
        v::CheckOptions o;
        o.tolerance = tolerance;
        o.max_steps = max_steps;
        o.stack = stack;
        py::gil_scoped_release release;
        return v::check(g, e, o);
      },
      "grammar"_a, "example"_a, "tolerance"_a = 0.0, "max_steps"_a = 10'000'000,
      "stack"_a = std::vector<std::string>{}, "Whether the grammar derives the example exactly, and how.");

  m.def(
      "write_buildings",
      [](const std::vector<v::Building>& buildings, const v::Grammar& g, const std::filesystem::path& file,
         double spacing) {
        py::gil_scoped_release release;
        v::write_buildings(buildings, g, file, spacing);
      },
      "buildings"_a, "grammar"_a, "file"_a, "spacing"_a = 5.0,
      "Writes buildings side by side to one .obj, .glb or .gltf file.");
}
