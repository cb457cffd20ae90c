/// saasgaps: thermal stress analysis of plane and axisymmetric bodies in contact across gaps.
/// Subcommands: solve, validate, import, serve, worker, plot, probe, export-vtu, and the client of a
/// service: submit, jobs, status, watch, cancel, resume, fetch (cli/client/client_commands.hpp). Exit codes (cli/common/usage.hpp,
/// docs/cli.md): 0 converged or valid, 3 not converged, 2 bad model, 1 any other failure, 64 a usage
/// error. Usage errors and exceptions become exit codes in cli/common/usage.cpp only.

#include <CLI/CLI.hpp>

#include <optional>

#include "cli/client/client_commands.hpp"
#include "cli/commands/export_vtu_command.hpp"
#include "cli/commands/import_command.hpp"
#include "cli/commands/plot_command.hpp"
#include "cli/commands/probe_command.hpp"
#include "cli/commands/serve_command.hpp"
#include "cli/commands/solve_command.hpp"
#include "cli/commands/study_command.hpp"
#include "cli/commands/validate_command.hpp"
#include "cli/commands/worker_command.hpp"
#include "cli/common/read_card_options.hpp"
#include "cli/common/usage.hpp"
#include "io/sections/run_limits.hpp"
#include "plot/draw/canvas.hpp"
#include "plot/draw/color_map.hpp"

int main(int argc, char** argv) {
  CLI::App app{"SAASGAPS: thermal stress analysis of plane and axisymmetric bodies in contact across gaps", "saasgaps"};
  app.require_subcommand(1);
  app.set_version_flag("--version", "saasgaps " SAASGAPS_VERSION);

  saasgaps::cli::SolveOptions solve;
  CLI::App* solve_cmd = app.add_subcommand("solve", "Solve a model; one progress line per iteration on stderr");
  solve_cmd->add_option("model", solve.model_path, "Model document (JSON)")->required();
  solve_cmd->add_option("-o,--output", solve.result_path,
                        "Result document; - is stdout (default: stdout, or MODEL.result.json when stdout is a terminal)");
  solve_cmd->add_option("--state-out", solve.state_out, "Write the restart state after every iteration");
  solve_cmd->add_option("--resume", solve.resume_from, "Continue from a restart state written by --state-out");
  saasgaps::cli::add_read_card_options(*solve_cmd, solve.changes,
                                       " (with --resume: started afresh at the next iteration)");
  solve_cmd->add_option("--stop-after", solve.stop_after, "Stop after this many iterations, keeping the state")
      ->check(saasgaps::cli::integer_range(1, saasgaps::io::max_iterations_limit));
  solve_cmd->add_flag("-q,--quiet", solve.quiet, "No progress table");
  solve_cmd->add_flag("--wide", solve.wide, "Every column of the progress table: the watched elements and gaps too");
  solve_cmd->add_flag("--pretty", solve.pretty, "Indent the result document (default: compact)");
  solve_cmd->add_option("--vtu", solve.vtu_path, "Also write the result as a VTK unstructured grid (.vtu)");
  solve_cmd->add_option("--cache", solve.cache_dir,
                        "Directory keeping symbolic analyses (fill-reducing ordering and supernodes) between "
                        "runs: a mesh solved before skips its analysis (created if missing)");

  saasgaps::cli::StudyOptions study;
  CLI::App* study_cmd = app.add_subcommand(
      "study", "Solve one model over many parameter values; outputs per point as JSON and CSV (docs/studies.md)");
  study_cmd->add_option("study", study.study_path, "Study document (JSON)")->required();
  study_cmd->add_option("-o,--output", study.result_path, "Study result document (the CSV goes beside it)")->required();
  study_cmd->add_option("--csv", study.csv_path, "The CSV of parameters and outputs (default: beside the result, .csv)");
  study_cmd->add_option("--workers", study.workers, "Points solved at once")->check(CLI::Range(1, 64))->capture_default_str();
  study_cmd->add_option("--max-points", study.max_points, "Most points a study may have (exit 2 beyond)")
      ->check(CLI::Range(std::size_t{1}, std::size_t{100000000}))
      ->capture_default_str();
  study_cmd->add_flag("--no-cache", study.no_cache, "Solve every point afresh, ignoring and not filling $SAASGAPS_CACHE");
  study_cmd->add_option("--cache-keep-days", study.cache_keep_days,
                        "After the study, remove cache entries last used more than DAYS days ago (default: keep)")
      ->envname("SAASGAPS_CACHE_KEEP_DAYS")
      ->check(CLI::PositiveNumber);
  study_cmd->add_option("--cache-max-entries", study.cache_max_entries,
                        "After the study, keep at most N cache entries, the most recently used (default: all)")
      ->envname("SAASGAPS_CACHE_MAX_ENTRIES")
      ->check(CLI::Range(std::size_t{1}, std::size_t{1000000000}));
  study_cmd->add_flag("-q,--quiet", study.quiet, "No line per finished point");

  std::string validate_path;
  CLI::App* validate_cmd = app.add_subcommand("validate", "Check a model and print every error with its JSON Pointer");
  validate_cmd->add_option("model", validate_path, "Model document (JSON)")->required();

  saasgaps::cli::ImportOptions import;
  CLI::App* import_cmd = app.add_subcommand(
      "import", "Build a model from an assembly: a Gmsh mesh and its physical groups (docs/import.md)");
  import_cmd->add_option("assembly", import.assembly_path, "Assembly document (JSON)")->required();
  import_cmd->add_option("-o,--output", import.model_path, "Model document to write (default: stdout)");
  saasgaps::cli::add_mesh_limit_options(*import_cmd, import.mesh);

  saasgaps::cli::ServeOptions serve;
  CLI::App* serve_cmd = app.add_subcommand("serve", "Run the HTTP job service on an SQLite database file");
  serve_cmd->add_option("--host", serve.host, "Address to listen on (beyond loopback only with --token-file)")
      ->capture_default_str();
  serve_cmd->add_option("--port", serve.port, "TCP port; 0 picks a free one and prints it")
      ->check(CLI::Range(0, 65535))
      ->capture_default_str();
  serve_cmd->add_option("--db", serve.database, "SQLite database file, created on first start")->capture_default_str();
  serve_cmd->add_option("--workers", serve.workers, "Jobs solved at once")->check(CLI::Range(1, 64))->capture_default_str();
  serve_cmd->add_option("--max-body", serve.max_body, "Largest request body in bytes (413 beyond)")
      ->check(CLI::Range(std::size_t{1024}, std::size_t{1} << 40))
      ->capture_default_str();
  saasgaps::cli::add_mesh_limit_options(*serve_cmd, serve.mesh);
  serve_cmd->add_option("--token-file", serve.token_file, "File holding a bearer token every request must carry");
  serve_cmd->add_option("--max-streams", serve.max_streams, "Concurrent event streams (503 beyond)")
      ->check(CLI::Range(1, 256))
      ->capture_default_str();
  serve_cmd->add_option("--max-interruptions", serve.max_interruptions,
                        "Server deaths a running job survives before it fails instead of resuming")
      ->check(CLI::Range(0, 100))
      ->capture_default_str();
  serve_cmd->add_option("--allow-host", serve.allowed_hosts,
                        "A Host name to answer besides loopback names and --host (repeatable; DNS-rebinding guard)");
  serve_cmd->add_option("--header-timeout", serve.header_timeout, "Seconds a client has to send a request's head")
      ->check(CLI::Range(0.1, 3600.0))
      ->capture_default_str();
  serve_cmd->add_option("--keep-alive", serve.keep_alive, "Seconds an idle connection stays open")
      ->check(CLI::Range(0.1, 3600.0))
      ->capture_default_str();
  serve_cmd->add_option("--keep-finished", serve.keep_finished_days,
                        "Delete finished jobs this many days after they finished (checked at start and hourly)")
      ->check(CLI::Range(0.0, 36500.0));

  serve_cmd->add_option("--executor", serve.executor, "Where jobs are solved: local (this process) or slurm (sbatch of workers)")
      ->check(CLI::IsMember({"local", "slurm"}))
      ->capture_default_str();
  serve_cmd->add_option("--slurm-partition", serve.slurm_partition, "sbatch --partition for workers");
  serve_cmd->add_option("--slurm-account", serve.slurm_account, "sbatch --account for workers");
  serve_cmd->add_option("--slurm-time-limit", serve.slurm_time_limit, "sbatch --time for workers (e.g. 4:00:00)");
  serve_cmd->add_option("--slurm-extra", serve.slurm_extra, "Further sbatch arguments, separated by spaces");
  serve_cmd->add_option("--slurm-worker-url", serve.slurm_worker_url,
                        "This server's URL as workers reach it (default http://HOST:PORT)");
  serve_cmd->add_option("--slurm-worker-binary", serve.slurm_worker_binary,
                        "The saasgaps binary on the compute nodes (default: this one)");
  serve_cmd->add_option("--slurm-token-file", serve.slurm_token_file,
                        "The token file as workers see it (default: --token-file)");
  serve_cmd->add_option("--slurm-log-dir", serve.slurm_log_dir, "Directory for worker logs (default: sbatch's)");
  serve_cmd->add_option("--slurm-poll", serve.slurm_poll, "Seconds between squeue polls")
      ->check(CLI::Range(0.05, 3600.0))
      ->capture_default_str();
  serve_cmd->add_option("--slurm-cancel-grace", serve.slurm_cancel_grace,
                        "Seconds a cancelled worker has to stop at an iteration boundary before scancel")
      ->check(CLI::Range(0.0, 86400.0))
      ->capture_default_str();

  saasgaps::cli::WorkerCommandOptions worker;
  CLI::App* worker_cmd = app.add_subcommand("worker", "Run one job of a service here, reporting each iteration over HTTP");
  worker_cmd->add_option("--server", worker.server, "The service's URL, http://HOST:PORT")->required();
  worker_cmd->add_option("--job", worker.job, "Job id")->required()->check(CLI::PositiveNumber);
  worker_cmd->add_option("--ticket", worker.ticket,
                         "ATTEMPT:TICKET, the run's single-use ticket (default: $SAASGAPS_TICKET, set by the Slurm executor)");
  worker_cmd->add_option("--lease", worker.lease, "ATTEMPT:SECRET, a lease already redeemed (default: $SAASGAPS_LEASE)");
  worker_cmd->add_option("--token-file", worker.token_file, "File holding the service's bearer token");
  worker_cmd->add_option("--retry-for", worker.retry_for, "Seconds a request is retried before the worker gives up")
      ->check(CLI::Range(0.0, 86400.0))
      ->capture_default_str();

  saasgaps::cli::PlotOptions plot;
  CLI::App* plot_cmd = app.add_subcommand("plot", "Draw a contour, path, closure, contact-pressure or convergence plot "
                                                  "of a result (PNG, SVG, or its numbers as CSV)");
  plot_cmd->add_option("result", plot.result_path, "Result document (JSON) written by solve")->required();
  plot_cmd->add_option("-o,--output", plot.output_path,
                       "Image file; the format follows the extension: .png or .svg (.csv: the numbers of a path, "
                       "closure or contact_pressure plot)")
      ->required();
  plot_cmd->add_option("--field", plot.field, "A field to contour, or closure, contact_pressure, convergence")
      ->capture_default_str();
  plot_cmd->add_option("--deformed", plot.deformed, "Draw the deformed mesh, displacements times SCALE (or 'auto')");
  plot_cmd->add_flag("--mesh", plot.mesh, "Draw the element edges");
  const CLI::Range image_side(saasgaps::plot::Canvas::min_side, saasgaps::plot::Canvas::max_side);
  plot_cmd->add_option("--width", plot.width, "Image width, px")->check(image_side)->capture_default_str();
  plot_cmd->add_option("--height", plot.height, "Image height, px")->check(image_side)->capture_default_str();
  plot_cmd->add_option("--bands", plot.bands, "At most this many colour bands")->check(CLI::Range(2, 40))
      ->capture_default_str();
  plot_cmd->add_option("--levels", plot.levels, "Band levels: even (round, equal width) or quantile (equal area)")
      ->check(CLI::IsMember({"even", "quantile"}))
      ->capture_default_str();
  plot_cmd->add_option("--colormap", plot.color_map,
                       "auto (diverging when the field changes sign, else viridis), viridis, cividis, diverging "
                       "or rainbow")
      ->check(CLI::IsMember(saasgaps::plot::ColorMap::names()))
      ->capture_default_str();
  plot_cmd->add_option("--centre", plot.centre,
                       "Plane models: the centre x,y of sigma_radial, sigma_hoop, tau_radial_hoop and their strains "
                       "(default 0,0)");
  plot_cmd->add_option("--gaps", plot.gaps, "The row of gaps for closure and contact_pressure, in order: ids and "
                                            "ranges, e.g. 81-98 or 5,7,9-12 (default: every gap, or the contact pairs when the result has them)");
  plot_cmd->add_option("--along", plot.along, "closure and contact_pressure only: x axis along the gap row, or along "
                                              "side A of each contact pair: index (the default), position (arc length), r or z")
      ->check(CLI::IsMember({"index", "position", "r", "z"}));
  plot_cmd->add_option("--set", plot.set, "--field force: the node set whose summed reactions (set_reactions) to plot "
                                          "against the load path");
  plot_cmd->add_option("--path", plot.path, "Plot the field along this polyline of points: 'r0,z0;r1,z1;...'");
  plot_cmd->add_option("--samples", plot.samples, "Points sampled along --path")->check(CLI::Range(2, 100000))
      ->capture_default_str();

  saasgaps::cli::ProbeOptions probe;
  CLI::App* probe_cmd = app.add_subcommand(
      "probe", "Print a result's recovered stresses, displacement and temperature at a point (docs/recovery.md)");
  probe_cmd->add_option("result", probe.result_path, "Result document (JSON) written by solve")->required();
  probe_cmd->add_option("--at", probe.at, "The point 'r,z' (x,y in plane analyses)")->required();
  probe_cmd->add_option("--field", probe.fields,
                        "Fields to print (repeat or separate by commas; default: the stress components, effective, "
                        "u_r, u_z and the temperature when the result has one)");
  probe_cmd->add_flag("--json", probe.json, "Print JSON, as the service's GET /v1/jobs/{id}/probe");

  saasgaps::cli::ExportVtuOptions vtu;
  CLI::App* vtu_cmd = app.add_subcommand("export-vtu", "Write a result as a VTK unstructured grid (.vtu) for ParaView");
  vtu_cmd->add_option("result", vtu.result_path, "Result document (JSON) written by solve")->required();
  vtu_cmd->add_option("-o,--output", vtu.output_path,
                      "VTU file; a .pvd name writes every iteration's gap closures as a ParaView collection")
      ->required();
  vtu_cmd->add_option("--format", vtu.format, "binary (zlib-compressed) or ascii")
      ->check(CLI::IsMember({"binary", "ascii"}))
      ->capture_default_str();

  const saasgaps::cli::ClientCommands client(app);

  if (const std::optional<int> done = saasgaps::cli::parse_command_line(app, argc, argv)) return *done;

  return saasgaps::cli::run_command([&] {
    if (const std::optional<int> code = client.run()) return *code;
    if (solve_cmd->parsed()) return saasgaps::cli::run_solve(solve);
    if (study_cmd->parsed()) return saasgaps::cli::run_study(study);
    if (validate_cmd->parsed()) return saasgaps::cli::run_validate(validate_path);
    if (import_cmd->parsed()) return saasgaps::cli::run_import(import);
    if (serve_cmd->parsed()) return saasgaps::cli::run_serve(serve);
    if (plot_cmd->parsed()) return saasgaps::cli::run_plot(plot);
    if (worker_cmd->parsed()) return saasgaps::cli::run_worker_command(worker);
    if (vtu_cmd->parsed()) return saasgaps::cli::run_export_vtu(vtu);
    if (probe_cmd->parsed()) return saasgaps::cli::run_probe(probe);
    return saasgaps::cli::exit_code::failure;
  }, import_cmd->parsed() ? "assembly" : study_cmd->parsed() ? "study" : "model");
}
