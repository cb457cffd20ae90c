#include "service/http/request_id.hpp"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <random>

namespace saasgaps::service {

std::string request_id(const httplib::Request& req) {
  const std::string given = req.get_header_value("X-Request-Id");
  const bool usable = !given.empty() && given.size() <= 128 && std::all_of(given.begin(), given.end(), [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '.' || c == '_' || c == ':' || c == '-';
  });
  if (usable) return given;
  thread_local std::mt19937_64 random(std::random_device{}());
  char text[17];
  std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(random()));
  return text;
}

}  // namespace saasgaps::service
