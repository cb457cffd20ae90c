// saasgaps_io_bench: model read and result write rates, the tree way (the old code path) against
// the streaming way, on one model document.
//
//   /usr/bin/python3 schemas/examples/make_ring_model.py --radial 160 --hoop 1600 -o /tmp/annulus-1e6.json
//   build/tests/bench/saasgaps_io_bench /tmp/annulus-1e6.json [--reads-only]
//
// Each stage runs in a child process of its own (fork), so its peak RSS (the child's ru_maxrss) is
// that stage's true peak for the whole process: what the parent held when it forked (the text, or
// the model and a solution) plus what the stage added. Rates are MB (10^6 bytes) of JSON text per
// second, of wall time and of the child's CPU time (user + system; on a shared machine the wall
// time includes waiting for a core). The result is that of a solve's shape (every node, element and gap, a
// history of 4 rows with every gap's closure), with pseudo-random values of full precision: the
// writers do not solve, they print.
//
// Stages (reading only: the restart digest is not part of reading, and is timed apart):
//   read, tree     parse_document (a tree of the whole text) + read_model: the tree reader the
//                  model-reader tests take as their reference
//   read, SAX      the nlohmann SAX pass (io/model/model_stream.hpp): what parse_model did before
//                  simdjson, and still does for text simdjson refuses
//   read, tape     simdjson's tape walked (io/model/simd_model_reader.hpp): what parse_model did before
//                  the scan, and still does for text the scan gives up on (the reporting path)
//   read, scan     parse_model(text): the strict scan in place (io/model/scan_model_reader.hpp)
//   digest         model_text_digest(text): the restart digest, from simdjson's tape, which
//                  restart states need (parse_model(text, &digest) costs read + digest)
// The read rates are also printed as ratios of CPU rates, all measured in this one run.
//   write, tree    the tree writer (kept in tests/io) + dump(2): what `saasgaps solve -o` wrote before
//   write, stream  io::write_result, compact (the default) and --pretty, through a 64 KiB buffer,
//                  its nodes and elements formatted on every core (at most 4; io/json/parallel_items.hpp),
//                  and compact on one thread: the wall time ratio one thread / every core
//
// With --plots RESULT.json, the pictures of a stored result instead, each stage reading the file
// itself as `saasgaps plot` does (the parent holds nothing of it), a 1200 x 800 PNG:
//   contour, tree     the text read whole, a tree of the nodes, gaps and each element's id,
//                     material, nodes and plotted field (parse_json_subset, the plots' reader
//                     before issue 23), then the contour of the effective stress
//   contour, arrays   io::read_result_arrays_file (typed arrays, no tree) and the same contour
//   arrays only       the read alone, without the drawing
//   convergence, tree / arrays   the same for the convergence plot
// and the ratios tree / arrays of wall time, CPU time and peak RSS, measured in this one run.
//
// With --stored RESULT.json, the result stored in a SQLite database (a temporary directory) and
// read for a contour as the service reads it: the text fetched whole (before) against the blob
// handle's 64 KiB pieces fed to the SAX reader (now), with their peak RSS, in this one run.
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <random>
#include <string>

#include <nlohmann/json.hpp>

#include "io/json/json_subset.hpp"
#include "io/json/json_writer.hpp"
#include "io/model/model_reader.hpp"
#include "io/model/model_stream.hpp"
#include "io/model/simd_model_reader.hpp"
#include "io/restart/state_codec.hpp"
#include "io/results/result_arrays.hpp"
#include "io/results/result_tree_reference.hpp"
#include "io/results/result_writer.hpp"
#include "plot/pictures/plot_request.hpp"
#include "service/store/sqlite.hpp"

using namespace saasgaps;

namespace {

struct Measured {
  double seconds = 0.0;
  double cpu_seconds = 0.0;  ///< user + system time of the child
  double bytes = 0.0;
  double peak_mib = 0.0;
};

double peak_rss_mib() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return static_cast<double>(usage.ru_maxrss) / 1024.0;
}

/// Runs stage() in a child process; it returns the bytes it read or wrote. The child reports its
/// wall time and byte count through a pipe; its peak RSS comes from wait4.
Measured in_child(const std::function<double()>& stage) {
  int fds[2];
  if (pipe(fds) != 0) std::abort();
  const pid_t pid = fork();
  if (pid == 0) {
    close(fds[0]);
    const auto start = std::chrono::steady_clock::now();
    const double bytes = stage();
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const double report[2] = {seconds, bytes};
    if (write(fds[1], report, sizeof report) != static_cast<ssize_t>(sizeof report)) _exit(1);
    _exit(0);
  }
  close(fds[1]);
  double report[2] = {0.0, 0.0};
  const ssize_t got = read(fds[0], report, sizeof report);
  close(fds[0]);
  int status = 0;
  rusage usage{};
  wait4(pid, &status, 0, &usage);
  if (got != static_cast<ssize_t>(sizeof report) || !WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    std::fprintf(stderr, "a stage failed\n");
    std::exit(1);
  }
  const auto cpu = [](const timeval& t) { return static_cast<double>(t.tv_sec) + 1e-6 * static_cast<double>(t.tv_usec); };
  return {report[0], cpu(usage.ru_utime) + cpu(usage.ru_stime), report[1], static_cast<double>(usage.ru_maxrss) / 1024.0};
}

void print(const char* name, const Measured& m) {
  std::printf("%-31s %7.2f s wall %7.2f s CPU %7.1f MB/s %7.1f MB/s CPU %6.0f MiB peak RSS (%.1f MB)\n", name,
              m.seconds, m.cpu_seconds, m.bytes / 1e6 / m.seconds, m.bytes / 1e6 / m.cpu_seconds, m.peak_mib,
              m.bytes / 1e6);
}

/// A solution of the model's shape with values of full precision.
Solution synthetic_solution(const Model& model) {
  std::mt19937_64 rng(1);
  std::uniform_real_distribution<double> value(-1e4, 1e4);
  Solution s;
  s.status = RunStatus::converged;
  s.iterations = 4;
  s.message = "converged in 4 iterations";
  for (int i = 1; i <= 4; ++i) {
    IterationRecord r;
    r.iteration = i;
    r.tensile_modulus = 20.0;
    r.seconds = value(rng);
    for (std::size_t g = 0; g < model.gap_count(); ++g) r.gap_closures.push_back(value(rng));
    s.history.push_back(r);
  }
  for (const Node& n : model.nodes) s.nodes.push_back({n.id, value(rng) * 1e-7, value(rng) * 1e-7});
  for (const Element& e : model.elements) {
    ElementResult r;
    r.id = e.id;
    for (int c = 0; c < 4; ++c) {
      r.stress[c] = value(rng);
      r.strain[c] = value(rng) * 1e-8;
    }
    r.principal = {value(rng), value(rng), value(rng) * 1e-2};
    r.effective = value(rng);
    s.elements.push_back(r);
  }
  if (model.gaps) {
    for (const GapElement& g : model.gaps->elements) {
      GapResult r;
      r.id = g.id;
      r.eps_m = value(rng) * 1e-4;
      r.closure = value(rng) * 1e-2;
      r.modulus = value(rng);
      r.sigma_m = value(rng);
      r.state = GapState::closed;
      r.converged = true;
      s.gaps.push_back(r);
    }
  }
  return s;
}

/// The file's text, read straight into a string of its size (as saasgaps reads files): a string
/// stream would hold a second copy for a moment, which at 300 MB would be the peak of a stage.
std::string file_text(const char* path) {
  std::ifstream in(path, std::ios::binary | std::ios::ate);
  std::string text(static_cast<std::size_t>(in.tellg()), '\0');
  in.seekg(0);
  in.read(text.data(), static_cast<std::streamsize>(text.size()));
  return text;
}

/// The plots' reading before issue 23: a tree of what the plot reads (a convergence plot: all but
/// the nodes and elements; a contour: of each element only id, material, nodes and its field).
nlohmann::json tree_before(const std::string& text, const plot::PlotRequest& request) {
  const io::ResultSelection selection = plot::result_selection_for(request);
  return io::parse_json_subset(text, [&selection](int depth, std::string_view section, std::string_view key) {
    if (!selection.mesh) return depth != 1 || (key != "nodes" && key != "elements");
    if (depth != 3 || section != "elements") return true;
    return key == "id" || key == "material" || key == "nodes" ||
           std::find(selection.element_keys.begin(), selection.element_keys.end(), key) != selection.element_keys.end();
  });
}

void print_ratios(const char* what, const Measured& tree, const Measured& arrays) {
  std::printf("%s: wall %.2fx, CPU %.2fx, peak RSS %.2fx\n", what, tree.seconds / arrays.seconds,
              tree.cpu_seconds / arrays.cpu_seconds, tree.peak_mib / arrays.peak_mib);
}

int plots(const char* path) {
  const auto size = static_cast<double>(std::ifstream(path, std::ios::binary | std::ios::ate).tellg());
  std::printf("result %s: %.1f MB of text; this process holds %.0f MiB\n", path, size / 1e6, peak_rss_mib());
  for (const char* name : {"effective", "convergence"}) {
    plot::PlotRequest request;
    request.name = name;
    const std::string what = std::string(name == std::string("effective") ? "contour" : "convergence");
    const Measured tree = in_child([&] {
      const nlohmann::json result = tree_before(file_text(path), request);
      const std::string png = plot::render_plot(result, request);
      return size;
    });
    print((what + ", tree (before)").c_str(), tree);
    const Measured arrays = in_child([&] {
      const plot::PlotResult result(io::read_result_arrays_file(path, plot::result_selection_for(request)));
      const std::string png = plot::render_plot(result, request);
      return size;
    });
    print((what + ", arrays").c_str(), arrays);
    print((what + ", arrays only (no drawing)").c_str(), in_child([&] {
            const io::ResultArrays read = io::read_result_arrays_file(path, plot::result_selection_for(request));
            return size;
          }));
    print_ratios((what + ", tree / arrays").c_str(), tree, arrays);
  }
  return 0;
}

/// A stored result read for a picture as the service reads it (the contour's selection), from a
/// SQLite database of the service's page size: the text fetched whole with SELECT (before) against
/// the blob handle's 64 KiB pieces fed to the SAX reader (now). The reading alone, no drawing.
int stored(const char* path) {
  char directory[] = "/tmp/saasgaps-io-bench-XXXXXX";
  if (mkdtemp(directory) == nullptr) return 1;
  const std::string database = std::string(directory) + "/results.db";
  double size = 0.0;
  {
    service::Connection db(database);
    db.execute("CREATE TABLE results (job_id INTEGER PRIMARY KEY, document TEXT NOT NULL)");
    const std::string text = file_text(path);
    size = static_cast<double>(text.size());
    db.prepare("INSERT INTO results (job_id, document) VALUES (1, ?)").bind(1, text).run();
  }
  std::printf("result %s: %.1f MB of text, stored; this process holds %.0f MiB\n", path, size / 1e6, peak_rss_mib());
  plot::PlotRequest request;
  request.name = "effective";
  const io::ResultSelection selection = plot::result_selection_for(request);
  const Measured whole = in_child([&] {
    service::Connection db(database);
    service::Statement q = db.prepare("SELECT document FROM results WHERE job_id = 1");
    if (!q.step()) std::abort();
    const io::ResultArrays read = io::read_result_arrays(q.text(0), selection);
    return size;
  });
  print("stored, text whole (before)", whole);
  const Measured pieces = in_child([&] {
    service::Connection db(database);
    service::BlobReader blob(db, "results", "document", 1);
    std::size_t offset = 0;
    const io::ResultArrays read = io::read_result_arrays_pieces(
        [&](char* out, std::size_t capacity) {
          const std::size_t count = std::min(capacity, blob.size() - offset);
          blob.read(offset, out, count);
          offset += count;
          return count;
        },
        selection);
    return size;
  });
  print("stored, blob pieces", pieces);
  print_ratios("stored result read, whole text / blob pieces", whole, pieces);
  std::filesystem::remove_all(directory);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc == 3 && std::string(argv[1]) == "--plots") return plots(argv[2]);
  if (argc == 3 && std::string(argv[1]) == "--stored") return stored(argv[2]);
  const bool reads_only = argc == 3 && std::string(argv[2]) == "--reads-only";
  if (argc != 2 && !reads_only) {
    std::fprintf(stderr, "usage: %s MODEL.json [--reads-only] | --plots RESULT.json | --stored RESULT.json\n", argv[0]);
    return 2;
  }
  std::string text = file_text(argv[1]);
  const auto size = static_cast<double>(text.size());
  std::printf("model %s: %.1f MB of text; this process holds %.0f MiB\n", argv[1], size / 1e6, peak_rss_mib());

  const Measured tree = in_child([&] {
    const nlohmann::json document = io::parse_document(text);
    const Model model = io::read_model(document);
    return size;
  });
  print("read, tree (reference)", tree);
  const Measured sax = in_child([&] {
    io::SectionReader reader;
    io::stream_model(text, reader, nullptr);
    const Model model = reader.finish();
    return size;
  });
  print("read, nlohmann SAX", sax);
  const Measured tape = in_child([&] {
    io::SectionReader reader;
    if (!io::read_model_text(text, reader, nullptr)) std::abort();
    const Model model = reader.finish();
    return size;
  });
  print("read, simdjson tape", tape);
  const Measured scan = in_child([&] {
    const Model model = io::parse_model(text);
    return size;
  });
  print("read, scan (parse_model)", scan);
  const Measured digest = in_child([&] {
    const std::string d = io::model_text_digest(text);
    return size;
  });
  print("restart digest (text)", digest);
  std::printf("read rate of CPU, scan / tree: %.1fx; scan / nlohmann SAX: %.1fx; scan / simdjson tape: %.1fx; "
              "digest / scan (CPU time): %.2f\n",
              tree.cpu_seconds / scan.cpu_seconds, sax.cpu_seconds / scan.cpu_seconds,
              tape.cpu_seconds / scan.cpu_seconds, digest.cpu_seconds / scan.cpu_seconds);

  if (reads_only) return 0;
  const Model model = io::parse_model(text);
  text = std::string();  // a solve no longer holds the text when it writes
  const Solution solution = synthetic_solution(model);
  std::printf("model: %zu nodes, %zu elements, %zu gaps (%zu unknowns)\n", model.nodes.size(),
              model.elements.size(), model.gap_count(), 2 * model.nodes.size());

  print("write, tree + dump(2) (before)", in_child([&] {
          std::ofstream out("/dev/null", std::ios::binary);
          const std::string dumped = io::reference::result_document(model, solution).dump(2) + "\n";
          out << dumped;
          return static_cast<double>(dumped.size());
        }));
  const auto write = [&](bool pretty, unsigned threads) {
    return in_child([&] {
      std::ofstream out("/dev/null", std::ios::binary);
      io::JsonWriter writer(io::stream_sink(out), pretty);
      io::write_result(writer, model, solution, {.threads = threads});
      writer.flush();
      return static_cast<double>(writer.bytes());
    });
  };
  const Measured one_thread = write(false, 1);
  print("write, stream (compact), 1 thread", one_thread);
  const Measured threads = write(false, 0);
  print("write, stream (compact)", threads);
  print("write, stream --pretty", write(true, 0));
  std::printf("write wall, 1 thread / every core: %.2fx\n", one_thread.seconds / threads.seconds);
  return 0;
}
