#pragma once
/// The JSON the API answers with about jobs: the job resource with its links, a job as the list
/// shows it, a page of stored history rows, a model's units; and how a JSON answer is sent.

#include <httplib.h>

#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "service/store/job_store.hpp"

namespace saasgaps::service {

/// The job resource: its record, its last history row, the warnings of its message, its READ card in
/// force, its Slurm job and the links to its sub-resources.
nlohmann::json job_json(const JobRecord& j);

/// A job as GET /v1/jobs lists it: the job resource without per-gap arrays (the last row's
/// gap_closures), which grow with the model and belong on the job and its iterations.
nlohmann::json job_list_item(const JobRecord& j);

/// {"job": id, "<member>": [rows]}: the rows are stored as JSON text, spliced rather than parsed and
/// printed again.
std::string rows_page(std::int64_t id, const char* member, const std::vector<std::string>& rows);

/// The names of the model's units (its top-level "units" object; {} when it names none), read
/// from the stored model text without building the rest of it.
nlohmann::json model_units(const std::string& model_text);

/// Answers `status` with `body` as application/json.
void send_json(httplib::Response& res, int status, const nlohmann::json& body);

}  // namespace saasgaps::service
