// Friction through a real server (issue 20): a finished job whose stored result and history rows are
// replaced, in the stopped server's database, by hand-made ones of a run with friction (until the
// solver fills them, no model gives them). The restarted server answers them as stored: the rows
// with their friction keys (GET iterations and the event stream), the contact pairs with mu, and the
// friction plot (CSV and PNG), `saasgaps watch` (the table's friction columns) and `saasgaps fetch
// --plot friction`; a frictionless result's friction plot is a 409 naming why.
#include <gtest/gtest.h>
#include <sqlite3.h>

#include <filesystem>
#include <string>

#include <nlohmann/json.hpp>

#include "service/server_process.hpp"
#include "service/service_fixture.hpp"

namespace saasgaps::testing {
namespace {

using nlohmann::json;

/// Runs SQL with one text parameter per '?' on a database file no server holds.
void run_sql(const std::filesystem::path& file, const std::string& sql, const std::vector<std::string>& texts) {
  sqlite3* db = nullptr;
  ASSERT_EQ(sqlite3_open(file.c_str(), &db), SQLITE_OK);
  sqlite3_stmt* q = nullptr;
  ASSERT_EQ(sqlite3_prepare_v2(db, sql.c_str(), -1, &q, nullptr), SQLITE_OK) << sqlite3_errmsg(db);
  for (std::size_t i = 0; i < texts.size(); ++i) {
    sqlite3_bind_text(q, static_cast<int>(i + 1), texts[i].c_str(), -1, SQLITE_TRANSIENT);
  }
  EXPECT_EQ(sqlite3_step(q), SQLITE_DONE) << sqlite3_errmsg(db);
  sqlite3_finalize(q);
  sqlite3_close(db);
}

/// A history row of a run with friction, as io/results/history_json.cpp writes it.
json friction_row(int iteration) {
  return {{"active_set_iterations", 2}, {"attempt", 1}, {"average_closure", 100.0}, {"bimodulus_changes", 0},
          {"closed_gaps", 0}, {"complementarity", 1e-16}, {"contact_pairs", 5}, {"extrapolated", false},
          {"friction_residual", 2.5e-14}, {"gap_closures", json::array()}, {"iteration", iteration},
          {"max_closure", 0.0}, {"nonconverged_gaps", 0}, {"nonconverged_plastic", 0}, {"seconds", 0.01},
          {"slip_points", 2}, {"stick_points", 3}, {"tensile_modulus", 0.0},
          {"watch", {{"elements", json::array()}, {"gaps", json::array()}}}, {"yielded_elements", 0}};
}

/// A result with one contact pair with friction 0.25: two points stick, two slip, one is open.
json friction_result() {
  const auto point = [](double r, double pressure, double shear, const char* state, double slip) {
    return json{{"gap", 0.0}, {"pressure", pressure}, {"r", r}, {"shear", shear}, {"slip", slip}, {"state", state},
                {"z", 1.0}};
  };
  json points = json::array({point(0.0, 100.0, 10.0, "stick", 0.0), point(1.0, 100.0, 20.0, "stick", 0.0),
                             point(2.0, 80.0, 20.0, "slip", 0.125), point(3.0, 50.0, -12.5, "slip", -0.25),
                             point(4.0, 0.0, 0.0, "open", 0.0)});
  return {{"analysis", "plane_strain"},
          {"contact", {{{"friction", 0.25}, {"points", points}, {"surfaces", {"block", "base"}}}}},
          {"elements", json::array()}, {"gaps", json::array()}, {"history", {friction_row(1)}},
          {"iterations", 1}, {"message", "converged in 1 iterations"}, {"nodes", json::array()},
          {"reactions", json::array()}, {"reference_temperature", 0.0}, {"status", "converged"},
          {"title", "hand-made friction"}};
}

class FrictionService : public ServiceFixture {};

TEST_F(FrictionService, StoredFrictionRowsAndResultAreServedWithTheFrictionPlot) {
  std::int64_t id = 0;
  {
    ServerProcess server(database());
    httplib::Client client = server.client();
    id = submit(client, example_text("quickstart-plane-strain-block.json"));
    wait_for_state(client, id, {"converged"});
    // A frictionless result has no friction plot: 409 with the reason.
    const json refused = problem(client.Get("/v1/jobs/" + std::to_string(id) + "/plots/friction.png"), 409);
    EXPECT_NE(refused.value("detail", "").find("no contact pair with friction > 0"), std::string::npos) << refused;
    ASSERT_EQ(server.stop(), 0);
  }
  const std::string job = std::to_string(id);
  run_sql(database(), "DELETE FROM iterations WHERE job_id = " + job, {});
  run_sql(database(), "DELETE FROM events WHERE job_id = " + job + " AND kind = 'iteration'", {});
  run_sql(database(), "INSERT INTO iterations (job_id, iteration, row) VALUES (" + job + ", 1, ?)",
          {friction_row(1).dump()});
  run_sql(database(),
          "INSERT INTO events (job_id, kind, data, created_at) VALUES (" + job + ", 'iteration', ?, '2026-01-01T00:00:00Z')",
          {friction_row(1).dump()});
  run_sql(database(), "UPDATE results SET document = ? WHERE job_id = " + job, {friction_result().dump()});

  ServerProcess server(database());
  httplib::Client client = server.client();
  const json rows = get_json(client, "/v1/jobs/" + job + "/iterations");
  ASSERT_EQ(rows["iterations"].size(), 1U) << rows;
  EXPECT_EQ(rows["iterations"][0]["stick_points"], 3);
  EXPECT_EQ(rows["iterations"][0]["slip_points"], 2);
  EXPECT_EQ(rows["iterations"][0]["friction_residual"], 2.5e-14);
  // The event stream (the job has finished: it ends after every past event).
  const httplib::Result events = client.Get("/v1/jobs/" + job + "/events");
  ASSERT_TRUE(events);
  EXPECT_NE(events->body.find("event: iteration\ndata: " + friction_row(1).dump()), std::string::npos) << events->body;
  // The contact pairs with their mu.
  const json contact = get_json(client, "/v1/jobs/" + job + "/contact");
  EXPECT_EQ(contact["contact"][0]["friction"], 0.25) << contact;
  // The friction plot: its table holds the stored numbers, its image is a PNG.
  const httplib::Result csv = client.Get("/v1/jobs/" + job + "/plots/friction.csv?width=800&height=500");
  ASSERT_TRUE(csv);
  ASSERT_EQ(csv->status, 200) << csv->body;
  EXPECT_NE(csv->body.find("\n1,3,2,2,1,80,20,0.25,20,0.125,slip,"), std::string::npos) << csv->body;
  EXPECT_NE(csv->body.find("# zones pair 1: stick 0..1.5 slip 1.5..3.5\n"), std::string::npos) << csv->body;
  const httplib::Result png = client.Get("/v1/jobs/" + job + "/plots/friction.png?width=800&height=500");
  ASSERT_TRUE(png);
  ASSERT_EQ(png->status, 200) << png->body;
  EXPECT_EQ(png->get_header_value("Content-Type"), "image/png");
  EXPECT_EQ(png->body.substr(1, 3), "PNG");

  // `saasgaps watch` (not a terminal: the progress table) shows the friction columns of the rows.
  const std::string url = "http://127.0.0.1:" + std::to_string(server.port());
  const CommandResult watch =
      run_command({"/bin/sh", "-c", "SAASGAPS_SERVER=" + url + " " + SAASGAPS_BINARY + " watch " + job});
  EXPECT_EQ(watch.exit_code, 0) << watch.output;
  EXPECT_NE(watch.output.find(" sets stick slip friction  seconds\n"), std::string::npos) << watch.output;
  EXPECT_NE(watch.output.find("     3    2  2.5e-14    0.010\n"), std::string::npos) << watch.output;
  // `saasgaps fetch --plot friction` draws it from the stored result.
  const CommandResult fetch = run_command({"/bin/sh", "-c", "SAASGAPS_SERVER=" + url + " " + SAASGAPS_BINARY +
                                                                " fetch " + job + " --plot friction -o " +
                                                                (dir_ / "friction.svg").string()});
  EXPECT_EQ(fetch.exit_code, 0) << fetch.output;
  EXPECT_TRUE(std::filesystem::file_size(dir_ / "friction.svg") > 1000U);
}

}  // namespace
}  // namespace saasgaps::testing
