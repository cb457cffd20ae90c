#include "io/restart/stored_state.hpp"

#include <zlib.h>

#include <algorithm>
#include <cstring>
#include <nlohmann/json.hpp>

#include "io/restart/state_codec.hpp"
#include "solver/base/errors.hpp"

namespace saasgaps::io {

using nlohmann::json;

namespace {

constexpr std::uint8_t compressed_magic[4] = {'S', 'G', 'Z', '1'};

/// The bytes of n doubles regrouped by significance: byte b of value i goes to b * n + i.
std::vector<std::uint8_t> shuffled(const std::vector<double>& values) {
  const std::size_t n = values.size();
  std::vector<std::uint8_t> out(n * sizeof(double));
  const auto* in = reinterpret_cast<const std::uint8_t*>(values.data());
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t b = 0; b < sizeof(double); ++b) out[b * n + i] = in[i * sizeof(double) + b];
  }
  return out;
}

json unshuffled(const json::binary_t& bytes) {
  if (bytes.size() % sizeof(double) != 0) throw SolverError("malformed restart state: displacement bytes");
  const std::size_t n = bytes.size() / sizeof(double);
  json values = json::array();
  values.get_ref<json::array_t&>().reserve(n);
  for (std::size_t i = 0; i < n; ++i) {
    std::uint8_t word[sizeof(double)];
    for (std::size_t b = 0; b < sizeof(double); ++b) word[b] = bytes[b * n + i];
    double v;
    std::memcpy(&v, word, sizeof v);
    values.push_back(v);
  }
  return values;
}

}  // namespace

std::vector<std::uint8_t> encode_stored_state(const RestartState& state, const std::string& digest) {
  json document = state_to_json(state, digest);
  document["displacement"] = json::binary(shuffled(state.displacement));
  const std::vector<std::uint8_t> cbor = json::to_cbor(document);
  uLongf size = compressBound(static_cast<uLong>(cbor.size()));
  std::vector<std::uint8_t> out(sizeof compressed_magic + size);
  std::memcpy(out.data(), compressed_magic, sizeof compressed_magic);
  // Level 1: most of the gain of level 6 at a fraction of its time on these doubles.
  if (compress2(out.data() + sizeof compressed_magic, &size, cbor.data(), static_cast<uLong>(cbor.size()), 1) !=
      Z_OK) {
    throw std::runtime_error("cannot compress the restart state");
  }
  out.resize(sizeof compressed_magic + size);
  return out;
}

RestartState decode_stored_state(std::span<const std::uint8_t> bytes, const std::string& expected_digest,
                                 std::size_t max_inflated) {
  const bool compressed =
      bytes.size() >= sizeof compressed_magic && std::memcmp(bytes.data(), compressed_magic, sizeof compressed_magic) == 0;
  if (!compressed) return state_from_cbor(std::vector<std::uint8_t>(bytes.begin(), bytes.end()), expected_digest);

  z_stream stream{};
  if (inflateInit(&stream) != Z_OK) throw std::runtime_error("cannot start zlib");
  stream.next_in = const_cast<Bytef*>(bytes.data() + sizeof compressed_magic);
  stream.avail_in = static_cast<uInt>(bytes.size() - sizeof compressed_magic);
  std::vector<std::uint8_t> cbor;
  int status = Z_OK;
  while (status == Z_OK) {
    const std::size_t done = cbor.size();
    if (done >= max_inflated) {
      inflateEnd(&stream);
      throw SolverError("malformed restart state: it inflates beyond " + std::to_string(max_inflated) +
                        " bytes, more than any model's state");
    }
    cbor.resize(std::min(max_inflated, done + std::max<std::size_t>(1 << 16, 2 * bytes.size())));
    stream.next_out = cbor.data() + done;
    stream.avail_out = static_cast<uInt>(cbor.size() - done);
    status = inflate(&stream, Z_NO_FLUSH);
    cbor.resize(cbor.size() - stream.avail_out);
  }
  inflateEnd(&stream);
  if (status != Z_STREAM_END) throw SolverError("malformed restart state: the compressed data is damaged");

  json document = restart_state_tree(cbor);
  if (document.is_object() && document.contains("displacement") && document["displacement"].is_binary()) {
    document["displacement"] = unshuffled(document["displacement"].get_binary());
  }
  return state_from_json(document, expected_digest);
}

}  // namespace saasgaps::io
