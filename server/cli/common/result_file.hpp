#pragma once
/// Reading a result document (written by `saasgaps solve -o`) for the commands that work on one.

#include <string>

#include <nlohmann/json.hpp>

#include "io/results/result_arrays.hpp"

namespace saasgaps::cli {

/// What `selection` names of the result document in the file, read as typed arrays in one pass over
/// the file (io/results/result_arrays.hpp): the plots of a 10^6-unknown result never hold its text or a tree
/// of it. A file that cannot be read, is not JSON, or is not a result (a model, a restart state) is a
/// std::runtime_error naming the file; a malformed mesh is the arrays' mesh_error.
io::ResultArrays read_result_arrays(const std::string& path, const io::ResultSelection& selection);

}  // namespace saasgaps::cli
