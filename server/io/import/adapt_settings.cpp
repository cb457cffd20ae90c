#include "io/import/adapt_settings.hpp"

#include <array>
#include <string_view>

#include "io/json/value_quote.hpp"
#include "io/json/value_rules.hpp"

namespace saasgaps::io {

namespace {

/// An integer first <= v <= last at `pointer`, or nullopt (reported).
template <class Report>
std::optional<long long> integer_in(const nlohmann::json& v, const std::string& pointer, std::string_view name,
                                    long long first, long long last, const char* why, Report&& report) {
  if (!v.is_number_integer()) {
    report(pointer, std::string(name) + " must be an integer, got " + describe(v));
    return std::nullopt;
  }
  const long long n = v.is_number_unsigned() && v.get<unsigned long long>() > 9000000000000000000ULL
                          ? last + 1
                          : v.get<long long>();
  if (n < first || n > last) {
    report(pointer, std::string(name) + " = " + quote(v) + " is out of range: need " + std::to_string(first) +
                        " <= " + std::string(name) + " <= " + std::to_string(last) + " (" + why + ")");
    return std::nullopt;
  }
  return n;
}

}  // namespace

std::optional<AdaptSettings> read_adapt_settings(const nlohmann::json& assembly,
                                                 const std::function<void(const std::string&, std::string)>& report) {
  if (!assembly.is_object()) return std::nullopt;
  const auto it = assembly.find("adapt");
  if (it == assembly.end()) return std::nullopt;
  const nlohmann::json& a = *it;
  constexpr std::array<std::string_view, 1> required{"target_error"};
  constexpr std::array<std::string_view, 2> optional{"max_cycles", "max_nodes"};
  bool ok = true;
  const auto note = [&](const std::string& p, std::string detail) {
    ok = false;
    report(p, std::move(detail));
  };
  if (!check_object(a, "/adapt", required, optional, note)) return std::nullopt;
  AdaptSettings out;
  if (const auto t = a.find("target_error"); t != a.end()) {
    static constexpr Range fraction{Bound{0.0, false}, Bound{1.0, false},
                                    "a relative error in the energy norm lies between 0 and 1"};
    if (const auto v = check_number(*t, std::string("/adapt/target_error"), "target_error", fraction, note)) {
      out.target_error = *v;
    }
  }
  if (const auto c = a.find("max_cycles"); c != a.end()) {
    if (const auto v = integer_in(*c, "/adapt/max_cycles", "max_cycles", 1, max_adapt_cycles,
                                  "each cycle is a mesh and a solve; one is the first mesh alone", note)) {
      out.max_cycles = static_cast<int>(*v);
    }
  }
  if (const auto n = a.find("max_nodes"); n != a.end()) {
    if (const auto v = integer_in(*n, "/adapt/max_nodes", "max_nodes", static_cast<long long>(min_adapt_nodes),
                                  static_cast<long long>(max_adapt_nodes),
                                  "fewer nodes leave nothing to refine; more than --max-mesh-nodes allows at most", note)) {
      out.max_nodes = static_cast<std::size_t>(*v);
    }
  }
  if (!ok) return std::nullopt;
  return out;
}

}  // namespace saasgaps::io
