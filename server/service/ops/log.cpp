#include "service/ops/log.hpp"

#include <cstdio>
#include <mutex>

#include "io/json/json_text.hpp"
#include "service/ops/utc_time.hpp"

namespace saasgaps::service {

namespace {

std::mutex output;

void write(const char* level, const std::string& event, nlohmann::json fields) {
  nlohmann::json line = {{"time", utc_now()}, {"level", level}, {"event", event}};
  if (fields.is_object()) line.update(fields);
  const std::string text = io::json_text(line) + "\n";
  std::lock_guard lock(output);
  std::fwrite(text.data(), 1, text.size(), stderr);
  std::fflush(stderr);
}

}  // namespace

void log_info(const std::string& event, nlohmann::json fields) { write("info", event, std::move(fields)); }
void log_warning(const std::string& event, nlohmann::json fields) { write("warning", event, std::move(fields)); }
void log_error(const std::string& event, nlohmann::json fields) { write("error", event, std::move(fields)); }

}  // namespace saasgaps::service
