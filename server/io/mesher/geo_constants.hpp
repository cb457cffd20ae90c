#pragma once
/// The parameters a Gmsh geometry (.geo) declares: the names it defines with `DefineConstant[...]`.
/// Gmsh's DefineConstant gives a name its value only when the name has none yet, so a value set
/// before the file is parsed (`gmsh -setnumber NAME VALUE`, or an assembly's `mesh_parameters`,
/// which the sandboxed mesher sets the same way) wins over the file's default, and the file still
/// meshes on its own with its defaults (docs/import.md).
///
/// Read from the file's text without running it (a geometry is a program, run only in the sandbox):
/// comments (`//`, `/* */`) and strings are skipped, and in each `DefineConstant[ ... ]` every
/// identifier before an `=` at the bracket's own level is a name (`a = 1`, `b = {0.1, Name "b"}`;
/// the ONELAB options inside braces are not).

#include <string>
#include <string_view>
#include <vector>

namespace saasgaps::io {

/// The names `text` declares with DefineConstant, in the order written (repeats kept once).
std::vector<std::string> geo_constants(std::string_view text);

/// Whether `name` is a name Gmsh's parser takes for a number: a letter or '_', then letters, digits
/// or '_'.
bool geo_identifier(std::string_view name);

}  // namespace saasgaps::io
