// The worker protocol's pieces on their own: leases as text, bodies that round-trip the exact bytes,
// bodies that are refused, and the batch script the Slurm executor submits (run by a real shell).
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "io/json/json_limits.hpp"
#include "io/mesher/subprocess.hpp"
#include "service/server_process.hpp"
#include "service/workers/slurm_executor.hpp"
#include "service/workers/worker_protocol.hpp"

namespace saasgaps::service {
namespace {

namespace protocol = worker_protocol;
using io::ProcessResult;
using io::run_process;

TEST(WorkerProtocol, LeasesParseOnlyWhenWellFormed) {
  const std::optional<Lease> lease = protocol::parse_lease("3:abc:def");
  ASSERT_TRUE(lease);
  EXPECT_EQ(lease->attempt, 3);
  EXPECT_EQ(lease->secret, "abc:def");
  EXPECT_EQ(protocol::format_lease(*lease), "3:abc:def");
  for (const char* bad : {"", "3", "3:", ":abc", "0:abc", "-1:abc", "x:abc", "3x:abc"}) {
    EXPECT_FALSE(protocol::parse_lease(bad)) << bad;
  }
}

TEST(WorkerProtocol, IterationsAndFinishesRoundTripTheirBytes) {
  std::vector<std::uint8_t> state(1000);
  for (std::size_t k = 0; k < state.size(); ++k) state[k] = static_cast<std::uint8_t>(k * 7);
  const protocol::Iteration it = protocol::decode_iteration(protocol::encode_iteration(12, R"({"iteration":12})", state));
  EXPECT_EQ(it.iteration, 12);
  EXPECT_EQ(it.row, R"({"iteration":12})");
  EXPECT_EQ(it.state, state);

  const protocol::Finish f =
      protocol::decode_finish(protocol::encode_finish({JobState::cancelled, "{}", "stopped", std::nullopt, "0123abcd"}));
  EXPECT_EQ(f.state, JobState::cancelled);
  EXPECT_EQ(f.result, "{}");
  EXPECT_EQ(f.message, "stopped");
  EXPECT_FALSE(f.error);
  EXPECT_EQ(f.model_digest, "0123abcd");
  // A finish names the model it solved: without model_digest it is refused.
  const std::vector<std::uint8_t> anonymous = nlohmann::json::to_cbor(nlohmann::json{{"state", "converged"}, {"result", "{}"}});
  EXPECT_THROW(protocol::decode_finish(std::string(anonymous.begin(), anonymous.end())), std::invalid_argument);
  // Two finishes differing anywhere have different digests (a retry is recognized by it).
  EXPECT_NE(protocol::body_digest(protocol::encode_finish({JobState::converged, "{}", {}, {}, "a"})),
            protocol::body_digest(protocol::encode_finish({JobState::converged, "{ }", {}, {}, "a"})));
  // A run cannot declare itself interrupted (that is the service's call, and counted), nor running.
  EXPECT_THROW(protocol::decode_finish(protocol::encode_finish({JobState::interrupted, {}, {}, {}, "d"})), std::invalid_argument);
  EXPECT_THROW(protocol::decode_finish(protocol::encode_finish({JobState::running, {}, {}, {}, "d"})), std::invalid_argument);
  EXPECT_THROW(protocol::decode_iteration(protocol::encode_iteration(0, "{}", state)), std::invalid_argument);
  EXPECT_THROW(protocol::decode_iteration(protocol::encode_iteration(1, "{not json", state)), std::invalid_argument);
  EXPECT_THROW(protocol::decode_iteration("\xa0"), std::invalid_argument);  // an empty CBOR map
}

/// Issue 17: nlohmann's CBOR decoder recurses once per level; 10^5 levels overflowed the stack.
TEST(WorkerProtocol, ThermalRowsRoundTripAndBadOnesAreRefused) {
  const std::string row = R"({"index":3,"kind":"transient"})";
  const protocol::ThermalRow t = protocol::decode_thermal(protocol::encode_thermal(3, row));
  EXPECT_EQ(t.index, 3);
  EXPECT_EQ(t.row, row);
  EXPECT_THROW(protocol::decode_thermal(protocol::encode_thermal(0, row)), std::invalid_argument);
  EXPECT_THROW(protocol::decode_thermal(protocol::encode_thermal(1, "{not json")), std::invalid_argument);
  EXPECT_THROW(protocol::decode_thermal("\xa0"), std::invalid_argument);  // an empty CBOR map
}

TEST(WorkerProtocol, DeepBodiesAreRefusedAtTheirPointer) {
  // {"iteration": 1, "row": "{}", "state": [[[...1...]]]} with 10^5 arrays, written byte by byte.
  std::string body = "\xA3\x69iteration\x01\x63row\x62{}\x65state";
  body += std::string(100000, '\x81') + '\x01';
  try {
    (void)protocol::decode_iteration(body);
    ADD_FAILURE() << "a body nested 10^5 deep was accepted";
  } catch (const io::NestingTooDeep& e) {
    ASSERT_EQ(e.issues().size(), 1u);
    std::string pointer = "/state";
    for (int k = 0; k < 63; ++k) pointer += "/0";
    EXPECT_EQ(e.issues().front().pointer, pointer);
  }
  // The JSON text of a row or a result is stored and served: it is held to the same limit.
  const std::string deep_text = std::string(100000, '[') + std::string(100000, ']');
  EXPECT_THROW(protocol::decode_iteration(protocol::encode_iteration(1, deep_text, {})), io::NestingTooDeep);
  EXPECT_THROW(protocol::decode_finish(protocol::encode_finish({JobState::converged, deep_text, {}, {}, {}})),
               io::NestingTooDeep);
  const std::string at_limit = std::string(64, '[') + std::string(64, ']');
  EXPECT_EQ(protocol::decode_iteration(protocol::encode_iteration(1, at_limit, {})).row, at_limit);
}

TEST(SlurmBatchScript, EveryWordSurvivesTheShellIntact) {
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / ("saasgaps-batch-script-" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  // A stand-in for the worker binary, at a path with a space and a quote, that prints its arguments.
  const std::filesystem::path binary = dir / "it's a worker";
  std::ofstream(binary) << "#!/bin/sh\nfor a in \"$@\"; do printf '[%s]\\n' \"$a\"; done\n";
  std::filesystem::permissions(binary, std::filesystem::perms::owner_all);
  SlurmOptions options;
  options.worker_binary = binary.string();
  options.worker_url = "http://host:8080/?a=$(reboot)&b='c'";
  options.token_file = "/secrets/my token";
  const std::filesystem::path script = dir / "script.sh";
  std::ofstream(script) << batch_script(options, 42);
  const testing::CommandResult run = testing::run_command({"/bin/sh", script.string()});
  EXPECT_EQ(run.exit_code, 0);
  EXPECT_EQ(run.output, "[worker]\n[--server]\n[http://host:8080/?a=$(reboot)&b='c']\n[--job]\n[42]\n"
                        "[--token-file]\n[/secrets/my token]\n");
  EXPECT_EQ(split_words("  --mem=8G\t--qos=low \n"), (std::vector<std::string>{"--mem=8G", "--qos=low"}));
  std::filesystem::remove_all(dir);
}

TEST(Subprocess, FeedsInputSetsTheEnvironmentAndKeepsItsTimeLimit) {
  const std::string big(1 << 20, 'x');  // more than a pipe holds: input and output must flow together
  const ProcessResult cat = run_process({"cat"}, big, {}, std::chrono::seconds(20));
  EXPECT_EQ(cat.exit_code, 0);
  EXPECT_EQ(cat.out, big);
  const ProcessResult env = run_process({"sh", "-c", "echo \"$SAASGAPS_PROBE\" >&2; exit 3"}, "", {"SAASGAPS_PROBE=a b"},
                                        std::chrono::seconds(20));
  EXPECT_EQ(env.exit_code, 3);
  EXPECT_EQ(env.err, "a b\n");
  const auto start = std::chrono::steady_clock::now();
  const ProcessResult slow = run_process({"sleep", "30"}, "", {}, std::chrono::milliseconds(200));
  EXPECT_EQ(slow.exit_code, -1);
  EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(10));
  EXPECT_THROW(run_process({"saasgaps-no-such-program"}, "", {}, std::chrono::seconds(5)), std::runtime_error);
}

}  // namespace
}  // namespace saasgaps::service
