#pragma once
/// Reading a stored result document (docs/results.md) into typed arrays, for
/// pictures and exports of large results without a tree.
///
/// A result at 10^6 unknowns is about 300 MB of JSON, nearly all of it the `nodes` (6 members each)
/// and the `elements` (18 members each). As an nlohmann tree the nodes and the kept element members
/// alone cost 1.2 GB and 8 s to build. This reader is one SAX pass (RapidJSON's Reader, iterative,
/// UTF-8 validated, numbers handed over as text and converted with std::from_chars, which rounds
/// correctly, as nlohmann's strtod does: the same doubles to the last bit). It reads:
///   - each node's id, r, z, T (0 when absent), u_r, u_z into columns;
///   - each element's id, material (0 when absent), node ids, and the numeric members the caller
///     names (a contour reads one field of the 18) into columns;
///   - every other member of the root (title, units, status, history, gaps, ...: kilobytes to a few
///     megabytes) into a tree, as nlohmann's parser would build it (repeated keys keep the later value).
/// Everything else in the text (the other element members, unknown members of a node) is checked
/// as JSON and skipped. The text is read in 64 KiB pieces from a file, so memory is the arrays.
///
/// Limits (io/json_limits.hpp): nesting deeper than max_json_depth throws NestingTooDeep at the
/// pointer where it happens, before anything deeper is read; the arrays grow with the text only.

#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

namespace saasgaps::io {

/// What to read typed.
struct ResultSelection {
  /// false: skip `nodes` and `elements` altogether (the convergence plot needs neither).
  bool mesh = true;
  /// Element members read as numbers besides id, material and nodes ("sigma_r", ...); a boolean
  /// reads as 1 or 0, as nlohmann's get<double>() reads it.
  std::vector<std::string> element_keys;
};

/// One column per node member, in the document's order.
struct ResultNodes {
  std::vector<int> id;
  std::vector<double> r, z, T, u_r, u_z;
  /// The recovered stresses (docs/results.md): sigma_r, sigma_z, tau_rz, sigma_theta, effective; NaN
  /// where a node has none (no solid element, or a result written before recovery).
  std::array<std::vector<double>, 5> stress;
};

/// The solid elements, in the document's order: node ids in CSR form (element e's nodes are
/// node_ids[first_node[e] .. first_node[e + 1])), and one column per selected key.
struct ResultElements {
  std::vector<int> id, material;
  std::vector<std::size_t> first_node{0};
  std::vector<int> node_ids;
  std::vector<std::vector<double>> values;  ///< values[k][e]: ResultSelection::element_keys[k] of element e
  /// Per selected key: the index of the first element without it (its column holds NaN there).
  std::vector<std::optional<std::size_t>> first_missing;

  [[nodiscard]] std::size_t size() const { return id.size(); }
};

struct ResultArrays {
  /// The root's members other than the `nodes` and `elements` read typed (each of those stays in the
  /// tree when it is not an array, so the reader of the mesh can say what is wrong with it).
  nlohmann::json document = nlohmann::json::object();
  std::optional<ResultNodes> nodes;        ///< read: `nodes` was an array and the mesh was selected
  std::optional<ResultElements> elements;  ///< likewise `elements`
  std::vector<std::string> element_keys;   ///< the selection's, in the order of ResultElements::values
  /// The first thing wrong with the root, the nodes or the elements ("malformed result document:
  /// /nodes/7/r is a string, not a number"); the arrays are then not to be used. Kept rather than
  /// thrown, so that a caller can first say what else the document is (a model, a failed run).
  std::optional<std::string> mesh_error;
};

/// The text is not JSON (RapidJSON's message and the byte offset where it stopped).
class ResultTextError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Reads a result's text. Text that is not JSON: ResultTextError; nesting too deep: NestingTooDeep.
/// A root that is not an object, or nodes and elements with members of the wrong kind (a missing id
/// or coordinate, a string where a number belongs, a number beyond a double) are mesh_error. A
/// number beyond a double in the tree part: std::invalid_argument naming its pointer.
ResultArrays read_result_arrays(std::string_view text, const ResultSelection& selection);

/// A source of a result's text in pieces: copies the text's next bytes into `out` (at most
/// `capacity`) and returns how many; 0 at the end. (A file, a SQLite blob handle.)
using TextPieces = std::function<std::size_t(char* out, std::size_t capacity)>;

/// The same from pieces, asked for 64 KiB at a time: the text is never held whole, memory is the
/// arrays and one piece. Exceptions of `next` pass through.
ResultArrays read_result_arrays_pieces(const TextPieces& next, const ResultSelection& selection);

/// The same from a file, read in 64 KiB pieces (the text is never held whole). A file that cannot
/// be opened: std::runtime_error "cannot read PATH: <reason>".
ResultArrays read_result_arrays_file(const std::string& path, const ResultSelection& selection);

}  // namespace saasgaps::io
