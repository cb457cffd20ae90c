#include "cli/client/client_commands.hpp"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <iostream>
#include <nlohmann/json.hpp>

#include "cli/client/job_watch.hpp"
#include "cli/common/file_io.hpp"
#include "cli/common/http_client.hpp"
#include "cli/common/usage.hpp"
#include "io/restart/read_card.hpp"
#include "solver/base/plural.hpp"

namespace saasgaps::cli {

namespace {

using nlohmann::json;

std::string environment(const char* name) {
  const char* value = std::getenv(name);
  return value != nullptr ? value : "";
}

ServiceClient connect(const ServerOptions& options) {
  std::string url = options.server.empty() ? environment("SAASGAPS_SERVER") : options.server;
  if (url.empty()) url = default_server_url;
  while (url.size() > 1 && url.back() == '/') url.pop_back();  // "http://host:8080/" names the same server
  const std::string token = options.token_file.empty() ? environment("SAASGAPS_TOKEN") : read_token_file(options.token_file);
  return {url, token};
}

void add_server_options(CLI::App& command, ServerOptions& options) {
  command.add_option("--server", options.server,
                     std::string("The service's URL (default: $SAASGAPS_SERVER, else ") + default_server_url + ")");
  command.add_option("--token-file", options.token_file, "File holding the bearer token (default: $SAASGAPS_TOKEN)");
}

CLI::App* add_job_command(CLI::App& app, const std::string& name, const std::string& description, std::int64_t& job,
                          ServerOptions& server) {
  CLI::App* command = app.add_subcommand(name, description);
  command->add_option("job", job, "Job id")->required()->check(integer_range(1, std::numeric_limits<std::int64_t>::max()));
  add_server_options(*command, server);
  return command;
}

std::string text_of(const json& job, const char* key) {
  const json value = job.value(key, json());
  return value.is_string() ? value.get<std::string>() : value.is_null() ? "-" : value.dump();
}

std::string job_path(std::int64_t job) { return "/v1/jobs/" + std::to_string(job); }

/// "plots/NAME.EXT": the extension from NAME if it has one, else from the output file, else png.
std::string plot_file(const std::string& name, const std::string& output) {
  const auto ends_with = [](const std::string& text, const std::string& end) {
    return text.size() >= end.size() && text.compare(text.size() - end.size(), end.size(), end) == 0;
  };
  if (ends_with(name, ".png") || ends_with(name, ".svg")) return name;
  return name + (ends_with(output, ".svg") ? ".svg" : ".png");
}

/// A plot is written in its own format only: FILE ends in .png or .svg, and agrees with an
/// extension NAME gives (a .csv of PNG bytes would be a broken file that exits 0).
void check_plot_output(const std::string& name, const std::string& output) {
  const auto extension = [](const std::string& file) {
    const auto dot = file.rfind('.');
    const auto slash = file.rfind('/');
    if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return std::string();
    std::string ext = file.substr(dot);
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return ext;
  };
  const std::string ext = extension(output);
  if (ext != ".png" && ext != ".svg") {
    throw UsageError("fetch --plot -o " + output + ": a plot is written as PNG or SVG only; give a FILE ending in "
                     ".png or .svg (a result's values are in `fetch --result`, or `--vtu` for ParaView)");
  }
  const std::string named = extension(name);
  if ((named == ".png" || named == ".svg") && named != ext) {
    throw UsageError("fetch --plot " + name + " -o " + output + ": the plot is " + named.substr(1) +
                     " but FILE ends in " + ext + "; give the same format to both");
  }
}

}  // namespace

ClientCommands::ClientCommands(CLI::App& app) {
  submit_ = app.add_subcommand("submit", "Submit a model to a saasgaps service; prints the job id");
  submit_->add_option("model", model_path_, "Model document (JSON)")->required();
  submit_->add_flag("--watch", watch_, "Then follow the job until it stops, as `watch` does");
  add_server_options(*submit_, server_);

  jobs_ = app.add_subcommand("jobs", "List a service's jobs, newest first");
  jobs_->add_option("--state", state_filter_, "Only jobs in this state")
      ->check(CLI::IsMember({"queued", "running", "converged", "not_converged", "failed", "cancelled", "interrupted"}));
  jobs_->add_option("--limit", limit_, "At most this many jobs")->check(integer_range(1, 100))->capture_default_str();
  add_server_options(*jobs_, server_);

  status_ = add_job_command(app, "status", "Show a job of a service", job_, server_);
  status_->add_flag("--json", json_, "The job as the service answers it (JSON)");

  watch_cmd_ = add_job_command(app, "watch", "Follow a job of a service until it stops; exit code as solve's", job_, server_);
  watch_cmd_->add_flag("--wide", wide_, "Every column of the progress table (when not on a terminal)");

  cancel_ = add_job_command(app, "cancel", "Cancel a job of a service (a running one stops at the next iteration)",
                            job_, server_);

  resume_ = add_job_command(app, "resume", "Resume a cancelled, not converged, interrupted or failed job of a service",
                            job_, server_);
  add_read_card_options(*resume_, changes_, " (started afresh at the next iteration)");
  resume_->add_flag("--watch", watch_, "Then follow the job until it stops, as `watch` does");

  fetch_ = add_job_command(app, "fetch", "Download a job's result document, VTU file or a plot", job_, server_);
  CLI::Option* result = fetch_->add_flag("--result", fetch_result_, "The result document (the default)");
  CLI::Option* vtu = fetch_->add_flag("--vtu", fetch_vtu_, "The result as a VTK unstructured grid (.vtu)");
  CLI::Option* plot = fetch_->add_option("--plot", fetch_plot_,
                                         "A plot by name (a field, closure, contact_pressure, convergence); PNG, or "
                                         "SVG when FILE ends in .svg");
  result->excludes(vtu)->excludes(plot);
  vtu->excludes(plot);
  fetch_->add_option("-o,--output", output_, "File to write; - is stdout")->required();
}

std::optional<int> ClientCommands::run() const {
  if (submit_->parsed()) return submit();
  if (jobs_->parsed()) return jobs();
  if (status_->parsed()) return status();
  if (watch_cmd_->parsed()) {
    ServiceClient client = connect(server_);
    return watch_job(client, job_, wide_);
  }
  if (cancel_->parsed()) return cancel();
  if (resume_->parsed()) return resume();
  if (fetch_->parsed()) return fetch();
  return std::nullopt;
}

int ClientCommands::submit() const {
  const std::string model = read_file(model_path_);
  ServiceClient client = connect(server_);
  std::string location;
  const json job = json::parse(client.post_json("/v1/jobs", model, &location));
  const std::int64_t id = job.at("id").get<std::int64_t>();
  std::cerr << "submitted " << model_path_ << " as job " << id << " (" << text_of(job, "state") << "): " << client.url()
            << location << '\n';
  if (!watch_) {
    std::cout << id << '\n';
    return exit_code::ok;
  }
  return watch_job(client, id, wide_);
}

int ClientCommands::jobs() const {
  ServiceClient client = connect(server_);
  std::string path = "/v1/jobs?page_size=" + std::to_string(limit_);
  if (!state_filter_.empty()) path += "&state=" + state_filter_;
  const json page = json::parse(client.get(path));
  const json& list = page.at("jobs");
  if (list.empty()) {
    std::cout << (state_filter_.empty() ? "no jobs\n" : "no " + state_filter_ + " jobs\n");
    return exit_code::ok;
  }
  char line[256];
  std::snprintf(line, sizeof line, "%6s  %-13s  %11s  %-24s  %s\n", "id", "state", "iteration", "created", "title");
  std::cout << line;
  for (const json& job : list) {
    const std::string iteration = std::to_string(job.value("iteration", 0)) + "/" + std::to_string(job.value("max_iterations", 0));
    std::snprintf(line, sizeof line, "%6lld  %-13s  %11s  %-24s  ", static_cast<long long>(job.at("id").get<std::int64_t>()),
                  text_of(job, "state").c_str(), iteration.c_str(), text_of(job, "created_at").c_str());
    std::cout << line << text_of(job, "title") << '\n';
  }
  if (page.value("next_page_token", json()).is_string()) {
    std::cout << "(more jobs than these " << limit_ << "; --limit N shows up to 100)\n";
  }
  return exit_code::ok;
}

int ClientCommands::status() const {
  ServiceClient client = connect(server_);
  const std::string body = client.get(job_path(job_));
  if (json_) {
    std::cout << body << '\n';
    return exit_code::ok;
  }
  const json job = json::parse(body);
  std::cout << "job " << job_ << ": " << text_of(job, "state") << (job.value("cancel_requested", false) ? " (cancel requested)" : "")
            << "\n  title       " << text_of(job, "title") << "\n  iteration   " << job.value("iteration", 0)
            << " of at most " << job.value("max_iterations", 0) << "\n  attempts    " << job.value("attempts", 0)
            << " (" << plural(job.value("interruptions", 0), "interruption") << ")\n  created     "
            << text_of(job, "created_at") << "\n  started     " << text_of(job, "started_at") << "\n  finished    "
            << text_of(job, "finished_at") << '\n';
  if (job.value("message", json()).is_string()) std::cout << "  message     " << text_of(job, "message") << '\n';
  if (job.value("error", json()).is_string()) std::cout << "  error       " << text_of(job, "error") << '\n';
  return exit_code::ok;
}

int ClientCommands::cancel() const {
  ServiceClient client = connect(server_);
  const json job = json::parse(client.post_json(job_path(job_) + "/cancel", ""));
  if (text_of(job, "state") == "cancelled") {
    std::cout << "job " << job_ << " cancelled after " << plural(job.value("iteration", 0), "iteration") << '\n';
  } else {
    std::cout << "job " << job_ << ": cancel requested; it stops at the next iteration boundary\n";
  }
  return exit_code::ok;
}

int ClientCommands::resume() const {
  const json body = io::read_card_to_json(changes_, io::ReadCardForm::changes);
  ServiceClient client = connect(server_);
  const json job = json::parse(client.post_json(job_path(job_) + "/resume", body.dump()));
  std::cerr << "job " << job_ << " " << text_of(job, "state") << " to continue after "
            << plural(job.value("iteration", 0), "iteration") << '\n';
  return watch_ ? watch_job(client, job_, wide_) : exit_code::ok;
}

int ClientCommands::fetch() const {
  if (!fetch_plot_.empty() && output_ != "-") check_plot_output(fetch_plot_, output_);
  if (output_ != "-") require_writable(output_, "-o");
  std::string part = "/result";
  if (fetch_vtu_) part = "/result.vtu";
  if (!fetch_plot_.empty()) part = "/plots/" + plot_file(fetch_plot_, output_);
  ServiceClient client = connect(server_);
  const std::string content = client.get(job_path(job_) + part);
  if (output_ == "-") {
    std::cout << content;
    std::cout.flush();
  } else {
    write_file_atomically(output_, content);
    std::cerr << "wrote " << output_ << " (" << content.size() << " bytes)\n";
  }
  return exit_code::ok;
}

}  // namespace saasgaps::cli
