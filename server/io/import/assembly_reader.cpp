#include "io/import/assembly_reader.hpp"

#include <string>
#include <utility>

#include "io/import/adapt_settings.hpp"
#include "io/import/assembly_importer.hpp"
#include "io/json/value_rules.hpp"
#include "solver/base/errors.hpp"

namespace saasgaps::io {

using nlohmann::json;

namespace assembly {

/// The steps in an order where each finds what it needs done (the mesh before every group, the
/// regions before the thermal sources that heat their materials), which is also the order of the
/// issues reported. Every step reports what it finds and goes on, so that one ModelError carries
/// every problem of the document; only a document that is not an object stops at once.
json Importer::run() {
  if (!object(doc_, "", {"schema_version", "title", "mesh", "analysis", "materials", "regions", "constraints"},
              {"description", "units", "order", "mesh_parameters", "loads", "gaps", "thermal", "solver", "output", "steps",
               "adapt"})) {
    throw ModelError(std::move(issues_), "assembly");
  }
  if (const auto v = doc_.find("schema_version"); v != doc_.end()) {
    check_schema_version(*v, std::string("/schema_version"), reporter());
  }
  json model = json::object();
  model["schema_version"] = 1;
  for (const char* key : {"title", "description", "units", "analysis", "materials"}) {
    if (const auto v = doc_.find(key); v != doc_.end()) model[key] = *v;
  }
  read_material_ids();
  const auto adapt = read_adapt_settings(doc_, reporter());
  load_mesh();
  if (adapt) adapt_mesh(*adapt);
  nodes(model);
  regions(model);
  gaps(model);
  constraints(model);
  loads(model);
  steps(model);
  thermal(model);
  sets(model);
  for (const char* key : {"solver", "output"}) {
    if (const auto v = doc_.find(key); v != doc_.end()) model[key] = *v;
  }
  // The model reader judges the result only when the assembly's own checks found nothing: a model
  // generated from a faulty assembly lacks what could not be generated, and its findings would be
  // about that.
  if (issues_.empty()) {
    for (InputIssue& finding : origins_.findings(model)) report(std::move(finding.pointer), std::move(finding.detail));
  }
  if (!issues_.empty()) throw ModelError(std::move(issues_), "assembly");
  return model;
}

}  // namespace assembly

nlohmann::json import_assembly(const nlohmann::json& assembly, const std::filesystem::path& base_directory,
                               FileAccess access, const SizeField* sizes, double* mesh_seconds) {
  assembly::Importer importer(assembly, base_directory, access, sizes);
  json model = importer.run();
  if (mesh_seconds != nullptr) *mesh_seconds = importer.mesh_seconds();
  return model;
}

}  // namespace saasgaps::io
