#include "service/http/job_path.hpp"

#include <charconv>
#include <limits>
#include <string>
#include <string_view>

#include "service/http/problem.hpp"

namespace saasgaps::service {

std::int64_t job_in_path(const httplib::Request& req) {
  const std::string text = req.matches[1];
  // The id as the client spelled it: the raw request target's segment after /v1/jobs/.
  constexpr std::string_view prefix = "/v1/jobs/";
  std::string_view spelled = req.target;
  spelled = spelled.starts_with(prefix) ? spelled.substr(prefix.size()) : std::string_view();
  spelled = spelled.substr(0, spelled.find_first_of("/?"));
  std::int64_t id = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), id);
  if (spelled != text || text.starts_with('0') || error != std::errc() || end != text.data() + text.size()) {
    throw HttpError(404, "Not Found",
                    "no job " + std::string(spelled.empty() ? std::string_view(text) : spelled) +
                        " (a job id is written in decimal digits without leading zeros, from 1 to " +
                        std::to_string(std::numeric_limits<std::int64_t>::max()) + ")");
  }
  return id;
}

}  // namespace saasgaps::service
