#include "io/import/generated_origins.hpp"

#include <algorithm>
#include <array>
#include <string_view>
#include <utility>

#include "io/model/model_reader.hpp"

namespace saasgaps::io::assembly {

namespace {

/// Sections of the model document the importer writes itself; the rest pass through.
constexpr std::array<std::string_view, 6> generated_sections{"/nodes", "/elements", "/constraints", "/gaps/elements",
                                                             "/loads/", "/contact"};

}  // namespace

void GeneratedOrigins::add(std::string generated, std::string written, bool same_keys) {
  origins_.push_back({std::move(generated), std::move(written), same_keys});
}

std::vector<InputIssue> GeneratedOrigins::findings(const nlohmann::json& model) const {
  std::vector<InputIssue> out;
  try {
    (void)read_model(model);
  } catch (const ModelError& e) {
    for (const InputIssue& issue : e.issues()) {
      // The body force passes through although the other loads are generated.
      const bool generated = std::any_of(generated_sections.begin(), generated_sections.end(), [&](std::string_view s) {
        return issue.pointer.starts_with(s) && !issue.pointer.starts_with("/loads/body_force");
      });
      const auto origin = std::find_if(origins_.begin(), origins_.end(), [&](const Origin& o) {
        return issue.pointer == o.generated || issue.pointer.starts_with(o.generated + "/");
      });
      if (origin != origins_.end() && origin->same_keys) {
        out.push_back({origin->written + issue.pointer.substr(origin->generated.size()), issue.detail});
      } else if (origin != origins_.end()) {
        out.push_back({origin->written, "the generated " + issue.pointer + ": " + issue.detail});
      } else if (generated) {
        out.push_back({"/mesh", "the generated model's " + issue.pointer + ": " + issue.detail});
      } else {
        out.push_back(issue);
      }
    }
  }
  return out;
}

}  // namespace saasgaps::io::assembly
