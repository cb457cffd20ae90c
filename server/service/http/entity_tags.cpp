#include "service/http/entity_tags.hpp"

namespace saasgaps::service {

std::uint64_t fnv1a(std::string_view bytes, std::uint64_t h) {
  for (unsigned char c : bytes) {
    h ^= c;
    h *= 1099511628211ULL;
  }
  return h;
}

std::string entity_tag(std::string_view bytes, std::string_view variant) {
  return "\"" + std::to_string(fnv1a(variant, fnv1a(std::string_view("\0", 1), fnv1a(bytes)))) + "\"";
}

std::string result_tag(JobStore& store, std::int64_t id, std::size_t size, std::string_view variant) {
  const JobRecord job = store.get(id);
  return entity_tag(std::to_string(id) + '/' + job.finished_at.value_or("") + '/' + std::to_string(job.attempts) + '/' +
                        std::to_string(size),
                    variant);
}

bool not_modified(const httplib::Request& req, httplib::Response& res, const std::string& tag) {
  // Weak: the same bytes may be sent gzip-compressed or not (a strong tag would have to differ).
  res.set_header("ETag", "W/" + tag);
  const std::string header = req.get_header_value("If-None-Match");
  if (header.empty()) return false;
  std::size_t start = 0;
  while (start < header.size()) {
    auto end = header.find(',', start);
    if (end == std::string::npos) end = header.size();
    std::string candidate = header.substr(start, end - start);
    candidate.erase(0, candidate.find_first_not_of(" \t"));
    candidate.erase(candidate.find_last_not_of(" \t") + 1);
    if (candidate.rfind("W/", 0) == 0) candidate.erase(0, 2);
    if (candidate == "*" || candidate == tag) {
      res.status = 304;
      return true;
    }
    start = end + 1;
  }
  return false;
}

}  // namespace saasgaps::service
