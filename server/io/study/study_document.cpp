#include "io/study/study_document.hpp"

#include <algorithm>
#include <array>
#include <limits>
#include <set>
#include <string_view>

#include "io/json/json_pointer.hpp"
#include "io/json/value_quote.hpp"
#include "io/json/value_rules.hpp"
#include "io/model/model_reader.hpp"
#include "io/study/study_outputs.hpp"

namespace saasgaps::io {

using nlohmann::json;

namespace {

/// The reference tokens of an RFC 6901 pointer ("~1" is "/", "~0" is "~"), or nullopt when it is
/// not one (it must be empty or start with "/"; "~" only before 0 or 1).
std::optional<std::vector<std::string>> tokens_of(std::string_view pointer) {
  std::vector<std::string> out;
  if (pointer.empty()) return out;
  if (pointer.front() != '/') return std::nullopt;
  std::string token;
  for (std::size_t i = 1; i <= pointer.size(); ++i) {
    if (i == pointer.size() || pointer[i] == '/') {
      out.push_back(token);
      token.clear();
    } else if (pointer[i] == '~') {
      if (i + 1 >= pointer.size() || (pointer[i + 1] != '0' && pointer[i + 1] != '1')) return std::nullopt;
      token += pointer[i + 1] == '0' ? '~' : '/';
      ++i;
    } else {
      token += pointer[i];
    }
  }
  return out;
}

/// An array index token: digits without a leading zero, below `size`.
std::optional<std::size_t> index_of(const std::string& token, std::size_t size) {
  if (token.empty() || token.size() > 18 || (token.size() > 1 && token[0] == '0')) return std::nullopt;
  if (!std::all_of(token.begin(), token.end(), [](char c) { return c >= '0' && c <= '9'; })) return std::nullopt;
  const std::size_t i = std::stoull(token);
  if (i >= size) return std::nullopt;
  return i;
}

/// Where a pointer leads in a document: the value there (nullptr when the last token names a member
/// an object does not have yet: the study adds it), or the reason it does not resolve.
struct Target {
  const json* value = nullptr;
  std::string problem;
};

Target resolve(const json& document, const std::vector<std::string>& tokens) {
  const json* at = &document;
  std::string walked;
  for (std::size_t k = 0; k < tokens.size(); ++k) {
    const std::string& t = tokens[k];
    const bool last = k + 1 == tokens.size();
    if (at->is_object()) {
      const auto it = at->find(t);
      if (it == at->end()) {
        if (last) return {nullptr, {}};
        return {nullptr, (walked.empty() ? std::string("the document") : walked) + " has no member " + quote_string(t)};
      }
      at = &*it;
    } else if (at->is_array()) {
      const auto i = index_of(t, at->size());
      if (!i) {
        return {nullptr, (walked.empty() ? std::string("the document") : walked) + " is an array of " +
                             std::to_string(at->size()) + " items: " + quote_string(t) + " is not one of its indices"};
      }
      at = &(*at)[*i];
    } else {
      return {nullptr, walked + " is " + describe(*at) + ": nothing is under it"};
    }
    walked = pointer_append(walked, t);
  }
  return {at, {}};
}

/// Same JSON kind: both numbers (integer or not), or the same type otherwise.
bool same_kind(const json& a, const json& b) {
  if (a.is_number() || b.is_number()) return a.is_number() && b.is_number();
  return a.type() == b.type();
}

json& place(json& document, const std::vector<std::string>& tokens) {
  json* at = &document;
  for (const std::string& t : tokens) {
    at = at->is_array() ? &(*at)[std::stoull(t)] : &(*at)[t];
  }
  return *at;
}

class StudyReader {
 public:
  explicit StudyReader(std::size_t max_points) : max_points_(max_points) {}

  void report(const std::string& pointer, std::string detail) { issues_.push_back({pointer, std::move(detail)}); }
  auto report_fn() {
    return [this](const std::string& pointer, std::string detail) { report(pointer, std::move(detail)); };
  }

  Study read(const json& doc) {
    static constexpr std::array<std::string_view, 2> required{"schema_version", "parameters"};
    static constexpr std::array<std::string_view, 5> optional{"title", "model", "assembly", "sampling", "outputs"};
    if (!check_object(doc, "", required, optional, report_fn())) throw ModelError(issues_, "study");
    if (doc.contains("schema_version")) check_schema_version(doc["schema_version"], "/schema_version", report_fn());
    if (doc.contains("title")) {
      if (auto t = check_string(doc["title"], "/title", "title", report_fn())) study_.title = *t;
    }
    const bool model = doc.contains("model"), assembly = doc.contains("assembly");
    if (model == assembly) {
      report("", model ? "a study has a \"model\" or an \"assembly\", not both" : "missing required key \"model\" (or \"assembly\")");
    } else {
      study_.assembly = assembly;
      study_.base = doc[assembly ? "assembly" : "model"];
      base_pointer_ = assembly ? "/assembly" : "/model";
      if (!study_.base.is_object()) {
        report(base_pointer_, "expected an object, got " + describe(study_.base));
        study_.base = json();
      }
    }
    if (doc.contains("sampling")) {
      const json& s = doc["sampling"];
      if (s == "grid") {
        study_.sampling = Sampling::grid;
      } else if (s == "zip") {
        study_.sampling = Sampling::zip;
      } else {
        report("/sampling", "sampling must be \"grid\" or \"zip\", got " + describe(s));
      }
    }
    parameters(doc["parameters"]);
    if (doc.contains("outputs")) outputs(doc["outputs"]);
    if (issues_.empty()) count_points();
    if (!issues_.empty()) throw ModelError(issues_, "study");
    return std::move(study_);
  }

 private:
  void parameters(const json& list) {
    if (!check_array(list, std::string("/parameters"), "parameters", 1, report_fn())) return;
    std::set<std::string> names, pointers;
    for (std::size_t k = 0; k < list.size(); ++k) {
      const std::string at = pointer_append("/parameters", k);
      static constexpr std::array<std::string_view, 3> required{"name", "pointer", "values"};
      if (!check_object(list[k], at, required, {}, report_fn())) continue;
      StudyParameter p;
      const json& item = list[k];
      if (item.contains("name")) {
        const auto name = check_string(item["name"], pointer_append(at, "name"), "name", report_fn());
        if (name && name->empty()) {
          report(pointer_append(at, "name"), "name must not be empty");
        } else if (name && !names.insert(*name).second) {
          report(pointer_append(at, "name"), "parameter name " + quote_string(*name) + " is used twice");
        }
        if (name) p.name = *name;
      }
      std::optional<std::vector<std::string>> tokens;
      const json* target = nullptr;
      bool target_known = false;
      if (item.contains("pointer")) {
        const std::string where = pointer_append(at, "pointer");
        const auto pointer = check_string(item["pointer"], where, "pointer", report_fn());
        if (pointer) {
          p.pointer = *pointer;
          tokens = tokens_of(*pointer);
          if (!tokens) {
            report(where, quote_string(*pointer) + " is not a JSON Pointer (RFC 6901: \"/key/0/key\", \"~1\" for \"/\")");
          } else if (tokens->empty()) {
            report(where, "the pointer must name a value inside the " + kind() + ", not the whole document");
          } else if (!pointers.insert(*pointer).second) {
            report(where, quote_string(*pointer) + " is the pointer of another parameter too");
          } else if (!study_.base.is_null()) {
            const Target t = resolve(study_.base, *tokens);
            if (!t.problem.empty()) {
              report(where, quote_string(*pointer) + " does not resolve in the " + kind() + ": " + t.problem);
            } else {
              target = t.value;
              target_known = true;
            }
          }
        }
      }
      if (item.contains("values")) {
        const std::string where = pointer_append(at, "values");
        if (const json* values = check_array(item["values"], where, "values", 1, report_fn())) {
          for (std::size_t j = 0; j < values->size(); ++j) {
            const json& v = (*values)[j];
            if (target_known && target != nullptr && !same_kind(v, *target)) {
              report(pointer_append(where, j), "wrong type: " + describe(v) + " where " + p.pointer + " in the " + kind() +
                                                   " holds " + describe(*target));
            }
            p.values.push_back(v);
          }
        }
      }
      study_.parameters.push_back(std::move(p));
    }
  }

  void outputs(const json& list) {
    if (!check_array(list, std::string("/outputs"), "outputs", 0, report_fn())) return;
    std::set<std::string> names;
    for (const StudyParameter& p : study_.parameters) names.insert(p.name);
    for (std::size_t k = 0; k < list.size(); ++k) {
      const std::string at = pointer_append("/outputs", k);
      static constexpr std::array<std::string_view, 3> required{"name", "of", "reduce"};
      static constexpr std::array<std::string_view, 4> optional{"elements", "nodes", "pair", "set"};
      if (!check_object(list[k], at, required, optional, report_fn())) continue;
      const json& item = list[k];
      StudyOutput o;
      if (item.contains("name")) {
        const auto name = check_string(item["name"], pointer_append(at, "name"), "name", report_fn());
        if (name && name->empty()) {
          report(pointer_append(at, "name"), "name must not be empty");
        } else if (name && !names.insert(*name).second) {
          report(pointer_append(at, "name"), "the name " + quote_string(*name) +
                                                 " is taken by a parameter or another output (they are the CSV's columns)");
        }
        if (name) o.name = *name;
      }
      if (item.contains("of")) {
        if (const auto of = check_string(item["of"], pointer_append(at, "of"), "of", report_fn())) {
          o.of = *of;
          if (std::string why = unknown_output_field(*of); !why.empty()) report(pointer_append(at, "of"), why);
        }
      }
      if (item.contains("reduce")) {
        const json& r = item["reduce"];
        if (r == "max") {
          o.reduce = Reducer::max;
        } else if (r == "min") {
          o.reduce = Reducer::min;
        } else if (r == "sum") {
          o.reduce = Reducer::sum;
        } else if (r == "mean") {
          o.reduce = Reducer::mean;
        } else {
          report(pointer_append(at, "reduce"), "reduce must be \"max\", \"min\", \"sum\" or \"mean\", got " + describe(r));
        }
      }
      const int selections = static_cast<int>(item.contains("elements")) + static_cast<int>(item.contains("nodes")) +
                             static_cast<int>(item.contains("pair")) + static_cast<int>(item.contains("set"));
      if (selections > 1) {
        report(at, "at most one of \"elements\", \"nodes\", \"pair\" and \"set\" selects what is reduced");
      }
      if (item.contains("set")) {
        const auto set = check_string(item["set"], pointer_append(at, "set"), "set", report_fn());
        if (set && set->empty()) report(pointer_append(at, "set"), "set must name a node set, not be empty");
        if (set && !set->empty()) o.set = *set;
      }
      o.elements = ids(item, at, "elements");
      o.nodes = ids(item, at, "nodes");
      if (item.contains("pair")) {
        const std::string where = pointer_append(at, "pair");
        const json& pair = item["pair"];
        if (!pair.is_array() || pair.size() != 2 || !pair[0].is_string() || !pair[1].is_string()) {
          report(where, "pair must be the two surface names [A, B] of a contact pair, got " + describe(pair));
        } else {
          o.pair = pair.get<std::vector<std::string>>();
        }
      }
      if (std::string why = selection_problem(o); !why.empty()) report(at, why);
      study_.outputs.push_back(std::move(o));
    }
  }

  std::optional<std::vector<int>> ids(const json& item, const std::string& at, const char* key) {
    if (!item.contains(key)) return std::nullopt;
    const std::string where = pointer_append(at, key);
    const json* list = check_array(item[key], where, key, 1, report_fn());
    if (list == nullptr) return std::nullopt;
    std::vector<int> out;
    for (std::size_t j = 0; j < list->size(); ++j) {
      const json& id = (*list)[j];
      if (!id.is_number_integer() || id.get<long long>() < 1 || id.get<long long>() > std::numeric_limits<int>::max()) {
        report(pointer_append(where, j), std::string("an id must be an integer in 1..2147483647, got ") + describe(id));
        continue;
      }
      out.push_back(id.get<int>());
    }
    return out;
  }

  void count_points() {
    if (study_.sampling == Sampling::zip) {
      const std::size_t n = study_.parameters.front().values.size();
      for (std::size_t k = 1; k < study_.parameters.size(); ++k) {
        if (study_.parameters[k].values.size() != n) {
          report(pointer_append(pointer_append("/parameters", k), "values"),
                 "zip sampling takes the k-th value of every parameter together: this parameter has " +
                     std::to_string(study_.parameters[k].values.size()) + " values, the first one " + std::to_string(n));
        }
      }
      if (n > max_points_) too_many(std::to_string(n));
      return;
    }
    std::size_t n = 1;
    for (const StudyParameter& p : study_.parameters) {
      if (n > max_points_ / p.values.size()) {  // then n * size > max_points_: said before it overflows
        long double count = 1;
        for (const StudyParameter& q : study_.parameters) count *= static_cast<long double>(q.values.size());
        too_many(count < 1e18L ? std::to_string(static_cast<unsigned long long>(count))
                               : format_number(static_cast<double>(count)));
        return;
      }
      n *= p.values.size();
    }
  }

  void too_many(const std::string& count) {
    report("/parameters", "the study has " + count + " points, more than the limit of " + std::to_string(max_points_) +
                              " (saasgaps study --max-points, the service's --max-study-points)");
  }

  [[nodiscard]] std::string kind() const { return study_.assembly ? "assembly" : "model"; }

  std::size_t max_points_;
  Study study_;
  std::string base_pointer_;
  std::vector<InputIssue> issues_;
};

}  // namespace

std::size_t Study::point_count() const {
  if (parameters.empty()) return 0;
  if (sampling == Sampling::zip) return parameters.front().values.size();
  std::size_t n = 1;
  for (const StudyParameter& p : parameters) n *= p.values.size();
  return n;
}

std::vector<std::size_t> Study::value_indices(std::size_t index) const {
  std::vector<std::size_t> out(parameters.size(), index);
  if (sampling == Sampling::zip) return out;
  for (std::size_t k = parameters.size(); k-- > 0;) {
    out[k] = index % parameters[k].values.size();
    index /= parameters[k].values.size();
  }
  return out;
}

json Study::point_parameters(std::size_t index) const {
  json out = json::object();
  const auto at = value_indices(index);
  for (std::size_t k = 0; k < parameters.size(); ++k) out[parameters[k].name] = parameters[k].values[at[k]];
  return out;
}

json Study::point_document(std::size_t index) const {
  json out = base;
  const auto at = value_indices(index);
  for (std::size_t k = 0; k < parameters.size(); ++k) {
    place(out, *tokens_of(parameters[k].pointer)) = parameters[k].values[at[k]];
  }
  return out;
}

Study read_study(const json& document, std::size_t max_points) { return StudyReader(max_points).read(document); }

std::string point_issues(const Study& study, std::size_t index) {
  try {
    (void)read_model(study.point_document(index));
    return {};
  } catch (const ModelError& e) {
    return point_issues(study, index, e);
  }
}

std::string point_issues(const Study& study, std::size_t index, const ModelError& error) {
  const auto at = study.value_indices(index);
  std::string out;
  for (std::size_t i = 0; i < error.issues().size(); ++i) {
    const InputIssue& issue = error.issues()[i];
    if (i > 0) out += "; ";
    for (std::size_t k = 0; k < study.parameters.size(); ++k) {
      const std::string& p = study.parameters[k].pointer;
      if (issue.pointer == p || issue.pointer.starts_with(p + "/")) {
        out += "parameter " + quote_string(study.parameters[k].name) + " = " + quote(study.parameters[k].values[at[k]]) +
               " (" + pointer_append(pointer_append(pointer_append("/parameters", k), "values"), at[k]) + "): ";
        break;
      }
    }
    out += (issue.pointer.empty() ? std::string() : issue.pointer + ": ") + issue.detail;
  }
  return out;
}

}  // namespace saasgaps::io
