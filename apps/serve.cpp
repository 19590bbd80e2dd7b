// serve: a page in the browser to write a grammar and see its buildings as
// you type, over the same derivation the other commands use.
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <optional>

#include "serve/server.hpp"
#include "serve/session.hpp"
#include "serve/web_files.hpp"
#include "support/command_line.hpp"
#include "support/example_options.hpp"
#include "support/guarded_main.hpp"

namespace fs = std::filesystem;
using namespace vern;

namespace {

CommandLine make_command_line() {
  CommandLine cl("serve", "serve [STYLE.grm] [EXAMPLES...] [--port N]",
                 "Starts a page on this machine (http://127.0.0.1:PORT/, nowhere else) to edit a grammar\n"
                 "and see its buildings as you type: errors at their line, seeds, several buildings side\n"
                 "by side, and a click on a part shows the rules that made it. Given examples (.obj,\n"
                 ".gltf, .glb or folders) without a grammar, it starts from the grammar inferred from\n"
                 "them, and shows them beside. The file is never written: the page saves a copy.");
  cl.add({"--port", "-p", 1, "N", "the port (default 8765; 0: any free one, said when listening)"});
  cl.add({"--web", "", 1, "DIR", "the page's folder (default: installed beside the program, or the sources' web/)"});
  add_example_options(cl);
  cl.add_standard_options();
  cl.set_epilog(
      "examples:\n"
      "  serve data/grammars/garage.grm\n"
      "  serve data/examples/garage/            # its inferred grammar, and the examples\n"
      "\n"
      "exit codes: 0 stopped, 2 usage error, 3 bad input, 5 a file could not be read or the port bound,\n"
      "            70 internal error\n");
  return cl;
}

int run(int argc, char** argv) {
  const CommandLine cl = make_command_line();
  const std::optional<ParsedCommandLine> parsed = cl.parse_or_answer(argc, argv);
  if (!parsed) return 0;
  const ParsedCommandLine& args = *parsed;
  ServeOptions options;
  if (args.has("--port")) options.port = static_cast<int>(CommandLine::integer(args, "--port", 0, 65535));
  options.web = find_web_folder(args.has("--web") ? std::optional<fs::path>(args.value("--web")) : std::nullopt,
                                fs::path("/proc/self/exe"));
  const ServeSession session = open_session(args.positional, example_limits(args), stack_order(args));
  serve(session, options, [&](int port, const std::function<void()>&) {
    // The one line a script waits for: the address.
    std::fprintf(stderr, "serve: http://127.0.0.1:%d/ (%s; Ctrl-C stops)\n", port, session.grammar_name.c_str());
    std::fflush(stderr);
  });
  return 0;
}

}  // namespace

int main(int argc, char** argv) { return guarded_main("serve", run, argc, argv); }
